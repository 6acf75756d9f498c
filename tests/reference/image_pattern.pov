// image_pattern: an image's stored grey level 0.297 R + 0.589 G + 0.114 B (no gamma) as a
// pattern value in a colour map, a texture map, and with use_alpha (value 1 - alpha)
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { rgb <0.3, 0.4, 0.5> }
camera { location <0, 4, -5> look_at <0, 0, 0.3> angle 50 }
light_source { <-3, 8, -6> rgb 1 }
plane { y, 0
  pigment { image_pattern { png "images/colours16.png" } color_map { [0 rgb <0.1, 0, 0.3>] [1 rgb <1, 0.9, 0.2>] } rotate x*90 scale 2 translate -x }
}
box { <-1, 0, -1>, <1, 0.4, 1>
  texture { image_pattern { png "images/colours16.png" interpolate 2 }
    texture_map { [0.3 pigment { rgb <0.9, 0.2, 0.1> }] [0.6 pigment { rgb <0.2, 0.8, 0.3> } finish { phong 0.6 }] }
    rotate x*90 scale 2 translate <-1, 0, -1> }
  translate <-1.6, 0, 0.6>
}
box { <-1, 0, -1>, <1, 0.4, 1>
  pigment { image_pattern { png "images/alpha16.png" use_alpha } color_map { [0 rgb 0.1] [1 rgb <0.3, 0.6, 1>] } rotate x*90 scale 2 translate <-1, 0, -1> }
  translate <1.6, 0, 0.6>
}
