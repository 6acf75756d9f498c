// Tests: fractal patterns on tiles facing the camera: mandel (default colouring, exponent
// 3, interior and exterior types), julia, and magnet 1 and 2 (mandel and julia forms).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-3, 6, -20> rgb 1 }

#declare Map = color_map { [0 rgb <0.1, 0.1, 0.4>] [0.3 rgb <0.9, 0.5, 0.1>] [1 rgb <1, 1, 0.8>] }
#macro Tile(Column, Row, Pattern)
  box { <-4 + Column * 2.7, 1 - Row * 2, 0>, <-1.4 + Column * 2.7, 2.9 - Row * 2, 1>
    pigment { Pattern translate <-2.7 + Column * 2.7, 2 - Row * 2, 0> }
    finish { ambient 0.3 diffuse 0.7 }
  }
#end
Tile(0, 0, pigment { mandel 30 color_map { Map } translate <0.5, 0, 0> scale 0.8 })
Tile(1, 0, pigment { mandel 30 exponent 3 color_map { Map } scale 0.8 })
Tile(2, 0, pigment { mandel 25 interior 1, 1 exterior 6, 0.3 color_map { Map }
  translate <0.5, 0, 0> scale 0.8 })
Tile(0, 1, pigment { julia <-0.75, 0.12>, 40 color_map { Map } scale 0.7 })
Tile(1, 1, pigment { julia <0.35, 0.4>, 30 exponent 4 interior 2, 1 exterior 7, 5
  color_map { Map } scale 0.8 })
Tile(2, 1, pigment { mandel 20 exterior 8, 4 color_map { Map } translate <0.5, 0, 0> scale 0.8 })
Tile(0, 2, pigment { magnet 1 mandel 30 color_map { Map } translate <-1.2, 0, 0> scale 0.35 })
Tile(1, 2, pigment { magnet 2 mandel 30 color_map { Map } translate <-1, 0, 0> scale 0.4 })
Tile(2, 2, pigment { magnet 1 julia <1.2, 0.3>, 30 color_map { Map } scale 0.6 })
