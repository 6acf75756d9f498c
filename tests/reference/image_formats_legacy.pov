// image_formats_legacy: a scene with no #version and no assumed_gamma uses every format's
// stored values as they are (TGA, JPEG, GIF, PPM; HDR linear values), decoded only by a
// `gamma` given in the block. Images: images/make_images.py.
camera { location <0, 1.7, -5> look_at <0, 1.45, 0> angle 58 }
light_source { <-2, 6, -8> rgb 1 }
background { rgb <0.1, 0.12, 0.2> }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.35 } }

#macro Tile(Pigment, X, Y)
  box { <0, 0, 0>, <1, 1, 0.2> pigment { Pigment } translate <X, Y, 0> }
#end

Tile(pigment { image_map { tga "images/tga_rgb24.tga" } }, -1.7, 0.1)
Tile(pigment { image_map { jpeg "images/jpeg_baseline.jpg" } }, -0.5, 0.1)
Tile(pigment { image_map { gif "images/gif_palette.gif" } }, 0.7, 0.1)
Tile(pigment { image_map { ppm "images/ppm_p6_8.ppm" } }, -1.7, 1.2)
Tile(pigment { image_map { pgm "images/pgm_p5_16.pgm" } }, -0.5, 1.2)
Tile(pigment { image_map { hdr "images/hdr_rle.hdr" } }, 0.7, 1.2)
Tile(pigment { image_map { tga "images/tga_rgba32_rle.tga" gamma 2.0 } }, -1.7, 2.3)
Tile(pigment { image_map { ppm "images/ppm_p3_16.ppm" gamma 2.0 } }, -0.5, 2.3)
Tile(pigment { image_map { gif "images/gif_transparent.gif" gamma 1.6 } }, 0.7, 2.3)
