// Tests: the dedicated normal perturbations of ripples and waves (ten wave sources, each
// with its own frequency in waves), with bump sizes, frequency, phase and scaling, on tiles
// facing the camera.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 8 up y * 6 }
light_source { <-3, 6, -20> rgb 1 }

#macro Tile(Column, Row, Normal)
  box { <-4 + Column * 2.7, 0.05 - Row * 3, 0>, <-1.4 + Column * 2.7, 2.95 - Row * 3, 1>
    pigment { rgb 0.8 }
    normal { Normal }
    finish { ambient 0.1 diffuse 0.9 specular 0.3 }
  }
#end
Tile(0, 0, normal { ripples 0.8 })
Tile(1, 0, normal { ripples 0.5 frequency 3 phase 0.2 scale 0.7 })
Tile(2, 0, normal { ripples 1.2 scale 0.3 translate <2, -1, 0> })
Tile(0, 1, normal { waves 0.8 })
Tile(1, 1, normal { waves 0.6 frequency 2.5 phase 0.4 scale 0.5 })
Tile(2, 1, normal { waves 1 scale 0.2 rotate 30 * z })
