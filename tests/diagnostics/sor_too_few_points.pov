// error: 4:1 a sor needs 4 to 10000000 points, found 3

// A sor needs at least four points.
sor { 3, <0.5, -1.5>, <0.6, -1>, <1.0, -0.5> }
