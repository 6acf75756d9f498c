// iso_internal_surfaces: functions.inc's algebraic surfaces, f_heart, f_klein_bottle and
// f_quantum, and the blob-like f_cross_ellipsoids.
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.3, 0> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, -1.3 pigment { rgb <0.8, 0.8, 0.7> } }
isosurface {
  function { f_heart(x, y, z, -1) }
  contained_by { box { -1.3, 1.3 } }
  max_gradient 30
  pigment { rgb <0.9, 0.2, 0.3> }
  rotate <-90, 0, 0>
  translate <-2.4, 0.2, 0>
}
isosurface {
  function { f_klein_bottle(x, y, z, 1) }
  contained_by { box { -1.4, 1.4 } }
  max_gradient 40
  pigment { rgb <0.2, 0.5, 0.9> }
  scale 0.55
  rotate <0, 30, 0>
  translate <-0.6, 0.3, 0>
}
isosurface {
  function { f_quantum(x, y, z, 0) }
  contained_by { box { -3, 3 } }
  max_gradient 6
  pigment { rgb <0.3, 0.8, 0.3> }
  scale 0.3
  translate <1, 0.3, 0>
}
isosurface {
  function { f_cross_ellipsoids(x, y, z, 0.2, 4, 1, 0.5) }
  contained_by { box { -1.2, 1.2 } }
  max_gradient 4
  pigment { rgb <0.9, 0.7, 0.2> }
  translate <2.5, 0.2, 0>
}
