// mesh (declared once, used twice with different transforms) and mesh2 with normals.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.6, 0> angle 50 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
#declare Pyramid = mesh {
  triangle { <-1,0,-1>, <1,0,-1>, <0,1.5,0> }
  triangle { <1,0,-1>, <1,0,1>, <0,1.5,0> }
  triangle { <1,0,1>, <-1,0,1>, <0,1.5,0> }
  triangle { <-1,0,1>, <-1,0,-1>, <0,1.5,0> }
}
object { Pyramid pigment { rgb <0.9, 0.4, 0.2> } translate <-1.5, 0, 0> }
object { Pyramid pigment { rgb <0.3, 0.8, 0.3> } scale <0.6, 1.2, 0.6> rotate y*30 translate <0.2, 0, 1.2> }
mesh2 {
  vertex_vectors { 5, <-1,0,-1>, <1,0,-1>, <1,0,1>, <-1,0,1>, <0,1.2,0> }
  normal_vectors { 5, <-1,0.5,-1>, <1,0.5,-1>, <1,0.5,1>, <-1,0.5,1>, <0,1,0> }
  face_indices { 4, <0,1,4>, <1,2,4>, <2,3,4>, <3,0,4> }
  pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.5 }
  translate <1.6, 0, -0.5>
}
