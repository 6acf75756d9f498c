// iso_internal_helix: functions.inc's f_helix1 (a double helix of round tubes and a single
// helix of rotated diamond tubes) and f_helix2 (a twisted square column).
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -6> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, -1.2 pigment { rgb <0.8, 0.8, 0.7> } }
isosurface {
  function { f_helix1(x, y, z, 2, 4, 0.12, 0.45, 1, 1, 0) }
  contained_by { box { <-0.7, -1.2, -0.7>, <0.7, 1.2, 0.7> } }
  max_gradient 3
  pigment { rgb <0.9, 0.3, 0.2> }
  translate <-1.8, 0, 0>
}
isosurface {
  function { f_helix1(x, y, z, 1, 3, 0.2, 0.4, 1.5, 2, 30) }
  contained_by { box { <-0.7, -1.2, -0.7>, <0.7, 1.2, 0.7> } }
  max_gradient 3
  pigment { rgb <0.2, 0.5, 0.9> }
}
isosurface {
  function { f_helix2(x, y, z, 0, 2, 0.45, 0.15, 0, 0, 0) }
  contained_by { box { <-0.7, -1.2, -0.7>, <0.7, 1.2, 0.7> } }
  max_gradient 3
  pigment { rgb <0.3, 0.8, 0.3> }
  translate <1.8, 0, 0>
}
