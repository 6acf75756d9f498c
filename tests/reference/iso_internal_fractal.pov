// iso_internal_fractal: functions.inc's noise fractals as isosurface height fields,
// f_ridged_mf on the left and f_hetero_mf on the right.
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -5> look_at <0, 0, 0> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
background { rgb <0.6, 0.7, 0.9> }
isosurface {
  function { y - 0.35 * f_ridged_mf(x, 0, z, 0.9, 2, 3, 1, 2, 2) }
  contained_by { box { <-1.4, -0.2, -1.4>, <1.4, 1, 1.4> } }
  max_gradient 6
  pigment { rgb <0.8, 0.6, 0.4> }
  translate <-1.5, 0, 0>
}
isosurface {
  function { y - 0.25 * f_hetero_mf(x, 0, z, 0.9, 2, 2.5, 0.8, 1, 2) }
  contained_by { box { <-1.4, -0.2, -1.4>, <1.4, 1.2, 1.4> } }
  max_gradient 6
  pigment { rgb <0.4, 0.7, 0.4> }
  translate <1.5, 0, 0>
}
