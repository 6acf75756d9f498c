// #default texture placement: an object without a texture shows the default fixed in the world, not moved by its transformations; one made by a pigment, normal or finish on the object is moved only by the transformations written after it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -9> look_at <0, 0.8, 0> angle 50 }
light_source { <-4, 9, -7> rgb 1 }
#default { texture { pigment { gradient y triangle_wave color_map { [0 rgb <0.1, 0.2, 0.6>] [1 rgb <1, 0.9, 0.6>] } scale 0.6 rotate z*20 } finish { ambient 0.2 diffuse 0.7 } } }
#declare Post = union { cylinder { 0, 1.6*y, 0.45 } sphere { 1.6*y, 0.6 } }
plane { y, 0 pigment { rgb 0.8 } }
object { Post translate <-3, 0, 0> }
object { Post scale 1.3 rotate y*40 translate <-1.5, 0, 0.5> }
box { -0.5, 0.5 scale <0.8, 2, 0.8> translate <0, 1, 0> finish { phong 0.5 } }
box { -0.5, 0.5 scale <0.8, 2, 0.8> finish { phong 0.5 } translate <1.5, 1, 0> }
sphere { 0, 0.8 scale <1, 1.5, 1> normal { bumps 0.3 scale 0.2 } translate <3, 1.2, 0> }
