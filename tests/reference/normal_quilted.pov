// Tests: quilted as a normal (its dedicated perturbation, added to the normal that faces the
// viewer) with several controls and bump sizes, on boxes turned towards the camera.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -20> right x * 4 / 3 direction 3 * z }
light_source { <300, 500, -500> rgb 0.65 }
light_source { <-50, 10, -500> rgb 0.45 }

#macro Quilted_Box(Column, Row, Bump, Control0, Control1)
  box { -0.8, 0.8
    pigment { rgb 1 }
    finish { phong 1 phong_size 400 }
    normal { quilted Bump control0 Control0 control1 Control1 scale 0.85 }
    rotate <-30, 30, 0>
    translate <-3 + 3 * Column, 2 - 2 * Row, 0>
  }
#end
Quilted_Box(0, 0, 5, 0, 0)
Quilted_Box(1, 0, 5, 0, 1)
Quilted_Box(2, 0, 1, 1, 1)
Quilted_Box(0, 1, 5, 0.5, 0.5)
Quilted_Box(1, 1, 2, 1, 0)
Quilted_Box(2, 1, 5, 1, 1)
Quilted_Box(0, 2, 0.5, 0.3, 0.7)
Quilted_Box(1, 2, 5, 1, 0.5)
Quilted_Box(2, 2, 3, 0.5, 0)
