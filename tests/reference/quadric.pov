// Tests: quadric surfaces clipped by boxes with intersection: a paraboloid bowl
// (x^2 + z^2 - y = 0) and a hyperboloid of one sheet (x^2 - y^2 + z^2 - 0.2 = 0).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -7> look_at <0, 0.7, 0> angle 50 }
light_source { <-4, 10, -8> rgb 1 }
background { rgb <0.15, 0.2, 0.25> }

plane { y, 0 pigment { checker rgb 0.8 rgb 0.55 } }
intersection {
  quadric { <1, 0, 1>, <0, 0, 0>, <0, -1, 0>, 0 }
  box { <-2, 0, -2>, <2, 1.5, 2> }
  translate <-1.7, 0, 0>
  pigment { rgb <0.9, 0.4, 0.2> }
}
intersection {
  quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.2 }
  box { <-1.2, -1, -1.2>, <1.2, 1, 1.2> }
  translate <1.7, 1, 0.5>
  pigment { rgb <0.3, 0.6, 0.9> }
}
