// Tests: the pavement pattern of triangles on four tiles facing the camera: the default
// (single triangles), a hexiamond with cut 60° corners and rounded 120° corners (exterior 1,
// form 2), a pentiamond with rounded 60° corners, cut 120° corners and Manhattan-like
// concave corners (exterior 2, form 1, interior 1), and a hexiamond with rounded concave
// corners (interior 2).
#version 3.7;
global_settings { assumed_gamma 1.0 }

// The tiles face the camera (-z); the x-z pattern is turned to face it too.
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-3, 6, -20> rgb 1 }

#declare Finish = finish { ambient 0.3 diffuse 0.7 }
#declare Map = color_map { [0 rgb <0.1, 0.2, 0.6>] [0.5 rgb <0.9, 0.8, 0.3>] [1 rgb 0.05] }
box { <-4, 0, 0>, <-0.05, 3, 1>
  pigment { pavement color_map { Map } scale 0.6 rotate -90 * x }
  finish { Finish }
}
box { <0.05, 0, 0>, <4, 3, 1>
  pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 5 exterior 1 form 2
    color_map { Map } scale 0.4 rotate -90 * x }
  finish { Finish }
}
box { <-4, -3, 0>, <-0.05, -0.1, 1>
  pigment { pavement number_of_sides 3 number_of_tiles 5 pattern 2 exterior 2 form 1
    interior 1 color_map { Map } scale 0.4 rotate -90 * x }
  finish { Finish }
}
box { <0.05, -3, 0>, <4, -0.1, 1>
  pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 11 interior 2
    color_map { Map } scale 0.4 rotate -90 * x translate <0.1, 0.1, 0> }
  finish { Finish }
}
