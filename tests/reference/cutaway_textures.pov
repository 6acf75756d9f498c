// cutaway_textures: the surfaces an untextured child cuts show the texture of the object they lie in (difference and intersection), a textured cutter keeps its own, and without the keyword the cut shows the default (black) texture
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5.5> look_at <0, 0.2, 0> angle 55 }
light_source { <4, 9, -7> rgb 1 }
plane { y, -1 pigment { checker rgb <0.8, 0.8, 0.7> rgb <0.3, 0.35, 0.45> } }
// Without the keyword: the cut is black.
difference {
  sphere { <-2.2, 0, 0>, 1 pigment { rgb <1, 0.25, 0.2> } }
  box { <-2.2, 0, -2>, <-1, 2, 0> }
}
// With it: the cut takes the sphere's pattern, evaluated inside; the textured cylinder keeps its green.
difference {
  sphere { 0, 1 pigment { gradient y color_map { [0 rgb <1, 0.8, 0.1>] [1 rgb <0.9, 0.1, 0.4>] } scale 0.5 } }
  box { <0, 0, -2>, <2, 2, 0> rotate y * 20 }
  cylinder { <-2, -0.3, -0.3>, <0, -0.3, -0.3>, 0.25 pigment { rgb <0.1, 0.8, 0.2> } }
  cutaway_textures
  translate y * 0.1
}
// An intersection: the box's faces inside the placed sphere show its gradient.
intersection {
  box { <-0.8, -1, -0.8>, <0.8, 0.4, 0.8> rotate y * 30 }
  sphere { 0, 1 pigment { gradient x color_map { [0 rgb <0.1, 0.3, 1>] [1 rgb <0.2, 1, 1>] } scale 0.6 } scale <1.1, 1, 1> }
  cutaway_textures
  translate x * 2.3
}
