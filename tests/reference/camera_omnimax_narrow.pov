// camera_omnimax_narrow: an omnimax camera narrower than square (right 0.8): the dome's
// centre is the image centre and the image width spans the dome
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { rgb <0.5, 0.6, 0.8> }
camera { omnimax location <0, 1.5, -2.5> right 0.8*x look_at <0, 1, 2> }
light_source { <-5, 8, -6> rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.8> rgb <0.3, 0.4, 0.5> } }
sphere { <0, 1, 2>, 1 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
sphere { <-2.2, 0.7, 1>, 0.7 pigment { rgb <0.2, 0.6, 0.9> } }
box { <1.5, 0, 0.5>, <2.7, 1.2, 1.7> pigment { rgb <0.3, 0.8, 0.3> } rotate y*20 }
cylinder { <-1, 0, 5>, <-1, 3, 5>, 0.4 pigment { rgb <0.9, 0.8, 0.2> } }
