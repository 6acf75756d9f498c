// Tests: cylinders: capped and standing, open (no end caps, inside visible) lying on its
// side, a tilted one with an arbitrary axis, and an open one seen from above.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -7> look_at <0, 0.4, 0> angle 55 }
light_source { <-5, 10, -5> rgb 1 }
background { rgb <0.2, 0.25, 0.3> }

plane { y, 0 pigment { checker rgb 0.75 rgb 0.45 } }
cylinder { <-2.5, 0, 0>, <-2.5, 2, 0>, 0.6 pigment { rgb <0.9, 0.3, 0.2> } }
cylinder { <-1.4, 0.5, -2.2>, <-0.4, 0.5, -0.2>, 0.5 open pigment { rgb <0.3, 0.8, 0.4> } }
cylinder { <1.2, 0, 1>, <2.8, 2, 1.5>, 0.3 pigment { rgb <0.3, 0.4, 0.9> } }
cylinder { <2.3, 0, -1.2>, <2.3, 0.8, -1.2>, 0.55 open pigment { rgb <0.9, 0.8, 0.2> } }
