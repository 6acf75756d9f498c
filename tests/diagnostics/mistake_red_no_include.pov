// error: 5:31 undefined identifier `Red`
// error-text: `Red` is declared in the standard include file `colors.inc`: add `#include "colors.inc"` before using it
// POV-Ray: Parse Error: No matching } in 'pigment', undeclared identifier 'Red' found instead
// Mistake: `Red` without `#include "colors.inc"`
sphere { 0, 1 pigment { color Red } }
