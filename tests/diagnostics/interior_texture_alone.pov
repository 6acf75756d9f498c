// error: 6:19 `interior_texture` belongs in an object or a `material`
// error-text: not a value of its own

// interior_texture on its own is not a value
sphere { 0, 1 }
#declare Inside = interior_texture { pigment { rgb 1 } }
