// Per-triangle textures in a mesh: `texture { T }` on triangles and smooth triangles,
// `texture_list { A B C }` blending three textures by corner, and triangles without a
// texture taking the mesh object's.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -6> look_at 0 angle 50 }
light_source { <-3, 5, -8> rgb 1 }
#declare Red = texture { pigment { rgb <1, 0.1, 0.1> } finish { phong 0.6 } }
#declare Green = texture { pigment { rgb <0.1, 0.9, 0.2> } }
#declare Blue = texture { pigment { rgb <0.2, 0.3, 1> } finish { ambient 0.3 } }
mesh {
  triangle { <-2.5, -1.5, 0>, <-0.5, -1.5, 0>, <-1.5, 1.5, 0> texture { Red } }
  smooth_triangle { <-0.5, -1.5, 0>, <-0.3, 0, -1>, <1.5, -1.5, 0>, <0.3, 0, -1>,
                    <0.5, 1.5, 0>, <0, 0.3, -1> texture { Green } }
  triangle { <1.5, -1.5, 0>, <3, -1.5, 0>, <2.25, 1.5, 0> texture_list { Red Green Blue } }
  triangle { <-1.5, 1.5, 0>, <0.5, 1.5, 0>, <-0.5, 2.5, 0> }
  texture { pigment { checker rgb 1, rgb 0.2 scale 0.25 } }
  rotate y * 10
}
plane { y, -1.6 pigment { rgb 0.6 } }
