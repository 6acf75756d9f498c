// Tests: the colour maps POV-Ray builds into agate, bozo, mandel, marble, radial and wood
// (used when a pigment gives no colour map), and that spotted and julia use the grey ramp;
// also a default-map pattern inside a pigment_map entry.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-3, 6, -20> rgb 1 }

#macro Tile(Column, Row, Pigment)
  box { <-4 + Column * 2, -1 - Row * 2, 0>, <-2.05 + Column * 2, 0.95 - Row * 2, 1>
    pigment { Pigment }
    finish { ambient 0.4 diffuse 0.6 }
  }
#end
Tile(0, -1, pigment { agate scale 2 })
Tile(1, -1, pigment { bozo scale 0.4 })
Tile(2, -1, pigment { mandel 60 scale 0.8 translate <1.6, 2, 0> })
Tile(3, -1, pigment { marble turbulence 0.5 scale 0.8 })
Tile(0, 0, pigment { radial rotate x * 90 translate <-3, 0, 0> })
Tile(1, 0, pigment { wood scale 0.15 translate <-1, 0, 0> })
Tile(2, 0, pigment { spotted scale 0.4 })
Tile(3, 0, pigment { julia <0.3, 0.5> 40 scale 0.8 translate <3, 0, 0> })
Tile(0, 1, pigment { gradient x pigment_map { [0.2 rgb <0.2, 0.6, 0.3>] [0.5 radial frequency 6 rotate x * 90] [0.8 wood scale 0.1] } translate <-4, 0, 0> scale 2 })
Tile(1, 1, pigment { wood turbulence 0.2 rotate y * 30 scale 0.3 })
Tile(2, 1, pigment { agate agate_turb 0.3 scale 0.7 })
Tile(3, 1, pigment { bozo turbulence 0.6 scale 0.5 })
