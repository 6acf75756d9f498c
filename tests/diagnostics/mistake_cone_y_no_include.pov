// error: 5:10 undefined identifier `Cone_Y`
// error-text: `Cone_Y` is declared in the standard include file `shapes_old.inc`: add `#include "shapes.inc"` before using it
// POV-Ray: Parse Error: Expected 'object', undeclared identifier 'Cone_Y' found instead
// Mistake: `Cone_Y` without `#include "shapes.inc"`
object { Cone_Y }
