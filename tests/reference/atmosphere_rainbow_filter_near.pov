// Tests: a rainbow's filter over nearby objects: the filter is weighted by the bow's fog share
// (a short `distance` here, so the share varies across the scene), and transmit bounds it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { rgb <0.5, 0.6, 0.8> }
camera { location <0, 1, -5> look_at <0, 2.5, 2> angle 90 }
light_source { <-5, 8, -6> rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.8> rgb <0.3, 0.4, 0.5> } }
sphere { <0, 1.5, 2>, 1.5 pigment { rgb <0.9, 0.8, 0.7> } finish { phong 0.5 } }
box { <-4, 0, 6>, <4, 6, 6.5> pigment { rgb <0.8, 0.8, 0.9> } }
rainbow { angle 40 width 20 distance 6 direction <-0.1, -0.3, 1> jitter 0
  color_map { [0.0 rgbf <1, 0.1, 0.1, 1>] [0.25 rgbf <1, 0.9, 0.1, 0.8>]
    [0.5 rgbft <0.1, 1, 0.2, 0.6, 0.5>] [0.75 rgbf <0.1, 0.2, 1, 0.9>] [1.0 rgbf <0.6, 0.1, 1, 1>] } }
