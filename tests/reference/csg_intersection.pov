// Tests: intersection: a lens (two spheres), a rounded cube (box and sphere) and the
// Steinmetz solid of three perpendicular cylinders.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -7> look_at <0, 0.9, 0> angle 50 }
light_source { <-4, 9, -7> rgb 1 }
background { rgb <0.15, 0.2, 0.2> }

plane { y, 0 pigment { checker rgb 0.8 rgb 0.6 } }
intersection {
  sphere { <-0.6, 0, 0>, 1 }
  sphere { <0.6, 0, 0>, 1 }
  rotate y*30 translate <-2.2, 0.9, 0>
  pigment { rgb <0.9, 0.5, 0.2> }
}
intersection {
  box { <-0.7, -0.7, -0.7>, <0.7, 0.7, 0.7> }
  sphere { 0, 0.9 }
  rotate y*25 translate <0, 0.7, 0.5>
  pigment { rgb <0.3, 0.7, 0.4> }
}
intersection {
  cylinder { <-1, 0, 0>, <1, 0, 0>, 0.6 }
  cylinder { <0, -1, 0>, <0, 1, 0>, 0.6 }
  cylinder { <0, 0, -1>, <0, 0, 1>, 0.6 }
  rotate <20, 30, 0> translate <2.1, 0.8, 0>
  pigment { rgb <0.4, 0.5, 0.9> }
}
