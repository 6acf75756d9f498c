// julia_fractal: quaternion sqr and cube, a tilted slice and a slice distance, with shadows.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -7> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, -1.3 pigment { rgb <0.8, 0.8, 0.7> } }
julia_fractal { <-0.083, 0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15
  pigment { rgb <0.9, 0.4, 0.3> } finish { phong 0.5 } translate <-1.7, 0, 0> }
julia_fractal { <-0.03, 0.5, -0.2, -0.5> cube max_iteration 6 precision 20
  pigment { rgb <0.3, 0.8, 0.4> } rotate <0, 60, 0> translate <0.2, 0, 0.3> }
julia_fractal { <0.2, 0.4, -0.3, 0.1> max_iteration 7 slice <0.3, 0, 0.2, 1>, 0.2
  pigment { rgb <0.3, 0.5, 0.9> } finish { phong 0.5 } rotate <30, 0, 0> translate <1.8, 0, 0> }
