// finish_irid: thin-film iridescence (irid amount and thickness) on spheres and a plane,
// with diffuse and specular light tinted alike
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> angle 55 }
light_source { <-4, 8, -6> rgb 0.8 }
light_source { <5, 3, -3> rgb 0.4 }
plane { y, 0 pigment { rgb 0.7 } finish { diffuse 0.8 irid { 0.3 thickness 0.8 } } }
sphere { <-1.6, 1, 0>, 1 pigment { rgb 0.9 } finish { diffuse 0.7 specular 0.6 roughness 0.02 irid { 0.35 thickness 0.5 } } }
sphere { <0.6, 0.8, 0.5>, 0.8 pigment { rgb <0.3, 0.5, 0.9> } finish { diffuse 0.6 phong 0.8 irid { 0.6 thickness 0.25 } } }
sphere { <1.9, 0.6, -0.6>, 0.6 pigment { rgb <0.9, 0.8, 0.3> } finish { irid { 1 thickness 1.2 } } }
