// warning: 6:1 `declare` should be `#declare`
// warning: 7:1 `include` should be `#include`

// POV-Ray 2's spelling: povray 3.7 still reads it and warns ("Should have '#' before
// 'declare'"); so does durer.
declare Radius = 1;
include "declare_without_hash.inc"
sphere { 0, Radius pigment { Red } }
