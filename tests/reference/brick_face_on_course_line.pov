// brick_face_on_course_line: a face lying exactly on a brick boundary (a box top at y = 0 with the pattern turned by rotate z*90, which leaves the pattern's x at about -1e-16 there) shows bricks, not speckled mortar: POV-Ray evaluates brick 1e-10 further along each axis
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -8> look_at <0, -0.5, 0> angle 45 }
light_source { <5, 9, -9> rgb 1 }
background { rgb <0.6, 0.7, 0.9> }
box {
  <-4, -1, -4>, <4, 0, 4>
  texture {
    pigment {
      brick
      pigment { rgb 0.05 }
      pigment { gradient z color_map { [0 rgb <0.8, 0.3, 0.1>] [1 rgb <0.9, 0.7, 0.3>] } }
      brick_size <1, 2.5, 20>
      mortar 0.05
    }
    rotate z * 90
    finish { phong 0.25 }
  }
}
sphere { <1.5, 1, 1>, 1 pigment { brick rgb 1 rgb <0.7, 0.1, 0.1> brick_size 0.4 mortar 0.04 } }
