// shape_bicubic_patch: a type 1 patch with 3 by 3 steps and a type 0 patch with 2 by 4 steps
// (smooth shading over the triangles).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.6, 0> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
#declare Hill = bicubic_patch { type 1 u_steps 3 v_steps 3
  <0, 0, 0>, <1, 0.2, 0>, <2, 0.2, 0>, <3, 0, 0>,
  <0, 0.3, 1>, <1, 2.5, 1>, <2, 1.5, 1>, <3, 0.3, 1>,
  <0, 0.3, 2>, <1, 1.5, 2>, <2, 2.8, 2>, <3, 0.3, 2>,
  <0, 0, 3>, <1, 0.2, 3>, <2, 0.2, 3>, <3, 0, 3>
}
object { Hill scale 0.7 translate <-2.6, 0, -0.5> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
bicubic_patch { type 0 flatness 0.01 u_steps 2 v_steps 4
  <0, 0, 0>, <1, 1, 0>, <2, -0.5, 0>, <3, 0.5, 0>,
  <0, 1, 1>, <1, 2, 1>, <2, 0.5, 1>, <3, 1, 1>,
  <0, 1, 2>, <1, 0, 2>, <2, 2, 2>, <3, 1, 2>,
  <0, 0.5, 3>, <1, 1, 3>, <2, 0.5, 3>, <3, 1.5, 3>
  scale 0.7 rotate <-30, 20, 0> translate <0.3, 0.4, -0.2>
  pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.5 } }
