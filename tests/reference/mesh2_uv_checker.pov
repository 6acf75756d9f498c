// mesh2 with uv_vectors and uv_indices under a uv-mapped checker and gradient; the mesh is
// moved and scaled after the texture, which does not move the pattern (as in POV-Ray).
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
  texture { uv_mapping pigment { checker rgb <1, 0.3, 0.1>, rgb <0.1, 0.2, 1> scale 0.5 } }
  scale 1.2 translate <-1.2, 0, 0>
}
object { Sheet
  pigment { uv_mapping gradient x color_map { [0 rgb 0] [1 rgb <0.2, 1, 0.4>] } }
  rotate y * 30 translate <1.3, 0, 0.3>
}
mesh {
  triangle { <-2, -0.5, 1.5>, <2, -0.5, 1.5>, <0, 1.5, 2> uv_vectors <0, 0>, <3, 0>, <1.5, 2> }
  triangle { <-2, -0.5, 1.5>, <0, 1.5, 2>, <-2.5, 1.5, 2.5> }
  pigment { uv_mapping checker rgb 1, rgb 0 scale 0.25 }
}
plane { y, -0.5 pigment { rgb 0.5 } }
