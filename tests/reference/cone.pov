// Tests: cones: pointed (zero top radius), truncated, open (no caps) upside down, and one
// whose first end is the narrow one.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.5, -7> look_at <0, 0.8, 0> angle 55 }
light_source { <4, 9, -6> rgb 1 }
background { rgb <0.15, 0.1, 0.2> }

plane { y, 0 pigment { rgb <0.7, 0.75, 0.7> } }
cone { <-2.5, 0, 0>, 0.8, <-2.5, 2.2, 0>, 0 pigment { rgb <0.9, 0.4, 0.1> } }
cone { <-0.7, 0, 0.5>, 0.9, <-0.7, 1.4, 0.5>, 0.4 pigment { rgb <0.2, 0.6, 0.8> } }
cone { <1, 1.8, -0.5>, 0.8, <1, 0.3, -0.5>, 0.2 open pigment { rgb <0.8, 0.2, 0.6> } }
cone { <2.6, 0, 1>, 0.2, <2.6, 2, 1>, 0.7 pigment { rgb <0.9, 0.9, 0.3> } }
