// iso_internal_comma_cyclid_enneper_torus: functions.inc's f_comma, f_dupin_cyclid, f_enneper
// and f_helical_torus as isosurfaces, with the parameters of POV-Ray's incdemo/i_internal.pov.
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -12> look_at <0, 0, 0> angle 50 }
light_source { <-6, 8, -10> rgb 1 }
light_source { <6, 2, -8> rgb 0.4 }
background { rgb <0.2, 0.3, 0.3> }
isosurface {
  function { f_comma(x, y, z, 1) }
  contained_by { box { <-1.0, -0.5, -0.55>, <1.0, 0.6, 1.1> } }
  max_gradient 1.4
  pigment { rgb <0.9, 0.7, 0.3> }
  scale 2 rotate <-35, -30, 0> translate <-2.6, 1.6, 0>
}
isosurface {
  function { f_dupin_cyclid(x, y, z, -0.05, 0.27, 0.04, 0.55, 0.0, 1.0) }
  contained_by { box { <1.0, -0.6, -1.6>, <4.3, 0.6, 1.6> } }
  max_gradient 2.1
  pigment { rgb <0.3, 0.6, 0.9> }
  scale 0.8 rotate <-60, 0, 0> translate <0.4, 1.7, 0>
}
isosurface {
  function { f_enneper(x, y, z, -0.1) }
  contained_by { box { <-3.5, -3.5, -3.8>, <3.5, 3.5, -0.25> } }
  max_gradient 85
  pigment { rgb <0.9, 0.3, 0.3> }
  scale 0.55 rotate <0, 15, 0> translate <-2.6, -1.8, 0>
}
isosurface {
  function { f_helical_torus(x, y, z, 2, 7, 1, 0.1, 1, 0.5, 1, 6, 2.0, 0) }
  contained_by { box { <-3.7, -1.7, -3.7>, <3.7, 1.7, 3.7> } }
  max_gradient 13
  pigment { rgb <0.4, 0.8, 0.4> }
  scale 0.6 rotate <-50, 0, 0> translate <2.6, -1.7, 0>
}
