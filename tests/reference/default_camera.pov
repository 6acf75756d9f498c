// Tests: the default camera (no camera statement): at the origin looking along +z with
// up y and right 4/3 x. Objects are placed in front of it above and below the eye level.
#version 3.7;
global_settings { assumed_gamma 1.0 }

light_source { <-5, 10, -10> rgb 1 }
background { rgb <0.25, 0.3, 0.4> }

plane { y, -1 pigment { checker rgb <0.8, 0.8, 0.8> rgb <0.4, 0.4, 0.45> } }
sphere { <0, 0, 5>, 1 pigment { rgb <0.9, 0.4, 0.2> } }
box { <-3.2, -1, 6>, <-1.8, 0.6, 7.4> pigment { rgb <0.3, 0.6, 0.9> } }
cone { <2.5, -1, 6>, 0.8, <2.5, 1.2, 6>, 0 pigment { rgb <0.4, 0.8, 0.3> } }
