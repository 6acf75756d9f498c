// Tests: turbulence: the classic modifier on a checker (float and vector amounts, octaves,
// omega, lambda), the patterns that handle it themselves (marble, wood, spiral1, agate with
// agate_turb), a turbulence warp between transformations, and a repeated black hole with
// turbulence.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-3, 6, -20> rgb 1 }

#declare Map = color_map { [0 rgb <0.1, 0.1, 0.4>] [0.5 rgb <0.9, 0.5, 0.1>] [1 rgb <1, 1, 0.8>] }
#macro Tile(Column, Row, Pattern)
  box { <-4 + Column * 2.7, 1 - Row * 2, 0>, <-1.4 + Column * 2.7, 2.9 - Row * 2, 1>
    pigment { Pattern }
    finish { ambient 0.3 diffuse 0.7 }
  }
#end
Tile(0, 0, pigment { checker rgb <0.9, 0.2, 0.1>, rgb 0.9 scale 0.4 turbulence 0.5 })
Tile(1, 0, pigment { checker rgb <0.1, 0.6, 0.2>, rgb 0.9 scale 0.4
  turbulence <0.8, 0.1, 0> octaves 3 omega 0.7 lambda 3 })
Tile(2, 0, pigment { marble color_map { Map } turbulence 0.8 scale 0.6 })
Tile(0, 1, pigment { wood color_map { Map } turbulence 0.1 scale 0.3 translate <-2.7, 2, 0> })
Tile(1, 1, pigment { spiral1 2 color_map { Map } turbulence 0.3 scale 0.3 translate <0, 0, 0> })
Tile(2, 1, pigment { agate agate_turb 0.4 color_map { Map } scale 0.7 })
Tile(0, 2, pigment { gradient x color_map { Map } scale 0.5
  warp { turbulence 0.4 octaves 4 } rotate 40 * z })
Tile(1, 2, pigment { gradient x color_map { Map } scale 0.5 rotate 40 * z
  warp { turbulence 0.4 octaves 4 } })
Tile(2, 2, pigment { checker rgb <0.2, 0.3, 0.9>, rgb 0.9 scale 0.2
  warp { black_hole <0.3, 0.3, 0.5>, 0.25 repeat <0.6, 0.6, 1> turbulence 0.05 } })
