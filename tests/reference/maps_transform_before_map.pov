// Tests: transformations written between a pattern and its texture_map, pigment_map or
// normal_map move the map's entries too, as those written after the map do.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at 0 right 8 * x up 6 * y }
light_source { <0, 0, -100> rgb 1 }
#declare T1 = texture { pigment { gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } } finish { ambient 1 diffuse 0 } }
#declare T2 = texture { pigment { gradient y color_map { [0 rgb <0, 1, 0>] [1 rgb 1] } } finish { ambient 1 diffuse 0 } }
#declare P1 = pigment { gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } }
#declare P2 = pigment { gradient y color_map { [0 rgb <0, 1, 0>] [1 rgb 1] } }
box { <-4, 0, 0>, <0, 3, 1> texture { gradient y scale 3 texture_map { [0.5 T1] [0.5 T2] } } }
box { <0, 0, 0>, <4, 3, 1> texture { gradient y texture_map { [0.5 T1] [0.5 T2] } scale 3 } }
box { <-4, -3, 0>, <0, 0, 1> pigment { gradient y scale 3 rotate 20 * z pigment_map { [0.5 P1] [0.5 P2] } } finish { ambient 1 diffuse 0 } }
box { <0, -3, 0>, <4, 0, 1> normal { gradient y scale 3 normal_map { [0.5 bumps 2] [0.5 gradient x 3] } } }
