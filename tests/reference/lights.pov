// Tests: several light sources: a red and a blue light cast two coloured shadows, a
// shadowless green light adds colour without shadows, and a no_shadow sphere casts none.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -7> look_at <0, 0.5, 0> angle 50 }
light_source { <-4, 6, -3> rgb <1, 0.4, 0.4> }
light_source { <4, 6, -3> rgb <0.4, 0.4, 1> }
light_source { <0, 3, -6> rgb <0, 0.3, 0> shadowless }

plane { y, 0 pigment { rgb <0.9, 0.9, 0.9> } }
cylinder { <-0.8, 0, 0>, <-0.8, 1.6, 0>, 0.35 pigment { rgb <0.9, 0.9, 0.9> } }
sphere { <1.4, 0.8, 0.2>, 0.6 pigment { rgb <0.9, 0.8, 0.3> } no_shadow }
box { <-0.3, 0, -2.2>, <0.5, 0.5, -1.4> pigment { rgb <0.8, 0.8, 0.8> } }
