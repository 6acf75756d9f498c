// Tests: the pavement pattern of squares on four tiles facing the camera: an L tromino
// turning cut straight (form 1), a pentomino with rounded ends and cut concave corners
// (exterior 2, interior 1), a hexomino with rounded turns, cut ends and rounded concave
// corners (form 2, exterior 1, interior 2), and a T tetromino with form 3 (turns follow
// exterior and interior).
#version 3.7;
global_settings { assumed_gamma 1.0 }

// The tiles face the camera (-z); the x-z pattern is turned to face it too.
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-3, 6, -20> rgb 1 }

#declare Finish = finish { ambient 0.3 diffuse 0.7 }
#declare Map = color_map { [0 rgb <0.1, 0.2, 0.6>] [0.5 rgb <0.9, 0.8, 0.3>] [1 rgb 0.05] }
box { <-4, 0, 0>, <-0.05, 3, 1>
  pigment { pavement number_of_sides 4 number_of_tiles 3 pattern 2 form 1
    color_map { Map } scale 0.4 rotate -90 * x }
  finish { Finish }
}
box { <0.05, 0, 0>, <4, 3, 1>
  pigment { pavement number_of_sides 4 number_of_tiles 5 pattern 7 exterior 2 interior 1
    color_map { Map } scale 0.3 rotate -90 * x }
  finish { Finish }
}
box { <-4, -3, 0>, <-0.05, -0.1, 1>
  pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 34 form 2 exterior 1
    interior 2 color_map { Map } scale 0.3 rotate -90 * x }
  finish { Finish }
}
box { <0.05, -3, 0>, <4, -0.1, 1>
  pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 3 form 3 exterior 2
    interior 1 color_map { Map } scale 0.35 rotate -90 * x translate <0.1, 0.1, 0> }
  finish { Finish }
}
