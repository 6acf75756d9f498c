// Tests: max_trace_level: two parallel mirrors facing each other with a sphere between
// them make a corridor of reflections, cut off after 4 levels.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 4 }

camera { location <-1.6, 1.4, -2.5> look_at <2, 0.9, 1.2> angle 60 }
light_source { <0, 6, -3> rgb 1 }
background { rgb <0.3, 0.3, 0.4> }

plane { y, 0 pigment { checker rgb <0.8, 0.8, 0.8> rgb <0.3, 0.3, 0.3> } }
#declare Mirror = finish { ambient 0 diffuse 0.05 reflection 0.9 }
box { <-2.2, 0, -6>, <-2, 2.5, 6> pigment { rgb 1 } finish { Mirror } }
box { <2, 0, -6>, <2.2, 2.5, 6> pigment { rgb 1 } finish { Mirror } }
sphere { <0, 0.8, 0.5>, 0.5 pigment { rgb <0.9, 0.3, 0.2> } }
cylinder { <-0.8, 0, 2>, <-0.8, 1.5, 2>, 0.2 pigment { rgb <0.3, 0.5, 0.9> } }
