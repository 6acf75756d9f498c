// image_formats_jpeg: JPEG files as image_map — baseline colour (4:4:4), greyscale and
// progressive (4:2:0 chroma, which decoders upsample slightly differently) — decoded from
// sRGB, with `interpolate 2` and `transmit all`; a grey JPEG as image_pattern, bump_map and
// height field. Images: images/make_images.py (written with Pillow).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.1, -5> look_at <0, 1.6, 0> angle 60 }
light_source { <-2, 6, -8> rgb 1 }
background { rgb <0.1, 0.12, 0.2> }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.35 } }

#macro Tile(Pigment, X, Y)
  box { <0, 0, 0>, <1, 1, 0.2> pigment { Pigment } translate <X, Y, 0> }
#end

Tile(pigment { image_map { jpeg "images/jpeg_baseline.jpg" } }, -1.7, 0.6)
Tile(pigment { image_map { jpeg "images/jpeg_grey.jpg" } }, -0.5, 0.6)
Tile(pigment { image_map { jpeg "images/jpeg_progressive.jpg" } }, 0.7, 0.6)
Tile(pigment { image_map { jpeg "images/jpeg_baseline.jpg" interpolate 2 transmit all 0.4 } }, -1.7, 1.7)
Tile(pigment { image_pattern { jpeg "images/jpeg_grey.jpg" } color_map { [0 rgb <0.1, 0, 0.3>] [1 rgb <1, 0.8, 0.2>] } }, -0.5, 1.7)
box { <0, 0, 0>, <1, 1, 0.2> pigment { rgb <0.9, 0.85, 0.7> }
  normal { bump_map { jpeg "images/jpeg_grey.jpg" bump_size 4 } }
  translate <0.7, 1.7, 0> }
height_field { jpeg "images/jpeg_grey.jpg" smooth
  scale <1.4, 0.5, 1> translate <-1.7, 0, -1.25> pigment { rgb <0.4, 0.7, 0.9> } }
height_field { jpeg "images/jpeg_baseline.jpg"
  scale <1.4, 0.5, 1> translate <0.3, 0, -1.25> pigment { rgb <0.9, 0.6, 0.3> } }
