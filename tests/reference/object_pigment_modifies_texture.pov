// Tests: a `pigment` given to an object that has a texture modifies that texture's pigment:
// `pigment { scale 0.5 }` and `pigment { turbulence 0.4 }` keep the pattern and its map, and
// a new pattern keeps the old one's transformations (the object's scale applies to it).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> }
light_source { <-4, 8, -6>, rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
#declare Striped = box { <-0.6, 0, -0.6>, <0.6, 1.6, 0.6>
  pigment { gradient x color_map { [0 rgb <1, 0.2, 0.1>] [0.5 rgb <1, 0.9, 0.2>] [1 rgb <0.1, 0.3, 1>] } } }
object { Striped translate -2.4 * x pigment { scale 0.5 } }
object { Striped pigment { turbulence 0.4 } }
object { Striped scale <1.5, 1, 1> translate 2.4 * x pigment { gradient y scale 0.45 } }
sphere { <0, 0.5, -1.8>, 0.5 pigment { rgb <0.3, 0.8, 0.3> } }
