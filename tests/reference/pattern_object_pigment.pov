// Tests: the object pattern (inside and outside of a sphere, a CSG object and a declared
// box, as pigment, normal and texture lists) and pigment_pattern (a pigment's grey level
// as a pattern, as pigment and normal).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at 0 right 8 * x up 6 * y }
light_source { <-3, 6, -20> rgb 1 }
#declare Blob = difference { sphere { 0, 1 } cylinder { -2 * z, 2 * z, 0.4 } }
#declare Cube = box { -0.5, 0.5 rotate 30 * z }
#declare Gray = pigment { checker rgb <1, 0, 0>, rgb <0, 0, 1> scale 0.5 }
box { <-4, 0, 0>, <-1.4, 3, 1> pigment { object { sphere { 0, 1 } rgb <0.2, 0.3, 0.8>, rgb <1, 0.8, 0.2> } translate <-2.7, 1.5, 0> } }
box { <-1.3, 0, 0>, <1.3, 3, 1> pigment { object { Blob color rgb <0.3, 0.6, 0.3>, color rgb <0.9, 0.1, 0.1> } translate <0, 1.5, 0> } }
box { <1.4, 0, 0>, <4, 3, 1> texture { object { Cube texture { pigment { rgb 0.3 } }, texture { pigment { rgb <0.3, 1, 0.3> } } } scale 1.5 translate <2.7, 1.5, 0> } }
box { <-4, -3, 0>, <-1.4, -0.1, 1> pigment { pigment_pattern { Gray } color_map { [0 rgb <0, 0, 0.3>] [0.3 rgb <1, 1, 0>] } } }
box { <-1.3, -3, 0>, <1.3, -0.1, 1> pigment { rgb 0.8 } normal { pigment_pattern { gradient x color_map { [0 rgb 0] [1 rgb 2] } scale 0.5 } 0.8 } }
box { <1.4, -3, 0>, <4, -0.1, 1> pigment { rgb 0.8 } normal { object { sphere { <2.7, -1.5, 0>, 1 } normal { bumps 1 scale 0.2 }, normal { dents 2 scale 0.3 } } } }
