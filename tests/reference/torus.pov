// Tests: tori: lying flat (the default, in the x-z plane), standing (rotated), thin, and
// two interlocked links.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -7> look_at <0, 0.7, 0> angle 55 }
light_source { <-4, 10, -6> rgb 1 }
background { rgb <0.1, 0.15, 0.15> }

plane { y, 0 pigment { checker rgb <0.8, 0.8, 0.8> rgb <0.5, 0.5, 0.55> } }
torus { 1, 0.3 translate <-2, 0.3, 0.5> pigment { rgb <0.9, 0.3, 0.3> } }
torus { 0.8, 0.25 rotate x*90 translate <0.3, 1.05, 0> pigment { rgb <0.3, 0.8, 0.3> } }
torus { 0.7, 0.08 translate <2.2, 0.08, -1> pigment { rgb <0.9, 0.8, 0.2> } }
torus { 0.6, 0.15 rotate x*90 translate <1.6, 1.5, 1.5> pigment { rgb <0.3, 0.4, 0.9> } }
torus { 0.6, 0.15 rotate z*90 translate <2.2, 1.5, 1.5> pigment { rgb <0.9, 0.5, 0.1> } }
