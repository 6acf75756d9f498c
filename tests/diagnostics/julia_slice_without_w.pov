// error: 4:34 the slice normal needs a non-zero fourth component

// A slice normal needs a fourth component.
julia_fractal { <0.1, 0.2, 0, 0> slice <1, 0, 0, 0>, 0 }
