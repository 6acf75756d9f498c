// superellipsoid: boxy, cylinder-like and star-like exponents.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.7, 0> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
superellipsoid { <0.25, 0.25> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } scale 0.7 rotate <0, 30, 0> translate <-1.8, 0.7, 0.5> }
superellipsoid { <1, 0.2> pigment { rgb <0.2, 0.7, 0.3> } scale 0.7 rotate <-90, 0, 0> translate <0, 0.7, 1> }
superellipsoid { <2, 0.5> pigment { rgb <0.2, 0.5, 0.9> } scale 0.7 rotate <20, 40, 0> translate <1.8, 0.8, 0.3> }
