// error: 5:25 `facets` can only be used in a `normal`
// error-text: not allowed in a `texture`

// `facets` as a texture pattern: POV-Ray refuses it too.
sphere { 0, 1 texture { facets texture_map { [0 pigment { rgb 0 }] [1 pigment { rgb 1 }] } } }
