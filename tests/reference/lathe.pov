// lathe: linear, quadratic, cubic and bezier splines turned around Y.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.7, 0> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
lathe { linear_spline 5, <0,0>, <0.8,0>, <0.5,0.8>, <0.7,1.5>, <0,1.5>
  pigment { rgb <0.9, 0.3, 0.2> } translate <-2.2, 0, 0.5> }
lathe { quadratic_spline 6, <0,-0.5>, <0,0>, <0.7,0.3>, <0.3,1.0>, <0.6,1.6>, <0.5,1.8>
  pigment { rgb <0.2, 0.7, 0.3> } translate <-0.6, 0, 0.8> }
lathe { cubic_spline 7, <0,-0.3>, <0.1,0>, <0.8,0.2>, <0.4,0.9>, <0.7,1.3>, <0.1,1.6>, <0,2>
  pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.5 } translate <1, 0, 0.8> }
lathe { bezier_spline 8, <0,0>, <0.5,0>, <0.9,0.3>, <0.6,0.6>, <0.6,0.6>, <0.3,0.9>, <0.5,1.2>, <0,1.2>
  pigment { rgb <0.9, 0.8, 0.2> } translate <2.4, 0, -0.3> }
