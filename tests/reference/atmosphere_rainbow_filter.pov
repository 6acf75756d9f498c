// atmosphere_rainbow_filter: rainbow arc whose colour map fades with filter instead of transmit
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { rgb <0.5, 0.6, 0.8> }
camera { location <0, 1, -5> look_at <0, 3, 2> angle 90 }
light_source { <-5, 8, -6> rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.8> rgb <0.3, 0.4, 0.5> } }
sphere { <0, 1, 2>, 1 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
sphere { <-2.2, 0.7, 1>, 0.7 pigment { rgb <0.2, 0.6, 0.9> } }
box { <1.5, 0, 0.5>, <2.7, 1.2, 1.7> pigment { rgb <0.3, 0.8, 0.3> } rotate y*20 }
cylinder { <-1, 0, 5>, <-1, 3, 5>, 0.4 pigment { rgb <0.9, 0.8, 0.2> } }
rainbow { angle 42.5 width 8 distance 1000 direction <-0.2, -0.2, 1> arc_angle 120 falloff_angle 30 up y
  color_map { [0.0 rgbf <1, 0, 0, 1>] [0.1 rgbf <1, 0, 0, 0.3>] [0.3 rgbf <1, 1, 0, 0.3>] [0.5 rgbf <0, 1, 0, 0.3>] [0.7 rgbf <0, 0, 1, 0.3>] [0.9 rgbf <0.5, 0, 1, 0.3>] [1.0 rgbf <0.5, 0, 1, 1>] } }
