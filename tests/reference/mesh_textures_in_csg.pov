// A mesh with per-triangle textures inside an intersection: each triangle keeps its texture,
// triangles without one take the mesh's.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -6> look_at 0 angle 50 }
light_source { <-3, 5, -8> rgb 1 }
#declare Red = texture { pigment { rgb <1, 0.1, 0.1> } finish { phong 0.6 } }
#declare Green = texture { pigment { rgb <0.1, 0.9, 0.2> } }
#declare M = mesh {
  triangle { <-2.5, -1.5, 0>, <-0.5, -1.5, 0>, <-1.5, 1.5, 0> texture { Red } }
  triangle { <-0.5, -1.5, 0>, <1.5, -1.5, 0>, <0.5, 1.5, 0> texture { Green } }
  triangle { <1.5, -1.5, 0>, <3, -1.5, 0>, <2.25, 1.5, 0> }
  texture { pigment { rgb <0.3, 0.3, 1> } }
}
intersection { object { M } box { <-2, -1, -1>, <2.5, 1, 1> } rotate y * 10 }
plane { y, -1.6 pigment { rgb 0.6 } }
