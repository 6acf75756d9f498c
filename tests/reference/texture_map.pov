// Tests: texture_map (blending whole shaded textures, with finishes), block textures of a
// checker pattern, tiles with a layered tile, average of textures with weights, and the
// transform of a texture_map applying to its entries.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -6> look_at <0, 0.7, 0> angle 60 }
light_source { <4, 9, -6> rgb 1 }
background { rgb <0.15, 0.15, 0.2> }

#declare Shiny = texture { pigment { rgb <0.9, 0.8, 0.2> } finish { phong 0.9 phong_size 30 } }
#declare Dull = texture { pigment { checker rgb <0.1, 0.2, 0.7> rgb <0.6, 0.7, 0.9> scale 0.2 } finish { ambient 0.3 diffuse 0.5 } }

plane { y, 0 texture { tiles { texture { pigment { rgb 0.8 } } tile2 texture { pigment { rgb <0.5, 0.3, 0.2> } } texture { pigment { gradient x color_map { [0 rgbt 1] [1 rgbt <0, 0, 0, 0.3>] } scale 0.5 } } } } }
sphere { <-1.7, 0.9, 0>, 0.9 texture { gradient y texture_map { [0.3 Shiny] [0.7 Dull] } scale 1.8 translate y*0 } }
sphere { <0, 0.9, 0>, 0.9 texture { checker texture { Shiny } texture { pigment { rgb <0.8, 0.1, 0.1> } finish { diffuse 0.9 } } scale 0.5 } }
sphere { <1.7, 0.9, 0>, 0.9 texture { average texture_map { [1 Shiny] [2 Dull] } } }
