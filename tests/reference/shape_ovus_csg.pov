// shape_ovus_csg: an ovus cut open by a box (intersection with an inverse ovus inside shows
// its inside test) and an ovus carved out of the top of a box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.6, 0> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, -1 pigment { rgb <0.8, 0.8, 0.7> } }
difference {
  ovus { 1, 0.7 }
  box { <-2, 0.3, -2>, <0, 3, 0> }
  ovus { 0.8, 0.5 translate <0, 0.05, 0> }
  translate <-1.6, 0, 0>
  pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.4 }
}
difference {
  box { <-0.9, -1, -0.9>, <0.9, 0.6, 0.9> }
  ovus { 0.7, 0.5 }
  rotate <0, 30, 0> translate <1.6, 0, 0.5>
  pigment { rgb <0.3, 0.6, 0.9> } finish { phong 0.4 }
}
intersection {
  ovus { 0.5, 0.6 }
  sphere { <0.4, 0.6, -0.3>, 0.5 inverse }
  translate <0, 0.2, -2>
  pigment { rgb <0.4, 0.9, 0.4> }
}
