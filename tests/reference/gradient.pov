// Tests: gradient pigments with color_map: a vertical rainbow on a wall (several entries,
// scaled), a two-entry x gradient on the floor (repeating every unit), and a gradient
// along a diagonal vector on a sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -7> look_at <0, 1.2, 0> angle 55 }
light_source { <-3, 8, -7> rgb 1 }

plane { y, 0
  pigment { gradient x color_map { [0 rgb <0.9, 0.9, 0.9>] [1 rgb <0.2, 0.2, 0.5>] } }
}
plane { z, 2
  pigment {
    gradient y
    color_map {
      [0.0 rgb <1, 0, 0>]
      [0.25 rgb <1, 1, 0>]
      [0.5 rgb <0, 1, 0>]
      [0.75 rgb <0, 0.3, 1>]
      [1.0 rgb <1, 0, 0>]
    }
    scale 3
  }
}
sphere { <0, 1, -1>, 1
  pigment {
    gradient <1, 1, 0>
    color_map { [0 rgb <0.1, 0.1, 0.1>] [0.5 rgb <1, 0.6, 0.1>] [1 rgb <0.1, 0.1, 0.1>] }
    scale 0.8
  }
}
