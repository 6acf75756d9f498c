#declare S = spline { linear_spline 0, <0,0,0> 1, <1,2,3> }
#declare F = function { S(x).y }
