// Tests: warps and turbulence on an `average` pigment (they move the point its entries are
// evaluated at), with transformations before and after the warp, and a repeated black hole
// whose centres are jittered per cell by its `turbulence`.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-3, 6, -20> rgb 1 }

#declare Mix = pigment { average pigment_map {
  [1 gradient x color_map { [0 rgb <0.1, 0.1, 0.5>] [1 rgb <1, 0.8, 0.2>] } scale 0.6]
  [1 onion color_map { [0 rgb <0.9, 0.2, 0.1>] [0.5 rgb 0.9] [1 rgb <0.1, 0.5, 0.2>] }
    scale 0.8]
} }
#macro Tile(Column, Row, Pattern)
  box { <-4 + Column * 4.05, 0.1 - Row * 3, 0>, <-0.05 + Column * 4.05, 2.9 - Row * 3, 1>
    pigment { Pattern }
    finish { ambient 0.3 diffuse 0.7 }
  }
#end
Tile(0, 0, pigment { Mix warp { repeat x * 0.9 offset <0, 0.4, 0> flip y } })
Tile(1, 0, pigment { Mix scale 1.3 warp { black_hole <3, 1.5, 0>, 1.2 strength 1.5 }
  translate <0.5, 0, 0> })
Tile(0, 1, pigment { Mix translate <0, 1, 0> turbulence 0.4 })
Tile(1, 1, pigment { checker rgb <0.9, 0.2, 0.1>, rgb 0.9 scale 0.25
  warp { black_hole <0.4, 0.4, 0>, 0.35 falloff 1 strength 0.8 repeat <1, 1, 0>
    turbulence <0.2, 0.2, 0> inverse } })
