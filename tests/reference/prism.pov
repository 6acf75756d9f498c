// prism: linear (with a hole), quadratic, cubic and bezier splines, linear sweep.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.3, 0> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
prism { linear_spline 0, 0.5, 10,
  <0,0>, <1.5,0>, <1.5,1.5>, <0,1.5>, <0,0>, <0.4,0.4>, <1.1,0.4>, <1.1,1.1>, <0.4,1.1>, <0.4,0.4>
  pigment { rgb <0.9, 0.3, 0.2> } translate <-2.5, 0, 0> }
prism { quadratic_spline 0, 0.8, 6,
  <0.5,-0.5>, <0,0>, <1,0>, <1,1>, <0,1>, <0,0>
  pigment { rgb <0.2, 0.7, 0.3> } translate <-0.5, 0, 1> }
prism { cubic_spline 0, 0.6, 7,
  <0.5,-0.5>, <0,0>, <1,0>, <1,1>, <0,1>, <0,0>, <-0.5,0.5>
  pigment { rgb <0.2, 0.5, 0.9> } translate <1.2, 0, 0.8> }
prism { bezier_spline 0, 0.4, 8,
  <0,0>, <0.5,-0.5>, <1,-0.5>, <1,0>, <1,0>, <1,1>, <0,1>, <0,0>
  pigment { rgb <0.9, 0.8, 0.2> } translate <0.5, 0, -1.3> }
