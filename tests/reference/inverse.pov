// Tests: inverse: an intersection with an inverted sphere (equivalent to a difference), an
// intersection with an inverted plane (a dome), and a sphere with a cubic cavity (an
// inverted box) cut open by a plane to show the cavity.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4.5, -7> look_at <0, 0.7, 0> angle 50 }
light_source { <-5, 10, -7> rgb 1 }
background { rgb <0.15, 0.15, 0.2> }

plane { y, 0 pigment { checker rgb <0.7, 0.75, 0.7> rgb <0.45, 0.5, 0.45> } }
intersection {
  box { <-0.8, 0, -0.8>, <0.8, 1.2, 0.8> }
  sphere { <0, 1.2, -0.8>, 0.8 inverse }
  translate <-2.1, 0, 0>
  pigment { rgb <0.9, 0.5, 0.2> }
}
intersection {
  sphere { 0, 1 }
  plane { y, 0 inverse }
  translate <0, 0, 0.8>
  pigment { rgb <0.3, 0.6, 0.9> }
}
intersection {
  sphere { 0, 0.9 }
  box { <-0.45, -0.45, -0.45>, <0.45, 0.45, 0.45> inverse }
  plane { -z, 0.1 }
  rotate y*-30 translate <2.1, 0.9, 0>
  pigment { rgb <0.9, 0.3, 0.5> }
}
