// sor: the manual's vase (with caps) and a goblet shape.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.7, 0> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
sor { 7, <0.000000, 0.000000> <0.118143, 0.000000> <0.620253, 0.540084> <0.210970, 0.827004> <0.194093, 0.962025> <0.286920, 1.000000> <0.468354, 1.033755>
  pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } scale 1.5 translate <-1.5, 0, 0.5> }
sor { 6, <0.5, -0.5>, <0.6, 0>, <0.3, 0.6>, <0.7, 1.2>, <0.5, 1.8>, <0.4, 2.2>
  pigment { rgb <0.2, 0.5, 0.9> } translate <1.2, 0, 0.5> }
