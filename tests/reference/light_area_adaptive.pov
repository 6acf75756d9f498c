// Tests: adaptive area lights: a 9x9 array with adaptive 1 (corners, then subdivision where
// they differ) and a linear 6x1 light with adaptive 0.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <2, 5, -1> rgb 0.7 area_light <3, 0, 0>, <0, 0, 3>, 9, 9 adaptive 1 }
light_source { <-3, 4, -2> rgb 0.3 area_light <0, 0, 3>, <0, 0, 0>, 6, 1 adaptive 0 }
plane { y, 0 pigment { rgb 0.9 } }
sphere { <-0.8, 0.9, 0.3>, 0.7 pigment { rgb <0.9, 0.4, 0.3> } }
box { <0.6, 0, -1.2>, <1.4, 1.2, -0.4> pigment { rgb <0.3, 0.5, 0.9> } }
