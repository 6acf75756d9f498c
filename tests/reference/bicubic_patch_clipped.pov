// bicubic_patch_clipped: POV-Ray never tests a bicubic patch's hits against clipped_by; rays
// that cross the clipping box (not the patch's own box) see the whole patch.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -5> look_at <0, 0.3, 0> angle 50 }
light_source { <-4, 8, -3> rgb 1 }
plane { y, -0.5 pigment { rgb <0.8, 0.8, 0.7> } }
#declare Patch = bicubic_patch { type 1 flatness 0.01 u_steps 4 v_steps 4
  <-2, 0, -2>, <-0.7, 1, -2>, <0.7, -0.5, -2>, <2, 0, -2>,
  <-2, 0.5, -0.7>, <-0.7, 1.5, -0.7>, <0.7, 1, -0.7>, <2, 0.3, -0.7>,
  <-2, 0, 0.7>, <-0.7, -0.5, 0.7>, <0.7, 1.2, 0.7>, <2, 0.5, 0.7>,
  <-2, 0.2, 2>, <-0.7, 0.6, 2>, <0.7, 0.4, 2>, <2, 0, 2> }
object { Patch clipped_by { box { <-1.5, -1, -1.5>, <1, 0.6, 1.5> } } pigment { rgb <0.9, 0.4, 0.2> } }
