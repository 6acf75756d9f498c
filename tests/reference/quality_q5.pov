// Quality +Q5: what povray leaves out at this level (0-1 pigment colours only, 2-3 no
// shadows, 4 area lights as points, 5 area lights, 6-7 transparency and refraction, 8
// reflection, 9 media and radiosity).
// povray-options: -A +Q5
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -5> look_at 0 }
light_source { <0, 8, 0> rgb 1 area_light x*4, z*4, 5, 5 }
plane { y, -1 pigment { checker rgb 1, rgb <0.3, 0.3, 0.8> } }
sphere { <-1.2, 0, 0>, 1 pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.5 } }
sphere { <1.2, 0, 0>, 0.5 pigment { rgb 0.5 } finish { phong 1 reflection 0.4 } }
background { rgb <0.3, 0.5, 0.9> }
