// Tests: the block patterns on tiles facing the camera: hexagon (three blocks), brick
// (mortar and brick, resized), square (four blocks), triangular (six blocks) and cubic (six
// pyramids around the origin), each on its own tile.
#version 3.7;
global_settings { assumed_gamma 1.0 }

// The tiles face the camera (-z); the x-z patterns are turned to face it too.
camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-3, 6, -20> rgb 1 }

#declare Finish = finish { ambient 0.3 diffuse 0.7 }
box { <-4, 0, 0>, <-1.4, 3, 1>
  pigment { hexagon rgb <0.9, 0.2, 0.1>, rgb <0.1, 0.7, 0.2>, rgb <0.2, 0.3, 0.9>
    scale 0.4 rotate -90 * x }
  finish { Finish }
}
box { <-1.3, 0, 0>, <1.3, 3, 1>
  pigment { brick rgb <0.6, 0.6, 0.6>, rgb <0.7, 0.2, 0.1> brick_size <1, 0.3, 0.5> mortar 0.08
    translate <0.1, 0.13, 0> }
  finish { Finish }
}
box { <1.4, 0, 0>, <4, 3, 1>
  pigment { square rgb <0.9, 0.2, 0.1>, rgb <0.1, 0.7, 0.2>, rgb <0.2, 0.3, 0.9>, rgb <0.9, 0.9, 0.2>
    scale 0.35 rotate -90 * x }
  finish { Finish }
}
box { <-4, -3, 0>, <-0.05, -0.1, 1>
  pigment { triangular rgb <0.9, 0.2, 0.1>, rgb <0.1, 0.7, 0.2>, rgb <0.2, 0.3, 0.9>,
    rgb <0.9, 0.9, 0.2>, rgb <0.9, 0.2, 0.9>, rgb <0.2, 0.9, 0.9> scale 0.6 rotate -90 * x }
  finish { Finish }
}
box { <0.05, -3, 0>, <4, -0.1, 1>
  pigment { cubic rgb <0.9, 0.2, 0.1>, rgb <0.1, 0.7, 0.2>, rgb <0.2, 0.3, 0.9>,
    rgb <0.9, 0.9, 0.2>, rgb <0.9, 0.2, 0.9>, rgb <0.2, 0.9, 0.9> translate <2, -1.5, 0.5> }
  finish { Finish }
}
