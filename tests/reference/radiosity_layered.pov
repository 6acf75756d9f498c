// radiosity_layered: radiosity gathered once per hit, not once per texture layer: the floor
// has three layers (the upper two partly clear), the sphere an averaged texture; each layer
// scales the same indirect light by its own pigment and diffuse
#version 3.7;
global_settings { radiosity { count 40 error_bound 0.6 recursion_limit 1 } }
camera { location <0, 1.5, -4> look_at <0, 0.6, 0> angle 55 }
light_source { <1, 2.5, -2> rgb 1 }
box { <-3, 0, -5>, <3, 3, 3> inverse pigment { rgb <0.9, 0.8, 0.7> } }
plane { y, 0.001
  texture { pigment { rgb <0.8, 0.8, 0.8> } finish { ambient 0 diffuse 0.7 } }
  texture { pigment { checker rgbt <0.9, 0.2, 0.1, 0.4> rgbt 1 scale 0.5 } finish { ambient 0 diffuse 0.5 } }
  texture { pigment { gradient x color_map { [0 rgbt <0.1, 0.3, 0.9, 0.5>] [1 rgbt 1] } } finish { ambient 0 diffuse 0.9 } }
}
sphere { <0, 0.7, 0>, 0.7
  texture { average texture_map {
    [1 pigment { rgb <1, 0.5, 0.2> } finish { ambient 0 diffuse 0.8 }]
    [1 pigment { rgb <0.2, 0.6, 1> } finish { ambient 0 diffuse 0.4 }]
  } }
}
