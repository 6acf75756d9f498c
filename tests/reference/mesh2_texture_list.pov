// mesh2 with a texture_list: faces with one texture index, faces with three (blended by
// corner) and faces without (the object's texture).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0.3, 0> angle 50 }
light_source { <-3, 6, -8> rgb 1 }
mesh2 {
  vertex_vectors { 9, <-2, 0, -1>, <0, 0, -1>, <2, 0, -1>, <-2, 1, 0>, <0, 1.3, 0>, <2, 1, 0>,
                   <-2, 0, 1>, <0, 0, 1>, <2, 0, 1> }
  texture_list { 3,
    texture { pigment { rgb <1, 0.2, 0.1> } finish { specular 0.5 } }
    texture { pigment { rgb <0.1, 1, 0.3> } }
    texture { pigment { gradient x color_map { [0 rgb <0, 0, 1>] [1 rgb 1] } } }
  }
  face_indices { 8,
    <0, 1, 4>, 0, <0, 4, 3>, 1, <1, 2, 5>, 0, 1, 2, <1, 5, 4>, 2, 2, 0,
    <3, 4, 7>, <3, 7, 6>, 2, <4, 5, 8>, 1, 2, 1, <4, 8, 7>
  }
  pigment { rgb 0.8 }
  rotate y * 20
}
plane { y, -0.01 pigment { rgb 0.5 } }
