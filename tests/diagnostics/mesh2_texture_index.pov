// error: 7:21 texture index out of range
// error-text: the texture_list has 1 textures

mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  texture_list { 1, texture { pigment { rgb 1 } } }
  face_indices { 1, <0,1,2>, 3 }
}
