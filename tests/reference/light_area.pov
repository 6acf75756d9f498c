// Tests: a 5x5 area light (every light tested) casting soft shadows of a sphere and a box,
// and a 4x4 one (an even array weighs all its lights equally).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <2, 5, -1> rgb 0.7 area_light <3, 0, 0>, <0, 0, 3>, 5, 5 }
light_source { <-3, 4, -2> rgb <0.3, 0.3, 0.2> area_light <2, 0, 0>, <0, 2, 0>, 4, 4 }
plane { y, 0 pigment { rgb 0.9 } }
sphere { <-0.8, 0.9, 0.3>, 0.7 pigment { rgb <0.9, 0.4, 0.3> } }
box { <0.6, 0, -1.2>, <1.4, 1.2, -0.4> pigment { rgb <0.3, 0.5, 0.9> } }
