// Tests: quilted with its default controls and with control0/control1 changed, and
// tiling 1 (bevelled squares), on tiles facing the camera.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-3, 6, -20> rgb 1 }

#declare Map = color_map { [0 rgb <0.1, 0.1, 0.4>] [0.15 rgb <0.9, 0.5, 0.1>] [0.4 rgb <1, 1, 0.8>] }
#macro Tile(Column, Row, Pattern)
  box { <-4 + Column * 2.7, 0.05 - Row * 3, 0>, <-1.4 + Column * 2.7, 3 - Row * 3, 1>
    pigment { Pattern }
    finish { ambient 0.3 diffuse 0.7 }
  }
#end
Tile(0, 0, pigment { quilted color_map { Map } scale 0.7 translate 0.1 })
Tile(1, 0, pigment { quilted control0 0 control1 0 color_map { Map } scale 0.7 translate 0.1 })
Tile(2, 0, pigment { tiling 1 color_map { Map } scale 0.6 rotate -90 * x })
Tile(0, 1, pigment { quilted control0 0 control1 1 color_map { Map } scale 0.7 translate 0.1 })
Tile(1, 1, pigment { quilted control0 0.7 control1 0.2 color_map { Map } scale 0.7 translate 0.1 })
Tile(2, 1, pigment { tiling 1 color_map { [0 rgb <0.2, 0.5, 0.2>] [0.7 rgb 0.9] [1 rgb 0.3] }
  scale 0.45 rotate <-90, 0, 20> })
