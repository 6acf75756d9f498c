// Tests: a parallel light (shadows of equal size whatever the distance) and one whose
// plane cuts through the scene (points beyond it are lit but not shadowed).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> angle 50 }
light_source { <3, 6, -4> rgb 0.7 parallel point_at <0, 0, 0> }
light_source { <-1, 1, 0> rgb <0.2, 0.2, 0.4> parallel point_at <-2, 0, 0> }
plane { y, 0 pigment { rgb 0.9 } }
sphere { <-1, 0.8, 0.5>, 0.6 pigment { rgb <0.9, 0.4, 0.3> } }
box { <0.8, 0, -0.5>, <1.6, 1.4, 0.3> pigment { rgb <0.3, 0.5, 0.9> } }
