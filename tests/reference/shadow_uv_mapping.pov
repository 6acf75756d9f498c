// Shadow rays see uv-mapped pigments at the hit's uv coordinates: a sphere and a mesh with a
// uv-mapped transmit checker cast checkered shadows; a layered texture whose top layer is a
// uv-mapped transmit checker shows the layer below through its clear squares.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -5> look_at <0, 0, 0> angle 55 }
light_source { <0, 8, -1> rgb 1 }
sphere { <-1.4, 1, 0>, 0.8
  pigment { uv_mapping checker rgbt <1, 0.3, 0.2, 0>, rgbt <1, 1, 1, 1> scale <0.125, 0.25, 1> }
}
mesh {
  triangle { <0.2, 1.2, -0.8>, <2.2, 1.2, -0.8>, <1.2, 1.2, 0.9> uv_vectors <0, 0>, <1, 0>, <0.5, 1> }
  pigment { uv_mapping checker rgbt <0.2, 0.4, 1, 0>, rgbt 1 scale 0.2 }
}
box { <-0.6, 0, -2>, <0.6, 0.2, -1.2>
  texture { pigment { rgb <0.1, 0.8, 0.2> } }
  texture { pigment { uv_mapping checker rgbt <1, 1, 0, 0>, rgbt 1 scale 0.05 } }
}
plane { y, 0 pigment { rgb 0.8 } }
