// error: 5:25 a function cannot be the spline `S` itself
// error-text: write `function { spline { S } }`

#declare S = spline { 0, <0,0> 1, <1,1> }
#declare F = function { S }
