// uv-mapped normals on meshes: the pattern follows the triangles' uv_vectors (interpolated),
// through `mesh2` and `mesh`; triangles without uv_vectors sit at uv <0, 0>.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -5> look_at <0, 0, 0> angle 55 }
light_source { <-3, 6, -8> rgb 1 }
#declare Sheet = mesh2 {
  vertex_vectors { 6, <-1, 0, -1>, <0, 0.4, -1>, <1, 0, -1>, <-1, 0, 1>, <0, 0.4, 1>, <1, 0, 1> }
  uv_vectors { 6, <0, 0>, <2, 0>, <4, 0>, <0, 3>, <2, 3>, <4, 3> }
  face_indices { 4, <0, 1, 4>, <0, 4, 3>, <1, 2, 5>, <1, 5, 4> }
}
object { Sheet
  texture {
    uv_mapping
    pigment { rgb <1, 0.6, 0.3> }
    normal { bumps 1 scale 0.1 }
  }
  scale 1.2 translate <-1.2, 0, 0>
}
object { Sheet
  pigment { rgb <0.4, 0.8, 1> }
  normal { uv_mapping checker 1 scale 0.5 }
  rotate y * 30 translate <1.3, 0, 0.3>
}
mesh {
  triangle { <-2, -0.5, 1.5>, <2, -0.5, 1.5>, <0, 1.5, 2> uv_vectors <0, 0>, <3, 0>, <1.5, 2> }
  triangle { <-2, -0.5, 1.5>, <0, 1.5, 2>, <-2.5, 1.5, 2.5> }
  pigment { rgb 0.9 }
  normal { uv_mapping gradient y 1 scale 0.3 }
}
plane { y, -0.5 pigment { rgb 0.5 } }
