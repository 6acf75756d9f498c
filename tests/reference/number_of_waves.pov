// Tests: `number_of_waves` (here 3, written after the objects: it applies to every ripples
// and waves pattern of the scene) in ripples and waves pigments and normals, and a normal
// map averaging two waves normals as in POV-Ray's normavg.pov example.
#version 3.7;

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-3, 6, -20> rgb 1 }

#macro Tile(Column, Row, Texture)
  box { <-4 + Column * 2.7, 0.05 - Row * 3, 0>, <-1.4 + Column * 2.7, 2.95 - Row * 3, 1>
    texture { Texture }
  }
#end
#declare Map = color_map { [0 rgb <0, 0, 0.3>] [0.5 rgb <0.2, 0.9, 0.6>] [1 rgb <1, 1, 0.8>] }
Tile(0, 0, texture { pigment { ripples color_map { Map } scale 0.5 } finish { ambient 1 diffuse 0 } })
Tile(1, 0, texture { pigment { waves color_map { Map } scale 0.3 } finish { ambient 1 diffuse 0 } })
Tile(2, 0, texture { pigment { rgb 0.8 } normal { ripples 0.7 scale 0.4 } })
Tile(0, 1, texture { pigment { rgb 0.8 } normal { waves 1 scale 0.3 } })
Tile(1, 1, texture { pigment { rgb 0.8 } finish { phong 1 phong_size 100 }
  normal { average normal_map {
    [waves 2.0 frequency 3 translate <1, 1, 0>]
    [waves 2.0 frequency 3 translate <-1, -1, 0>] } scale 0.8 } })
Tile(2, 1, texture { pigment { rgb 0.8 } normal { waves 0.8 frequency 2 phase 0.3 scale 0.5 } })

global_settings { assumed_gamma 1.0 number_of_waves 3 }
