// An orthographic camera with look_at and no right/up (POV-Ray scales the plane by the distance); spotlight and shadowless, where the last keyword wins.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <5, 8, -5> rgb 1 spotlight point_at 0 radius 10 falloff 15 shadowless }
light_source { <-5, 8, -5> rgb 0.5 shadowless spotlight point_at <-1,0,0> radius 5 falloff 8 }
plane { y, 0 pigment { checker rgb 1, rgb 0.2 } }
sphere { <0, 0.5, 0>, 0.5 pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.6 } }
box { <-2, 0, 0>, <-1.2, 0.8, 0.8> pigment { rgb <0.2, 0.5, 0.9> } }
