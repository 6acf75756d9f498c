// Tests: the noise patterns without turbulence on tiles facing the camera: bozo, spotted
// (noise generator 1), bumps (generator 3), dents, granite (generators 2 and 1), wrinkles
// (generators 2 and 3), agate. (waves and ripples are not exact yet: their wave centres are
// POV-Ray's own random data, not measured.)
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
Tile(0, 0, pigment { bozo color_map { Map } scale 0.4 })
Tile(1, 0, pigment { spotted noise_generator 1 color_map { Map } scale 0.4 })
Tile(2, 0, pigment { bumps noise_generator 3 color_map { Map } scale 0.4 })
Tile(0, 1, pigment { dents color_map { Map } scale 0.5 })
Tile(1, 1, pigment { granite color_map { Map } scale 2 })
Tile(2, 1, pigment { wrinkles color_map { Map } scale 0.5 })
Tile(0, 2, pigment { agate color_map { Map } scale 0.8 })
Tile(1, 2, pigment { granite noise_generator 1 color_map { Map } scale 1.5 })
Tile(2, 2, pigment { wrinkles noise_generator 3 color_map { Map } scale 0.5 })
