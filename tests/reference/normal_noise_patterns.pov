// Tests: the dedicated normal perturbations of bumps, dents and wrinkles (with bump sizes,
// scaling and a noise generator) on tiles facing the camera.
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
Tile(0, 0, normal { bumps 1 scale 0.4 })
Tile(1, 0, normal { dents 0.8 scale 0.5 })
Tile(2, 0, normal { wrinkles 0.6 scale 0.3 })
Tile(0, 1, normal { bumps 0.5 noise_generator 1 scale 0.2 })
Tile(1, 1, normal { dents 1.5 noise_generator 3 scale 0.6 })
Tile(2, 1, normal { wrinkles 1 scale 0.7 rotate 30 * z })
