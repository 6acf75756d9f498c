// blob component textures: patterns moved by the component's and the blob's transformations, a cylinder and a negative component with their own, one component showing the blob's texture.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.3, 0> angle 50 }
light_source { <-4, 8, -6> rgb 1 }
plane { y, -1.2 pigment { rgb 0.8 } }
blob { threshold 0.4
  // given before the translate: the checker moves with the component
  sphere { <0, 0, 0>, 1.1, 1 texture { pigment { checker rgb <1, 0, 0> rgb 1 scale 0.25 } } translate <-1.2, 0, 0> }
  // translate before the texture: the checker stays where it was written
  sphere { <0, 0, 0>, 1.1, 1 translate <1.2, 0, 0> texture { pigment { checker rgb <0, 0, 1> rgb 1 scale 0.25 } finish { phong 0.8 } } }
  cylinder { <-1, 0, 0>, <1, 0, 0>, 0.7, 1.2 pigment { gradient x color_map { [0 rgb <0, 1, 0>] [1 rgb <1, 1, 0>] } } rotate y*30 translate <0, 1.1, 0.3> }
  sphere { <0, 0.6, -0.8>, 0.6, -0.5 texture { pigment { rgb <1, 0, 1> } } }
  sphere { <0, -0.5, 0>, 0.9, 1 }
  texture { pigment { rgb <1, 0.6, 0.2> } finish { specular 0.5 } }
  rotate y*-20 scale 1.1 translate <0, 0, 0.3>
}
