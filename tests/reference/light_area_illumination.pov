// Tests: area_illumination: each light of the array lights the surface from its own
// position (diffuse and highlights), not only from the centre. (durer is slightly brighter
// next to the light: block diff 1.8/255, no pixel over the threshold.)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <0, 1.6, -0.5> rgb 1 area_light <4, 0, 0>, <0, 0, 2>, 5, 3 area_illumination }
plane { y, 0 pigment { rgb 0.9 } }
sphere { <-1, 0.6, 0.5>, 0.6 pigment { rgb <0.9, 0.4, 0.3> } finish { phong 0.6 } }
box { <0.6, 0, 0>, <1.4, 0.8, 0.8> pigment { rgb <0.3, 0.5, 0.9> } }
