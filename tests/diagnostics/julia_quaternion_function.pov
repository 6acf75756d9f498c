// error: 5:45 quaternion julia fractals take only `sqr` or `cube`
// error-text: needs `hypercomplex`

// A quaternion julia fractal cannot take exp.
julia_fractal { <0.1, 0.2, 0, 0> quaternion exp }
