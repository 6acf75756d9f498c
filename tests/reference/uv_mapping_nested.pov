// uv-mapped pigments nested in other pigments (average, block patterns, pigment maps) are
// looked up at the surface's uv coordinates too, and no transformation applied after the
// block that says `uv_mapping` reaches them: not the enclosing pigment's, the texture's, nor
// one written after a uv-mapped pigment's name. On a shape without uv coordinates (the cone)
// the uv are the world point's x and y. Uv-mapped normals follow the same rules.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -7> look_at <0, 0.3, 0> angle 45 }
light_source { <-4, 8, -6> rgb 1 }
#declare G = pigment { uv_mapping gradient x color_map { [0 rgb <1, 0.2, 0>] [1 rgb <0, 0.3, 1>] } }
#declare C = pigment { uv_mapping checker rgb 1, rgb 0 scale 0.1 }
sphere { 0, 1 pigment { average pigment_map { [1 G] [1 C] } scale 0.5 }
  rotate 30 * y translate <-2.2, 0.3, 0> }
box { -0.8, 0.8 pigment { checker pigment { G }, pigment { C } scale 0.4 }
  rotate <20, 30, 0> translate <0, 0.3, 0> }
torus { 0.8, 0.35 pigment { uv_mapping gradient y pigment_map { [0 C] [1 G rotate 45 * z] } }
  rotate -50 * x scale 1.2 translate <2.2, 0.3, 0> }
sor { 5, <0.5, -1.5>, <0.6, -1>, <1.0, -0.8>, <0.7, 0.6>, <0.4, 1.2>
  texture { pigment { bozo pigment_map { [0.3 G] [0.7 C translate 0.5 * x] } scale 0.3 } scale 2 }
  scale 0.8 translate <-1, 0, -2> }
cone { -y, 0.8, y, 0.3 pigment { average pigment_map { [1 G] [1 C] } } translate <1.2, 0, -2> }
#declare N = normal { uv_mapping bumps 1 scale 0.1 }
sphere { 0, 0.5 pigment { rgb 1 } normal { average normal_map { [1 N] } scale 0.5 }
  translate <-0.5, 1.7, 1> }
sphere { 0, 0.5 texture { pigment { rgb 1 } normal { N scale 0.5 } } scale 1.2
  translate <1.2, 1.9, 1.5> }
plane { y, -1.2 pigment { rgb 0.5 } }
