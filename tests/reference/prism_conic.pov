// prism with conic_sweep: a linear pyramid and a bezier bowl.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
prism { conic_sweep linear_spline 0, 1, 5, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1>
  pigment { rgb <0.9, 0.3, 0.2> } rotate x*180 translate <-1.8, 1, 0.5> }
prism { conic_sweep bezier_spline 0.5, 1, 8, <-1,0>, <-1,-1.2>, <1,-1.2>, <1,0>, <1,0>, <1,1.2>, <-1,1.2>, <-1,0>
  pigment { rgb <0.2, 0.5, 0.9> } scale <1, 1.5, 1> translate <0.8, -0.6, 0.5> }
