// Tests: planes with checker pigments: a floor, a back wall with scaled checkers, and a
// tilted plane (non-axis normal), plus a sphere so the shading has a reference.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -6> look_at <0, 1, 0> angle 60 }
light_source { <-3, 6, -6> rgb 1 }

plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.9> rgb <0.1, 0.1, 0.1> } }
plane { -z, -4 pigment { checker rgb <0.8, 0.2, 0.2> rgb <0.9, 0.9, 0.3> scale 0.5 } }
plane { <1, 1, 0>, -3 pigment { checker rgb <0.2, 0.3, 0.8> rgb <0.6, 0.8, 1> } }
sphere { <0.5, 0.8, 0>, 0.8 pigment { rgb <0.3, 0.8, 0.3> } }
