// Tests: crand graininess: the diffuse amount is lowered by crand times a random number
// per pixel. POV-Ray's numbers are random; durer's are a hash of the point, so single
// pixels differ while the mean brightness matches.
// tolerance: 0.08
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 8, -6> rgb 1 }
plane { y, 0 pigment { rgb 0.8 } finish { crand 0.1 } }
sphere { <-1.3, 1, 0>, 1 pigment { rgb <0.9, 0.5, 0.3> } finish { crand 0.3 } }
sphere { <1.3, 1, 0>, 1 pigment { rgb <0.3, 0.6, 0.9> } }
