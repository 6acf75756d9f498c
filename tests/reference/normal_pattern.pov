// Tests: normals — gradient as a normal with the default bump size and with a given one,
// bump_size, a scaled normal (bumps keep their depth), no_bump_scale, checker as a normal,
// slope_map, normal_map, a declared normal, normals inside textures and texture maps.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.5, -6> look_at <0, 0.6, 0> angle 60 }
light_source { <-3, 9, -6> rgb 1 }
background { rgb <0.15, 0.15, 0.2> }

#declare Ridges = normal { gradient x 3 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } scale 0.5 }

plane { y, 0 pigment { rgb 0.8 } normal { gradient <1, 0, 1> 2 scale 0.7 } finish { specular 0.4 } }
sphere { <-2, 0.8, 0>, 0.8 pigment { rgb <0.9, 0.4, 0.2> } normal { Ridges } finish { phong 0.8 } }
sphere { <0, 0.8, 0>, 0.8 texture { pigment { rgb <0.3, 0.6, 0.9> } normal { gradient y bump_size 4 scale 0.3 } finish { phong 0.8 } } }
box { <1.3, 0, -0.6>, <2.5, 1.2, 0.6> rotate y*-25
  texture { gradient x texture_map {
    [0.5 pigment { rgb <0.2, 0.8, 0.3> } normal { gradient z 6 scale 0.2 no_bump_scale }]
    [0.5 pigment { rgb <0.9, 0.9, 0.3> } normal { gradient y normal_map { [0 gradient x 4 scale 0.25] [1 gradient z 4 scale 0.25] } }] } scale 0.6 } }
sphere { <0, 0.35, -1.6>, 0.35 pigment { rgb 0.9 } normal { checker 1 scale 0.2 } finish { phong 1 } }
