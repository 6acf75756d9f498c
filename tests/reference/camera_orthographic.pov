// Tests: orthographic camera (right and up give the view size): a grid of equal boxes whose
// parallel edges stay parallel, seen from above at an angle.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <6, 7, -8> look_at <0, 0.3, 0> right x*8 up y*6 }
light_source { <-4, 10, -5> rgb 1 }
background { rgb <0.2, 0.2, 0.25> }

plane { y, 0 pigment { checker rgb <0.8, 0.8, 0.8> rgb <0.55, 0.55, 0.6> } }
#declare Block = box { <-0.4, 0, -0.4>, <0.4, 0.8, 0.4> }
object { Block translate <-1.5, 0, -1.5> pigment { rgb <0.9, 0.3, 0.2> } }
object { Block translate <0, 0, -1.5> pigment { rgb <0.9, 0.7, 0.2> } }
object { Block translate <1.5, 0, -1.5> pigment { rgb <0.4, 0.8, 0.3> } }
object { Block translate <-1.5, 0, 1.5> pigment { rgb <0.3, 0.6, 0.9> } }
object { Block translate <0, 0, 1.5> pigment { rgb <0.6, 0.3, 0.9> } }
object { Block translate <1.5, 0, 1.5> pigment { rgb <0.15, 0.15, 0.15> } }
sphere { <0, 0.7, 0>, 0.7 pigment { rgb <0.8, 0.2, 0.5> } }
