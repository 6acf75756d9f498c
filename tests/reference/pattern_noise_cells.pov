// Tests: the cell patterns, whose random cell values come from POV-Ray's random tables:
// cells, crackle (default form, form <1, 0, 0>, metric 1, offset, solid).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-3, 6, -20> rgb 1 }

#declare Map = color_map { [0 rgb <0.1, 0.1, 0.4>] [0.5 rgb <0.9, 0.5, 0.1>] [1 rgb <1, 1, 0.8>] }
#macro Tile(Column, Row, Pattern)
  box { <-4 + Column * 4, 0.05 - Row * 3, 0>, <-0.05 + Column * 4, 3 - Row * 3, 1>
    pigment { Pattern }
    finish { ambient 0.3 diffuse 0.7 }
  }
#end
Tile(0, 0, pigment { cells color_map { Map } scale 0.5 })
Tile(1, 0, pigment { crackle color_map { Map } scale 0.5 })
Tile(0, 1, pigment { crackle form <1, 0, 0> metric 1 color_map { Map } scale 0.5 })
Tile(1, 1, pigment { crackle solid offset 0.1 color_map { Map } scale 0.5 })
