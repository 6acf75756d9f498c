// warning: 6:33 a `projected_through` object cannot have a texture; it is removed

// povray: "Projected through objects can not have texture, texture removed."
#declare Shade = sphere { 0, 0.3 pigment { rgb <1, 0, 0> } }
#declare Bare = sphere { 0, 0.3 }
light_source { <0, 2, 0>, rgb 1 projected_through { Shade scale 2 } }
light_source { <0, 2, 0>, rgb 1 projected_through { Bare translate y } }
