// error: 5:18 a spline needs at least one point
// error-text: this spline has none

// A spline without points.
#declare Empty = spline { linear_spline }
