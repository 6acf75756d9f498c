// image_formats_gamma: at `assumed_gamma 2.2` TGA, JPEG and GIF colours are decoded from
// sRGB and re-encoded with 1/2.2, HDR values encoded with 1/2.2, while PPM and PGM values
// stay as stored; a `gamma 1.5` in the block decodes any format. Images: images/make_images.py.
#version 3.7;
global_settings { assumed_gamma 2.2 }

camera { location <0, 1.7, -5> look_at <0, 1.45, 0> angle 58 }
light_source { <-2, 6, -8> rgb 1 }
background { rgb <0.1, 0.12, 0.2> }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.35 } }

#macro Tile(Pigment, X, Y)
  box { <0, 0, 0>, <1, 1, 0.2> pigment { Pigment } translate <X, Y, 0> }
#end

Tile(pigment { image_map { tga "images/tga_rgb24_rle.tga" } }, -1.7, 0.1)
Tile(pigment { image_map { jpeg "images/jpeg_grey.jpg" } }, -0.5, 0.1)
Tile(pigment { image_map { gif "images/gif_interlaced.gif" } }, 0.7, 0.1)
Tile(pigment { image_map { ppm "images/ppm_p6_16.ppm" } }, -1.7, 1.2)
Tile(pigment { image_map { pgm "images/pgm_p2_8.pgm" } }, -0.5, 1.2)
Tile(pigment { image_map { hdr "images/hdr_flat.hdr" } }, 0.7, 1.2)
Tile(pigment { image_map { tga "images/tga_mapped8.tga" gamma 1.5 } }, -1.7, 2.3)
Tile(pigment { image_map { ppm "images/ppm_p6_8.ppm" gamma 1.5 } }, -0.5, 2.3)
Tile(pigment { image_map { hdr "images/hdr_rle.hdr" gamma 1.5 } }, 0.7, 2.3)
