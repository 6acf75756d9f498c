// image_formats_tga: TGA files as image_map — uncompressed and run-length encoded, 24-bit,
// 32-bit with alpha (as transmit), 8-bit grey, colour-mapped with `filter`/`transmit`
// palette entries, bottom-left and top-left origins — decoded from sRGB; an image_pattern
// and a bump_map from the grey TGA. Images: images/make_images.py.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 1.7, -5> look_at <0, 1.45, 0> angle 58 }
light_source { <-2, 6, -8> rgb 1 }
background { rgb <0.1, 0.12, 0.2> }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.35 } }

#macro Tile(Pigment, X, Y)
  box { <0, 0, 0>, <1, 1, 0.2> pigment { Pigment } translate <X, Y, 0> }
#end

Tile(pigment { image_map { tga "images/tga_rgb24.tga" } }, -1.7, 0.1)
Tile(pigment { image_map { tga "images/tga_rgb24_top.tga" interpolate 2 } }, -0.5, 0.1)
Tile(pigment { image_map { tga "images/tga_rgb24_rle.tga" } }, 0.7, 0.1)
Tile(pigment { image_map { tga "images/tga_rgba32.tga" } }, -1.7, 1.2)
Tile(pigment { image_map { tga "images/tga_rgba32_rle.tga" filter all 0.4 } }, -0.5, 1.2)
Tile(pigment { image_map { tga "images/tga_grey8.tga" } }, 0.7, 1.2)
Tile(pigment { image_map { tga "images/tga_mapped8.tga" filter 5, 1.0 transmit 10, 0.6 } }, -1.7, 2.3)
Tile(pigment { image_map { tga "images/tga_mapped8_rle.tga" transmit all 0.3 } }, -0.5, 2.3)
Tile(pigment { image_pattern { tga "images/tga_grey8_rle.tga" } color_map { [0 rgb <0.1, 0, 0.3>] [1 rgb <1, 0.8, 0.2>] } }, 0.7, 2.3)
sphere { <2.2, 0.5, -1>, 0.5 pigment { rgb <0.9, 0.9, 0.8> }
  normal { bump_map { tga "images/tga_grey8.tga" bump_size 3 } scale 0.3 } }
