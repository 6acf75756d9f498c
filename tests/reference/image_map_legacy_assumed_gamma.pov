// image_map_legacy_assumed_gamma: under `#version 3.6` with `assumed_gamma 2.2`, PNG files that state no gamma give their stored values as scene colours, unconverted (advanced/drums2 relies on it); one palette file, one RGB file
#version 3.6;
global_settings { assumed_gamma 2.2 }
camera { location <0, 0, -3> look_at 0 angle 50 }
light_source { <0, 3, -5> rgb 1 }
plane { z, 0
  pigment { image_map { png "images/palette8.png" once } translate <-1, -0.5, 0> }
  finish { ambient 0.3 }
  clipped_by { box { <-1, -0.5, -1>, <0, 0.5, 1> } }
}
plane { z, 0
  pigment { image_map { png "images/colours16.png" once } translate <0, -0.5, 0> }
  finish { ambient 0.3 }
  clipped_by { box { <0, -0.5, -1>, <1, 0.5, 1> } }
}
background { rgb <0.2, 0.3, 0.4> }
