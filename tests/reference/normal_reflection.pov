// Tests: the perturbed normal bends reflected and refracted rays — a mirror floor and a glass
// sphere with gradient normals, a reflective box with a checker normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -6> look_at <0, 0.8, 0> angle 60 }
light_source { <4, 9, -6> rgb 1 }
background { rgb <0.3, 0.4, 0.6> }

plane { y, 0 pigment { rgb 0.2 } finish { reflection 0.6 } normal { gradient x 1.5 scale 0.8 } }
plane { z, 6 pigment { checker rgb <0.9, 0.8, 0.3> rgb <0.2, 0.3, 0.8> } }
sphere { <-1.5, 1, 0>, 1 pigment { rgbf <0.9, 1, 0.9, 0.9> } interior { ior 1.5 } normal { gradient y 2 scale 0.4 } finish { phong 0.8 } }
box { <0.6, 0, -0.7>, <2.4, 1.6, 0.7> rotate y*-20 pigment { rgb <0.6, 0.2, 0.2> } finish { reflection 0.5 } normal { checker 0.8 scale 0.3 } }
