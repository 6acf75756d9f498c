// image_map_palette: `filter N, F` / `transmit N, T` of single palette entries of a palette
// PNG; later settings win over earlier ones (`filter all` replaces earlier entries)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5, 0.5, -2> look_at <0.5, 0.5, 0> angle 40 }
light_source { <0, 3, -5> rgb 1 }
plane { z, 0
  pigment { image_map { png "images/palette8.png" transmit all 0.1 transmit 1, 0.7 filter 2, 0.8 filter all 0.2 filter 3, 0.9 transmit 5, 1 } }
  finish { ambient 0.5 }
}
plane { z, 1 pigment { checker rgb 1 rgb <0.3, 0.2, 0.1> scale 0.1 } finish { ambient 1 } }
