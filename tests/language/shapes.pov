// Syntax of polygon, smooth_triangle, mesh, mesh2, poly, cubic and quartic.
#declare P = polygon { 5, <0,0>, <1,0>, <1,1>, <0,1>, <0,0> }
#declare P3 = polygon { 4, <0,0,1>, <1,0,1>, <1,1,1>, <0,0,1> pigment { rgb 1 } }
#declare S = smooth_triangle { <0,0,0>, <0,0,-1>, <1,0,0>, <0,0,-1>, <0,1,0>, <0,0,-1> }
#declare M = mesh {
  triangle { <0,0,0>, <1,0,0>, <0,1,0> }
  smooth_triangle { <0,0,0>, z, <1,0,0>, z, <0,1,0>, z }
  triangle { <0,0,0>, <1,0,0>, <0,0,1> uv_vectors <0,0>, <1,0>, <0,1> }
  inside_vector y
  pigment { rgb <1, 0, 0> }
  translate x
}
#declare M2 = mesh2 {
  vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }
  normal_vectors { 2, -z, <0,0.1,-1> }
  uv_vectors { 2, <0,0>, <1,1> }
  face_indices { 2, <0,1,2>, <0,2,3> }
  normal_indices { 2, <0,0,1>, <0,1,1> }
  uv_indices { 2, <0,1,1>, <0,1,0> }
  scale 2
}
#declare M3 = mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <1,1,0> }
  face_indices { 1, <0,1,2> }
}
#declare Q = quartic {
  < 1, 0, 0, 0, 2, 0, 0, 2, 0, -5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 4, 0, 0, 0, 0, 1, 0, -5, 0, 4 >
  sturm
}
#declare C = cubic { < 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, -0.3 > }
#declare Po = poly { 2, < 1, 0, 0, 0, 1, 0, 0, 1, 0, -1 > sturm off }
union { object { P } object { S } object { M } object { M2 } object { M3 } object { Q } object { C } object { Po } object { P3 } }
// POV-Ray's fonts are not redistributed with durer: this part runs when they are installed.
#if (file_exists("timrom.ttf") & file_exists("cyrvetic.ttf"))
  #declare T1 = text { ttf "timrom.ttf" "Hello, World!" 0.2, 0 }
  #declare T2 = text { ttf "cyrvetic.ttf" concat("a", "b") 1, <0.1, 0.2> inverse }
  #declare T3 = text { ttf "timrom.ttf" "" 1, 0 }
  union { object { T1 } object { T2 } object { T3 } }
#end
#declare Pr1 = prism { 0, 1, 4, <0,0>, <1,0>, <1,1>, <0,0> open }
#declare Pr2 = prism { linear_sweep bezier_spline -1, 1, 4, <0,0>, <1,0>, <1,1>, <0,0> sturm }
#declare Pr3 = prism { conic_sweep linear_spline 0, 1, 3, <0,0>, <1,0>, <1,1> }
#declare Pr4 = prism { cubic_spline 0, 1, 7, <0,-1>, <0,0>, <1,0>, <1,1>, <0,1>, <0,0>, <-1, 0> pigment { rgb 1 } }
union { object { Pr1 } object { Pr2 } object { Pr3 } object { Pr4 } }
#declare Clipped = sphere { 0, 1 clipped_by { box { -1, 0.5 } plane { x, 0.2 } } bounded_by { sphere { 0, 1.1 } } no_image no_reflection double_illuminate }
#declare Bounded = sphere { 0, 1 bounded_by { box { -1, 1 } } clipped_by { bounded_by } translate x }
#declare Reversed = sphere { 0, 1 clipped_by { box { -1, 0.5 } } bounded_by { clipped_by } no_image off }
union { object { Clipped } object { Bounded } object { Reversed } clipped_by { sphere { 0, 3 } } }
#declare L1 = lathe { 3, <0,0>, <1,0>, <0,1> sturm }
#declare L2 = lathe { bezier_spline 4, <0,0>, <1,0>, <1,1>, <0,1> pigment { rgb 1 } }
#declare L3 = lathe { cubic_spline 4, <0,0>, <1,0>, <1,1>, <0,1> }
union { object { L1 } object { L2 } object { L3 } }
#declare B1 = blob { threshold 0.5 sphere { 0, 1, 1 pigment { rgb 1 } translate x } cylinder { 0, x, 0.5, strength -1 } component 1, 1, <0, 1, 0> sturm hierarchy off }
#declare B2 = blob { sphere { 0, 0, 1 } pigment { rgb 1 } threshold 0.2 }
union { object { B1 } object { B2 } }
// Blob components with their own texture, pigment, normal and finish, layered textures and
// transformations before and after them; inside() as POV-Ray 3.7 reports it.
#declare BT = texture { pigment { rgb <1,0,0> } }
#declare BTr = transform { rotate y*30 }
#declare B3 = blob { threshold 0.5
  sphere { 0, 1, 1 texture { BT } translate x }
  sphere { 0, 1, strength 1 texture { BT } texture { pigment { rgbt <0,0,1,0.5> } } transform { BTr } }
  cylinder { 0, y, 0.5, 1 pigment { rgb 1 } normal { bumps 0.3 } finish { phong 1 } transform { BTr } scale 2 }
  sphere { x, 1, 1 finish { ambient 0.5 } }
}
#if (!inside(B3, <1, 0, 0>) | !inside(B3, 0) | inside(B3, <0, -1.5, 0>) | inside(B3, <2.5, 0, 0>))
  #error "blob component positions"
#end
object { B3 }
#declare Se = superellipsoid { <0.5, 1> pigment { rgb 1 } }
#declare Se2 = superellipsoid { <0, -1> }
union { object { Se } object { Se2 } }
#declare So = sor { 4, <1, -1>, <1, 0>, <1, 1>, <1, 2> open sturm }
#declare So2 = sor { 4, <0, 0>, <0, 0>, <0, 1>, <0, 1> }
union { object { So } object { So2 } }
