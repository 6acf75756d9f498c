// Texture, pigment and normal statements evaluate: maps, declared maps, layered textures,
// averages, tiles, block textures, normals with their modifiers, #default normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare CM = color_map { [0 rgb 0] [0.5 0.7 color rgb 1 color rgb <1, 0, 0>] }
#declare PM = pigment_map { [0 rgb 1] [1 checker rgb 0, rgb 1] }
#declare NM = normal_map { [0 gradient x 0.5] [1 gradient y] }
#declare TM = texture_map { [0 pigment { rgb 1 }] [1 pigment { rgb 0 } finish { phong 1 }] }
#declare SM = slope_map { [0 <0, 1>] [1 <1, 0>] }
#declare N = normal { gradient x bump_size 0.3 accuracy 0.01 no_bump_scale scale 2 }
#declare T = texture { pigment { rgb 1 } } texture { pigment { rgbt <1, 0, 0, 0.5> } }
#declare P = pigment { gradient x pigment_map { PM } scale 2 quick_color rgb 1 }
#default { normal { gradient z 0.1 } }
sphere { 0, 1 pigment { gradient y color_map { CM } } normal { N } }
sphere { 0, 1 texture { T } pigment { rgb 0.5 } }
sphere { 0, 1 texture { pigment { rgb 1 } } texture { pigment { rgbf <0, 0, 1, 0.5> } } }
sphere { 0, 1 pigment { average pigment_map { [1 rgb 1] [2 P] } } }
sphere { 0, 1 normal { average normal_map { [1 gradient x] [1 gradient z] } } }
sphere { 0, 1 normal { gradient x normal_map { NM } } }
sphere { 0, 1 normal { gradient x 2 slope_map { SM } } }
sphere { 0, 1 normal { checker normal { gradient x }, normal { gradient y } } }
sphere { 0, 1 texture { gradient x texture_map { TM } rotate z*30 } }
sphere { 0, 1 texture { checker texture { T } texture { pigment { rgb 1 } } } }
sphere { 0, 1 texture { average texture_map { [1 T] [3 pigment { rgb 1 }] } } }
plane { y, 0 texture { tiles { texture { pigment { rgb 1 } } tile2 texture { pigment { rgb 0 } } } } }
