// iso_internal_curves: functions.inc's 2d curves, f_witch_of_agnesi_2d swept around y (SOR
// switch on), f_devils_curve_2d extruded along z, and the algebraic cylinder f_algbr_cyl2
// swept with an offset and a tilt.
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 0.2, 0> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, -1 pigment { rgb <0.8, 0.8, 0.7> } }
isosurface {
  function { f_witch_of_agnesi_2d(x, y, z, -1, 0.4, 0.5, 1, 0, 0) }
  contained_by { box { <-1, -0.5, -1>, <1, 1, 1> } }
  max_gradient 4
  pigment { rgb <0.9, 0.3, 0.2> }
  translate <-2, 0, 0>
}
isosurface {
  function { f_devils_curve_2d(x, y, z, -1, 0.8, 0.6, 0, 0, 0) }
  contained_by { box { <-1, -1, -0.6>, <1, 1, 0.6> } }
  max_gradient 6
  pigment { rgb <0.2, 0.5, 0.9> }
  rotate <0, 30, 0>
}
isosurface {
  function { f_algbr_cyl2(x, y, z, -1, 5, 1, 0.3, 20) }
  contained_by { box { <-1, -1, -1>, <1, 1, 1> } }
  max_gradient 6
  pigment { rgb <0.3, 0.8, 0.3> }
  translate <2, 0, 0>
}
