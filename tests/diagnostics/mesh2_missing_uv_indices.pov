// error: 4:1 missing `uv_indices` in mesh2
// error-text: 2 uv vectors for 3 vertices

mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  uv_vectors { 2, <0,0>, <1,1> }
  face_indices { 1, <0,1,2> }
}
