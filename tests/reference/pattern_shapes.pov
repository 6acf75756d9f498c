// Tests: the continuous patterns that need no noise, each on a tile facing the camera:
// boxed, cylindrical, spherical, planar, onion, leopard, radial (with frequency), spiral1
// and spiral2.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-3, 6, -20> rgb 1 }

#declare Finish = finish { ambient 0.3 diffuse 0.7 }
#declare Map = color_map { [0 rgb <0.1, 0.1, 0.4>] [0.5 rgb <0.9, 0.5, 0.1>] [1 rgb <1, 1, 0.8>] }
#macro Tile(Column, Row, Pattern)
  box { <-4 + Column * 2.7, 1 - Row * 2, 0>, <-1.4 + Column * 2.7, 2.9 - Row * 2, 1>
    pigment { Pattern }
    finish { Finish }
  }
#end
Tile(0, 0, pigment { boxed color_map { Map } scale 1.2 translate <-2.7, 2, 0> })
Tile(1, 0, pigment { cylindrical color_map { Map } scale 1.1 rotate 90 * x translate <0, 2, 0> })
Tile(2, 0, pigment { spherical color_map { Map } scale 1.3 translate <2.7, 2, 0> })
Tile(0, 1, pigment { planar color_map { Map } scale 0.5 rotate 30 * z })
Tile(1, 1, pigment { onion color_map { Map } scale 0.6 translate <0.2, 0.1, 0> })
Tile(2, 1, pigment { leopard color_map { Map } scale 0.12 })
Tile(0, 2, pigment { radial color_map { Map } frequency 5 rotate -90 * x translate <-2.7, -2, 0> })
Tile(1, 2, pigment { spiral1 3 color_map { Map } scale 0.5 translate <0, -2, 0> })
Tile(2, 2, pigment { spiral2 2 color_map { Map } scale 0.6 translate <2.7, -2, 0> })
