// image_formats_alpha: transparency across formats — a 32-bit TGA's alpha and a GIF's
// transparent entry as transmit over a striped wall, and image_pattern `use_alpha`: the
// transparency of files that store it (TGA, GIF), 0 for a palette file without it, and the
// red channel of files without alpha (PPM, TGA, JPEG; measured). Images: images/make_images.py.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 1.7, -5> look_at <0, 1.45, 0> angle 58 }
light_source { <-2, 6, -8> rgb 1 }
background { rgb <0.1, 0.12, 0.2> }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.35 } }
plane { z, 1.5 pigment { gradient x color_map { [0.5 rgb <0.9, 0.2, 0.1>] [0.5 rgb <0.1, 0.3, 0.9>] } scale 0.4 } }

#macro Tile(Pigment, X, Y)
  box { <0, 0, 0>, <1, 1, 0.2> pigment { Pigment } translate <X, Y, 0> }
#end
#declare Levels = color_map { [0 rgb <0.1, 0, 0.3>] [1 rgb <1, 0.8, 0.2>] }

Tile(pigment { image_map { tga "images/tga_rgba32.tga" } }, -1.7, 0.1)
Tile(pigment { image_map { gif "images/gif_transparent.gif" } }, -0.5, 0.1)
Tile(pigment { image_map { tga "images/tga_rgba32_rle.tga" interpolate 2 filter all 0.3 } }, 0.7, 0.1)
Tile(pigment { image_pattern { tga "images/tga_rgba32.tga" use_alpha } color_map { Levels } }, -1.7, 1.2)
Tile(pigment { image_pattern { gif "images/gif_transparent.gif" use_alpha } color_map { Levels } }, -0.5, 1.2)
Tile(pigment { image_pattern { gif "images/gif_palette.gif" use_alpha } color_map { Levels } }, 0.7, 1.2)
Tile(pigment { image_pattern { ppm "images/ppm_p6_8.ppm" use_alpha } color_map { Levels } }, -1.7, 2.3)
Tile(pigment { image_pattern { tga "images/tga_rgb24.tga" use_alpha } color_map { Levels } }, -0.5, 2.3)
Tile(pigment { image_pattern { jpeg "images/jpeg_baseline.jpg" use_alpha } color_map { Levels } }, 0.7, 2.3)
