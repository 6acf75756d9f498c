// `facets` as a texture pattern: POV-Ray refuses it too.
sphere { 0, 1 texture { facets texture_map { [0 pigment { rgb 0 }] [1 pigment { rgb 1 }] } } }
