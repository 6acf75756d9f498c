// Tests: difference: a box with a spherical bite (the cut surface takes the pigment of the
// subtracted sphere), a sphere drilled by two cylinders, and a hollow tube cut from a
// cylinder.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4.5, -7> look_at <0, 0.7, 0> angle 50 }
light_source { <-5, 10, -7> rgb 1 }
background { rgb <0.2, 0.18, 0.25> }

plane { y, 0 pigment { rgb <0.75, 0.75, 0.7> } }
difference {
  box { <-0.8, 0, -0.8>, <0.8, 1.4, 0.8> pigment { rgb <0.3, 0.6, 0.9> } }
  sphere { <0.8, 1.4, -0.8>, 0.9 pigment { rgb <0.95, 0.9, 0.3> } }
  rotate y*-20 translate <-2, 0, 0.3>
}
difference {
  sphere { 0, 0.9 }
  cylinder { <-1, 0, 0>, <1, 0, 0>, 0.35 }
  cylinder { <0, 0, -1>, <0, 0, 1>, 0.35 }
  rotate y*30 translate <0.2, 0.9, 0>
  pigment { rgb <0.9, 0.3, 0.3> }
}
difference {
  cylinder { <0, 0, 0>, <0, 1.2, 0>, 0.7 }
  cylinder { <0, -0.1, 0>, <0, 1.3, 0>, 0.5 }
  translate <2.2, 0, -0.4>
  pigment { rgb <0.4, 0.8, 0.4> }
}
