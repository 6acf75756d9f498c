// Tests: discs: facing the camera, lying on the floor with a hole, and tilted with a hole
// (an annulus casting a ring shadow).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -7> look_at <0, 1, 0> angle 55 }
light_source { <3, 8, -7> rgb 1 }
background { rgb <0.25, 0.25, 0.3> }

plane { y, 0 pigment { rgb <0.6, 0.65, 0.6> } }
disc { <-2, 1.3, 0>, -z, 1 pigment { rgb <0.9, 0.3, 0.2> } }
disc { <0.5, 0.01, -1.5>, y, 1, 0.5 pigment { rgb <0.2, 0.4, 0.9> } }
disc { <2, 1.5, 1>, <-1, 1, -1>, 1.2, 0.6 pigment { rgb <0.9, 0.85, 0.2> } }
