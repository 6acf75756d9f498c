// error: 5:25 undefined identifier `Jade`
// error-text: `Jade` is declared in the standard include file `textures.inc`: add `#include "textures.inc"` before using it
// POV-Ray: Parse Error: No matching } in 'pigment', undeclared identifier 'Jade' found instead
// Mistake: `Jade` without `#include "textures.inc"`
sphere { 0, 1 pigment { Jade } }
