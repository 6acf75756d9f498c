// A spline without points.
#declare Empty = spline { linear_spline }
