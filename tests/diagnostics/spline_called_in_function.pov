// error: 5:25 the spline `S` cannot be called inside a function
// error-text: function { spline { S } }

#declare S = spline { linear_spline 0, <0,0,0> 1, <1,2,3> }
#declare F = function { S(x).y }
