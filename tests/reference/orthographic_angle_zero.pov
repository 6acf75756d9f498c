// orthographic_angle_zero: an orthographic camera's `angle 0` (and `angle` without a value) takes the view of a perspective camera through right and direction at the look_at distance; a given angle overrides the plane's size
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 1, -8> right 4*x up 3*y direction 2*z look_at <0, 0, 0> angle 0 }
light_source { <-4, 6, -6> rgb 1 }
plane { y, -1 pigment { checker rgb 1 rgb <0.2, 0.3, 0.6> } }
sphere { 0, 1 pigment { rgb <0.9, 0.3, 0.1> } finish { phong 0.6 } }
box { <-6, -1, 2>, <6, 3, 2.5> pigment { gradient x color_map { [0 rgb <1, 1, 0>] [1 rgb <0, 0.5, 1>] } scale 2 } }
