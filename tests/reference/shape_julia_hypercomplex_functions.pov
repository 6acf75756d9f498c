// julia_fractal: hypercomplex sin and cos cut by boxes: the boxes' faces show povray's
// inside test for those functions, which reads the point's y for z (measured with inside()).
// tolerance: 0.08 (povray's own hypercomplex sin/cos surfaces are speckled by its ray steps, 6.3% off)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -8> look_at <0, 0, 0> angle 50 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
background { rgb <0.3, 0.4, 0.5> }
intersection {
  julia_fractal { <-0.083, 0.0, -0.83, -0.025> hypercomplex sin max_iteration 6 precision 30 }
  box { <-1.5, -1.5, -1.5>, <1.5, 1.5, 1.5> }
  pigment { rgb <0.3, 0.8, 0.4> } scale 0.9 rotate <0, 20, 0> translate <-1.8, 0, 0>
}
intersection {
  julia_fractal { <-0.2, 0.3, 0.1, 0.0> hypercomplex cos max_iteration 6 precision 30 }
  box { <-1.4, -1.4, -1.4>, <1.4, 1.4, 1.4> }
  pigment { rgb <0.4, 0.5, 0.9> } scale 0.9 rotate <10, -30, 0> translate <1.8, 0, 0>
}
