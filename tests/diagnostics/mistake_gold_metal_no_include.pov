// error: 5:25 undefined identifier `Gold_Metal`
// error-text: `Gold_Metal` is declared in the standard include file `textures.inc`: add `#include "textures.inc"` before using it
// POV-Ray: Parse Error: No matching } in 'texture', undeclared identifier 'Gold_Metal' found instead
// Mistake: `Gold_Metal` without `#include "textures.inc"`
sphere { 0, 1 texture { Gold_Metal } }
