// interior_texture on its own is not a value
sphere { 0, 1 }
#declare Inside = interior_texture { pigment { rgb 1 } }
