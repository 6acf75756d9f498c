// interior_texture: the texture of inside faces (rays leaving the object, backs of patches):
// a cut-open sphere (given in a material), a union passing it to children with their own
// texture, two layered interior textures, backs of a disc, a triangle, a mesh triangle and
// a polygon, and a shadow coloured by the inside face it crosses
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { rgb <0.2, 0.3, 0.4> }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <-4, 8, -6> rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.8, 0.2> rgb <0.2, 0.5, 0.9> } }
#declare Outside = texture { pigment { rgb <0.9, 0.2, 0.1> } }
#declare Inside = texture { pigment { rgb <0.1, 0.8, 0.2> } }
sphere { <-1.9, 1.2, 0.5>, 0.7
  material { texture { Outside } interior_texture { Inside normal { bumps 0.5 scale 0.1 } } }
  clipped_by { plane { -z, 0 translate 0.3*z } }
}
union {
  sphere { <-0.4, 1.2, 0.5>, 0.5 pigment { rgb <0.9, 0.9, 0.2> } }
  sphere { <0.7, 1.2, 0.5>, 0.5 }
  pigment { rgb <0.6, 0.2, 0.8> }
  interior_texture { pigment { rgb <0.1, 0.7, 0.9> } }
  interior_texture { pigment { checker rgbt <1, 1, 1, 0> rgbt 1 scale 0.2 } }
  clipped_by { plane { -z, -0.3 } }
}
sphere { <1.9, 1.3, 0.5>, 0.5
  pigment { rgbf <1, 1, 1, 1> }
  interior_texture { pigment { rgbf <1, 0.1, 0.1, 0.9> } }
}
disc { <-2.2, 0.4, -1.2>, <0, 0.3, 1>, 0.4 texture { Outside } interior_texture { Inside } }
triangle { <-1.5, 0.1, -1.2>, <-0.7, 0.1, -1.2>, <-1.1, 0.9, -1.2>
  texture { Outside } interior_texture { Inside } }
triangle { <-0.6, 0.1, -1.2>, <-0.2, 0.9, -1.2>, <0.2, 0.1, -1.2>
  texture { Outside } interior_texture { Inside } }
mesh { triangle { <0.3, 0.1, -1.2>, <1.1, 0.1, -1.2>, <0.7, 0.9, -1.2> }
  texture { Outside } interior_texture { Inside } }
polygon { 4, <1.2, 0.1, -1.2>, <2, 0.1, -1.2>, <2, 0.8, -1.2>, <1.2, 0.8, -1.2>
  texture { Outside } interior_texture { Inside } }
