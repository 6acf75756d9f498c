// julia_fractal: hypercomplex sqr (as fractal4), hypercomplex sqr on a tilted slice, and a
// quaternion cube cut by a box in a CSG intersection (as fractal2).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -7> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
background { rgb <0.3, 0.4, 0.5> }
julia_fractal { <-0.745, 0, 0.113, 0.05> hypercomplex max_iteration 9
  pigment { rgb <0.9, 0.5, 0.6> } finish { phong 0.9 phong_size 20 }
  scale <1, 2, 1> rotate <135, -30, 0> scale 0.8 translate <-1.8, 0.2, 0> }
julia_fractal { <0.2, 0.1, 0.59, -0.2> hypercomplex max_iteration 7 slice <0, 0.2, 0, 1>, 0.1
  pigment { rgb <0.3, 0.8, 0.4> } rotate <30, 20, 0> translate <0, 0.3, 0> }
intersection {
  julia_fractal { <-0.54, 0.57, 0, -0.37> quaternion cube max_iteration 8 }
  box { <-3, -3, -3>, <3, 3, 0.1> }
  pigment { rgb <0.3, 0.5, 0.9> } rotate <0, 30, 110> translate <1.8, 0.2, 0>
}
