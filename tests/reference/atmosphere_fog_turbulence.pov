// atmosphere_fog_turbulence: ground fog stirred by turbulence
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { rgb <0.5, 0.6, 0.8> }
camera { location <0, 2, -5> look_at <0, 1, 2> angle 50 }
light_source { <-5, 8, -6> rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.8> rgb <0.3, 0.4, 0.5> } }
sphere { <0, 1, 2>, 1 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
sphere { <-2.2, 0.7, 1>, 0.7 pigment { rgb <0.2, 0.6, 0.9> } }
box { <1.5, 0, 0.5>, <2.7, 1.2, 1.7> pigment { rgb <0.3, 0.8, 0.3> } rotate y*20 }
cylinder { <-1, 0, 5>, <-1, 3, 5>, 0.4 pigment { rgb <0.9, 0.8, 0.2> } }
fog { fog_type 2 distance 3 colour rgb 0.9 fog_offset 0.5 fog_alt 0.4 turbulence <0.5, 0.2, 0.5> turb_depth 0.3 octaves 4 omega 0.6 lambda 2.5 }
