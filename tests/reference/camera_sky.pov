// Tests: perspective camera with a wide angle and a tilted sky vector: the horizon and the
// vertical pillars appear rotated.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2, -6> look_at <0, 1, 0> sky <0.4, 1, 0> angle 75 }
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.4, 0.55, 0.8> }

plane { y, 0 pigment { checker rgb <0.3, 0.6, 0.3> rgb <0.2, 0.45, 0.2> scale 2 } }
cylinder { <-2, 0, 1>, <-2, 3, 1>, 0.3 pigment { rgb <0.9, 0.9, 0.85> } }
cylinder { <2, 0, 1>, <2, 3, 1>, 0.3 pigment { rgb <0.9, 0.9, 0.85> } }
box { <-2.3, 3, 0.7>, <2.3, 3.4, 1.3> pigment { rgb <0.8, 0.3, 0.2> } }
sphere { <0, 0.7, -1>, 0.7 pigment { rgb <0.9, 0.7, 0.1> } }
