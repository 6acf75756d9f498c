// Tests: spheres of different centres and radii, one sunk into the floor, one floating
// (detached shadow), on a plain plane lit by one point light.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.5, -6> look_at <0, 0.7, 0> angle 50 }
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.1, 0.12, 0.2> }

plane { y, 0 pigment { rgb <0.8, 0.8, 0.75> } }
sphere { <-1.7, 0.7, 0>, 0.7 pigment { rgb <0.9, 0.15, 0.1> } }
sphere { <0, 1, 0.8>, 1 pigment { rgb <0.2, 0.7, 0.25> } }
sphere { <1.6, 0.2, -0.6>, 0.5 pigment { rgb <0.2, 0.3, 0.9> } }
sphere { <1.2, 2.1, 1.2>, 0.35 pigment { rgb 1 } }
