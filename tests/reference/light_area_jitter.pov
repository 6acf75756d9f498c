// Tests: a jittered area light. POV-Ray's jitter is random from render to render; durer's
// is a fixed hash of the lit point, so the penumbra grain differs pixel by pixel.
// tolerance: 0.03
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <2, 5, -1> rgb 1 area_light <3, 0, 0>, <0, 0, 3>, 5, 5 jitter }
plane { y, 0 pigment { rgb 0.9 } }
sphere { <-0.8, 0.9, 0.3>, 0.7 pigment { rgb <0.9, 0.4, 0.3> } }
box { <0.6, 0, -1.2>, <1.4, 1.2, -0.4> pigment { rgb <0.3, 0.5, 0.9> } }
