// Tests: a pigment or finish written in a texture modifies the texture's own (a layered
// texture's top layer): `pigment { turbulence .. scale .. }` keeps the pattern and map, a
// new pattern in a named pigment keeps its colour map and transformations, and a finish
// reaches only the top layer.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.4, 0> angle 50 }
light_source { <-4, 8, -6> rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
#declare Stripes = texture { pigment { gradient x color_map { [0 rgb <0.9, 0.2, 0.1>]
  [0.5 rgb <1, 0.9, 0.3>] [1 rgb <0.1, 0.3, 0.8>] } scale 0.5 } }
#declare Layers = texture { pigment { checker rgb <0.1, 0.6, 0.2>, rgb 0.9 scale 0.4 } }
  texture { pigment { bozo color_map { [0 rgbt <1, 1, 1, 1>] [1 rgbt <0.8, 0.1, 0.1, 0.2>] }
    scale 0.3 } }
#declare Named = pigment { granite color_map { [0 rgb <0.2, 0.2, 0.9>] [1 rgb <1, 0.8, 0.2>] }
  scale <0.6, 1, 1> }
box { <-3, 0, -0.8>, <-1.2, 1.2, 0.8>
  texture { Stripes pigment { turbulence 0.6 scale 1.5 } finish { phong 0.8 } } }
box { <-0.9, 0, -0.8>, <0.9, 1.2, 0.8>
  texture { Layers pigment { turbulence 0.8 } finish { ambient 0.4 } } }
box { <1.2, 0, -0.8>, <3, 1.2, 0.8> pigment { Named gradient x } }
