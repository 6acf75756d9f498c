// error: 6:14 `f_sphere` cannot be used inside a function
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'operator', ( found instead
// Mistake: `f_sphere` without `#include "functions.inc"`
isosurface {
  function { f_sphere(x, y, z, 1) }
  contained_by { box { -2, 2 } }
}
