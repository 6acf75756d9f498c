// Tests: a shadow through a layered texture passes what every layer passes, colour by
// colour: a red filtering layer over a clear `transmit` one casts a red shadow (a glass
// texture given after a `pigment`), and a layer of green filter under blue transmit a dark
// teal one.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.6, 0> }
light_source { <-3, 9, 6>, rgb 1 }
plane { y, 0 pigment { rgb 0.9 } }
sphere { <-1.6, 1, 0>, 1
  pigment { transmit 0.9 }
  texture { pigment { rgbf <0.9, 0.1, 0.2, 0.8> } finish { phong 0.5 } } }
box { <0.4, 0, -0.6>, <2.4, 1.6, 0.6>
  texture { pigment { rgbf <0.1, 1, 0.2, 0.7> } }
  texture { pigment { rgbt <0.2, 0.3, 1, 0.6> } } }
cylinder { <0, 0, -2.5>, <0, 1.2, -2.5>, 0.3 pigment { rgb <0.9, 0.6, 0.2> } }
