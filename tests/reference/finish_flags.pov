// Tests: no_image (invisible to the camera but seen in the mirror and casting a shadow)
// and no_reflection (seen directly, missing from the mirror).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -7> look_at <0, 1, 0> angle 55 }
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.3, 0.45, 0.7> }
plane { y, 0 pigment { rgb 0.8 } }
box { <-3, 0, 2>, <3, 3, 2.2> pigment { rgb 0.1 } finish { reflection 0.8 } }
sphere { <-1.2, 0.8, 0>, 0.8 pigment { rgb <0.9, 0.3, 0.2> } no_image }
sphere { <1.2, 0.8, 0>, 0.8 pigment { rgb <0.3, 0.8, 0.3> } no_reflection }
