// uv mapping and corner texture blending on meshes and bicubic patches inside CSG: a uv
// checker sheet with a hole cut out, a uv-mapped patch with bounded_by, and a mesh2 whose
// corners blend a texture_list, intersected with a box (and moved, so its textures move).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -5> look_at <0, 0.2, 0> angle 60 }
light_source { <-3, 6, -8> rgb 1 }
#declare Sheet = mesh2 {
  vertex_vectors { 6, <-1, 0, -1>, <0, 0.4, -1>, <1, 0, -1>, <-1, 0, 1>, <0, 0.4, 1>, <1, 0, 1> }
  uv_vectors { 6, <0, 0>, <2, 0>, <4, 0>, <0, 3>, <2, 3>, <4, 3> }
  face_indices { 4, <0, 1, 4>, <0, 4, 3>, <1, 2, 5>, <1, 5, 4> }
}
difference {
  object { Sheet }
  sphere { <0.2, 0.3, 0>, 0.45 }
  texture { uv_mapping pigment { checker rgb <1, 0.3, 0.1>, rgb <0.1, 0.2, 1> scale 0.5 } }
  translate <-2, 0, 0.3>
}
bicubic_patch { type 1 flatness 0 u_steps 3 v_steps 3
  <-1, 0, -1>, <-0.3, 0.5, -1>, <0.3, 0.5, -1>, <1, 0, -1>,
  <-1, 0, -0.3>, <-0.3, 1, -0.3>, <0.3, 1, -0.3>, <1, 0, -0.3>,
  <-1, 0, 0.3>, <-0.3, 1, 0.3>, <0.3, 1, 0.3>, <1, 0, 0.3>,
  <-1, 0, 1>, <-0.3, 0.5, 1>, <0.3, 0.5, 1>, <1, 0, 1>
  texture { uv_mapping pigment { checker rgb <1, 0.9, 0.2>, rgb <0.2, 0.6, 0.2> scale 0.125 } }
  bounded_by { box { <-1.1, -1, -1.1>, <1.1, 2, 1.1> } }
  translate <0.2, 0, 0.3>
}
intersection {
  mesh2 {
    vertex_vectors { 4, <-1, 0, -1>, <1, 0, -1>, <1, 0.5, 1>, <-1, 0.5, 1> }
    texture_list { 3,
      texture { pigment { rgb <1, 0.1, 0.1> } }
      texture { pigment { rgb <0.1, 1, 0.1> } }
      texture { pigment { rgb <0.1, 0.1, 1> } }
    }
    face_indices { 2, <0, 1, 2>, 0, 1, 2, <0, 2, 3>, 0, 2, 1 }
  }
  box { <-0.9, -1, -0.9>, <0.9, 1, 0.9> }
  rotate y * 20 translate <2.1, 0, 0.3>
}
plane { y, -0.3 pigment { rgb 0.5 } }
