// error: 6:35 `facets` can only be used in a `normal`
// error-text: not allowed in a `pigment`
// error-text: normal { facets .. }

// `facets` outside a normal: POV-Ray refuses it ("can only be used in a normal statement").
#declare F = function { pattern { facets size 0.2 } }
sphere { 0, 1 pigment { facets color_map { [0 rgb 0] [1 rgb 1] } } }
