// Tests: spotlights: a white one with a sharp edge (radius close to falloff), a red one
// with a soft edge and high tightness, and a blue one pointed sideways at the wall.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -7> look_at <0, 0.5, 0> angle 55 }
light_source { <-2, 6, -1> rgb 1
  spotlight point_at <-2, 0, 0> radius 12 falloff 15 tightness 0 }
light_source { <2, 5, -2> rgb <1, 0.3, 0.2>
  spotlight point_at <1.5, 0, 0> radius 5 falloff 25 tightness 20 }
light_source { <0, 1, -3> rgb <0.3, 0.4, 1>
  spotlight point_at <0, 1.5, 3> radius 8 falloff 14 }

plane { y, 0 pigment { rgb <0.8, 0.8, 0.8> } }
plane { z, 3 pigment { rgb <0.8, 0.8, 0.8> } }
sphere { <-2, 0.5, 0>, 0.5 pigment { rgb <0.9, 0.9, 0.3> } }
sphere { <1.5, 0.5, 0>, 0.5 pigment { rgb 1 } }
