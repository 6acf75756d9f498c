#declare S = spline { 0, <0,0> 1, <1,1> }
#declare F = function { S }
