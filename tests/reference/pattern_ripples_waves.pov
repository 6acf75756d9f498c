// Tests: the ripples and waves pattern values (ten wave sources, each with its own frequency
// in waves) as pigments, with frequency and phase (applied both to the distances and to the
// result), a wave type and scaling.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }

#macro Tile(Column, Row, Pigment)
  box { <-4 + Column * 2.7, 0.05 - Row * 3, 0>, <-1.4 + Column * 2.7, 2.95 - Row * 3, 1>
    pigment { Pigment }
    finish { ambient 1 diffuse 0 }
  }
#end
#declare Map = color_map { [0 rgb <0, 0, 0.3>] [0.5 rgb <0.2, 0.9, 0.6>] [1 rgb <1, 1, 0.8>] }
Tile(0, 0, pigment { ripples color_map { Map } })
Tile(1, 0, pigment { ripples frequency 2 phase 0.3 color_map { Map } scale 0.8 })
Tile(2, 0, pigment { ripples sine_wave color_map { Map } scale 0.25 translate <1, 2, 0> })
Tile(0, 1, pigment { waves color_map { Map } })
Tile(1, 1, pigment { waves frequency 0.6 phase 0.1 color_map { Map } scale 0.4 })
Tile(2, 1, pigment { waves triangle_wave color_map { Map } scale 3 rotate 40 * z })
