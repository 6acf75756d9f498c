// mesh_identifier: `mesh { MeshIdentifier modifiers }` and `mesh2 { .. }` start from a
// declared object (as `object { .. }` does), keeping its texture unless modified
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0.6, 0> angle 55 }
light_source { <-4, 6, -5> rgb 1 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.4 } }
#declare Pyramid = mesh {
  triangle { <-0.6, 0, -0.6>, <0.6, 0, -0.6>, <0, 1.2, 0> }
  triangle { <0.6, 0, -0.6>, <0.6, 0, 0.6>, <0, 1.2, 0> }
  triangle { <-0.6, 0, 0.6>, <-0.6, 0, -0.6>, <0, 1.2, 0> }
  pigment { rgb <0.9, 0.5, 0.2> }
}
#declare Quad = mesh2 {
  vertex_vectors { 4, <-0.5, 0, 0>, <0.5, 0, 0>, <0.5, 1, 0>, <-0.5, 1, 0> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
}
mesh { Pyramid translate -1.4*x }
mesh { Pyramid rotate 30*y pigment { rgb <0.3, 0.5, 0.9> } translate 1.4*x }
mesh2 { Quad pigment { rgb <0.4, 0.9, 0.4> } rotate -20*y translate <0, 0.2, 0.5> }
mesh { Quad pigment { rgb <0.9, 0.9, 0.3> } scale 0.5 translate <-0.2, 1.5, -1> }
