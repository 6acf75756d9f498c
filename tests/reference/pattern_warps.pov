// Tests: warps on tiles facing the camera: repeat with offset and flip, black holes
// (repeated with the centre moved into its cell; inverse with strength and falloff),
// cylindrical and spherical mappings of a checker (one with an orientation), toroidal with
// dist_exp, planar with an oblique normal, and a warp written before or after a translation
// (order matters).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-3, 6, -20> rgb 1 }

#declare Map = color_map { [0 rgb <0.1, 0.1, 0.4>] [0.6 rgb <0.9, 0.5, 0.1>] [1 rgb <1, 1, 0.8>] }
#macro Tile(Column, Row, Pattern)
  box { <-4 + Column * 2.7, 1 - Row * 2, 0>, <-1.4 + Column * 2.7, 2.9 - Row * 2, 1>
    pigment { Pattern }
    finish { ambient 0.3 diffuse 0.7 }
  }
#end
Tile(0, 0, pigment { onion color_map { Map } scale 0.7
  warp { repeat x * 0.8 offset <0, 0.3, 0> flip <1, 0, 0> } })
Tile(1, 0, pigment { checker rgb <0.9, 0.2, 0.1>, rgb 0.9 scale 0.3
  warp { black_hole <0.1, 0.35, 0.2>, 0.3 repeat <0.8, 0.7, 0> } })
Tile(2, 0, pigment { checker rgb <0.1, 0.6, 0.2>, rgb 0.9 scale 0.3
  warp { black_hole <2.7, 2, 0>, 0.9 strength 1.5 falloff 1 inverse } })
Tile(0, 1, pigment { checker rgb <0.2, 0.3, 0.9>, rgb 0.9 scale <0.125, 0.5, 1>
  warp { cylindrical dist_exp 1 orientation <0.2, 0.1, 1> } translate <-2.7, 0, 0> })
Tile(1, 1, pigment { checker rgb <0.9, 0.5, 0.1>, rgb 0.9 scale <0.0625, 0.125, 1>
  warp { spherical } translate <0, 2, -0.5> })
Tile(2, 1, pigment { gradient y color_map { Map } scale 0.2
  warp { toroidal major_radius 0.7 dist_exp 0.5 } rotate 90 * x translate <2.7, 0, 0> })
Tile(0, 2, pigment { gradient z color_map { Map } scale 0.4 warp { planar <1, 2, 3>, 0.25 }
  rotate 30 * z })
Tile(1, 2, pigment { hexagon rgb <0.9, 0.2, 0.1>, rgb 0.9, rgb <0.2, 0.3, 0.9> scale 0.2
  rotate -90 * x warp { black_hole <0, 0, 0>, 0.8 } translate <0, -2, 0> })
Tile(2, 2, pigment { hexagon rgb <0.9, 0.2, 0.1>, rgb 0.9, rgb <0.2, 0.3, 0.9> scale 0.2
  rotate -90 * x translate <2.7, -2, 0> warp { black_hole <2.7, -2, 0>, 0.8 } })
