// Tests: pigment_map (with checker and gradient entries, transformed with the map), colour map
// range entries `[a b colour colour]`, a declared colour map and pigment map, average with
// weights, block pigments given as pigments.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3.2, -6> look_at <0, 0.6, 0> angle 60 }
light_source { <4, 9, -6> rgb 1 }
background { rgb <0.15, 0.15, 0.2> }

#declare Warm = color_map { [0 0.5 color rgb <1, 0.3, 0> color rgb <1, 0.9, 0.2>] [0.5 1 color rgb <0.2, 0.4, 1> color rgb <0.9, 0.9, 1>] }
#declare Stripes = pigment_map {
  [0 checker rgb <0.9, 0.1, 0.1> rgb <0.95, 0.95, 0.9> scale 0.25]
  [0.5 rgb <0.1, 0.6, 0.2>]
  [1 gradient z color_map { Warm } scale 0.5]
}

plane { y, 0 pigment { gradient x pigment_map { Stripes } scale 3 } }
box { <-2.6, 0, -0.6>, <-1.4, 1.2, 0.6> pigment { gradient y color_map { Warm } scale 1.2 } }
sphere { <0, 0.8, 0>, 0.8
  pigment { average pigment_map { [1 rgb <1, 0, 0>] [3 gradient y color_map { [0 rgb 0] [1 rgb <0, 0.8, 1>] } scale 0.5] } }
}
box { <1.4, 0, -0.6>, <2.6, 1.2, 0.6>
  pigment { checker pigment { gradient x color_map { [0 rgb 1] [1 rgb <1, 0, 1>] } scale 0.5 } pigment { rgb <0.2, 0.2, 0.3> } scale 0.6 }
  rotate y*20
}
