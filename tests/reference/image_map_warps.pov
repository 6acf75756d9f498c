// Tests: turbulence and warps written in an image_map pigment (classic turbulence acts
// innermost whatever the order; a warp acts where it is written), and a declared image map
// pigment given turbulence when used.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-3, 6, -20> rgb 1 }

#declare Image = pigment { image_map { png "images/colours16.png" } translate -0.5 scale 2.6 }
#macro Tile(Column, Row, Pigment)
  box { <-4 + Column * 2.7, -3 + Row * 3, 0>, <-1.4 + Column * 2.7, -0.05 + Row * 3, 1>
    pigment { Pigment translate <-2.65 + Column * 2.7, -1.5 + Row * 3, 0> }
    finish { ambient 0.4 diffuse 0.6 }
  }
#end
Tile(0, 1, pigment { Image turbulence 0.4 * x octaves 2 rotate 90 * z })
Tile(1, 1, pigment { Image rotate 90 * z turbulence 0.4 * x octaves 2 })
Tile(2, 1, pigment { Image rotate 90 * z warp { turbulence 0.4 * x octaves 2 } })
Tile(0, 0, pigment { Image warp { turbulence 0.4 * x octaves 2 } rotate 90 * z })
Tile(1, 0, pigment { image_map { png "images/colours16.png" interpolate 2 } translate -0.5 scale 2.6 warp { repeat x * 0.9 flip x } })
Tile(2, 0, pigment { Image warp { black_hole <0, 0, 0>, 1.2 strength 2 } turbulence 0.2 })
