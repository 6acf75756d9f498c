// csg_finish_modifies_texture: a `finish { }` given to a union after its texture changes that texture's finish (the reflection 0.5 of the declared texture stays; phong and diffuse are added), as it does for a single object; durer replaced the whole finish on CSG objects, so the spheres lost their reflection (wild: khayyam90 diamond.pov, `texture { Glass2 } ... finish { phong 1 }`)
#version 3.7;
global_settings { assumed_gamma 1 }
background { rgb <0.2, 0.3, 0.9> }
camera { location <0, 0, -4> look_at 0 angle 50 }
light_source { <3, 5, -5> rgb 1 }
plane { y, -1 pigment { checker rgb 1 rgb 0 } }
#declare T = texture { pigment { rgb <1, 0.3, 0.2> } finish { ambient 0.05 diffuse 0.3 reflection 0.5 } }
union { sphere { <-1.1, 0, 0>, 0.5 } texture { T } finish { phong 1 } }
difference { sphere { <0, 0, 0>, 0.5 } sphere { <0, 0, -1>, 0.3 } texture { T } finish { ambient 0.05 } }
merge { sphere { <1.1, 0, 0>, 0.5 } texture { T } finish { phong 1 } finish { diffuse 0.9 } }
