// error: 5:21 expected a spline kind

// A spline called with a second argument that is not a spline kind.
#declare S = spline { 0, <0,0,0> 1, <1,1,1> }
#declare P = S(0.5, 3);
