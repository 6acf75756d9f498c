// error: 5:25 undefined identifier `T_Stone1`
// error-text: `T_Stone1` is declared in the standard include file `stones1.inc`: add `#include "stones.inc"` before using it
// POV-Ray: Parse Error: No matching } in 'texture', undeclared identifier 'T_Stone1' found instead
// Mistake: `T_Stone1` without `#include "stones.inc"`
sphere { 0, 1 texture { T_Stone1 } }
