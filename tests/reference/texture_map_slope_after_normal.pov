// texture_map_slope_after_normal: a texture map visits the upper entry first; a `slope` map
// evaluated after a bumpy plain texture at the same hit sees that texture's perturbed
// normal (left: T then V, bumpy boundary), not before it (right: V then T, smooth)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -30> look_at <0, 1, 0> angle 50 }
light_source { <200, 200, -200> rgb 1.2 }
background { rgb <0.5, 0.6, 0.8> }
#declare V = texture { pigment { rgb <0.2, 0.5, 0.1> } normal { bumps 2 scale 0.5 } }
#declare S = texture { pigment { rgb <0.8, 0.5, 0.3> } }
#declare T = texture { slope { -y*3, 0, 0.5 } texture_map { [0.45 V] [0.55 S] } }
sphere { <-6, 1, 0>, 5.5 texture { gradient y scale 30 texture_map { [0 T] [1 V] } } }
sphere { <6, 1, 0>, 5.5 texture { gradient y scale 30 texture_map { [0 V] [1 T] } } }
