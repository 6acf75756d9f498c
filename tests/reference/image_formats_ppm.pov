// image_formats_ppm: PPM and PGM files as image_map — binary (P6, P5) and ASCII (P3, P2),
// 8-bit and 16-bit maxval — whose stored values POV-Ray 3.7 uses as they are (no sRGB
// decoding), a `gamma 2.2` given in the block, `interpolate 2`, and 16-bit PGM and PPM
// height fields. Images: images/make_images.py.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.1, -5> look_at <0, 1.6, 0> angle 60 }
light_source { <-2, 6, -8> rgb 1 }
background { rgb <0.1, 0.12, 0.2> }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.35 } }

#macro Tile(Pigment, X, Y)
  box { <0, 0, 0>, <1, 1, 0.2> pigment { Pigment } translate <X, Y, 0> }
#end

Tile(pigment { image_map { ppm "images/ppm_p6_8.ppm" } }, -1.7, 0.6)
Tile(pigment { image_map { ppm "images/ppm_p6_16.ppm" } }, -0.5, 0.6)
Tile(pigment { image_map { ppm "images/ppm_p3_8.ppm" gamma 2.2 } }, 0.7, 0.6)
Tile(pigment { image_map { ppm "images/ppm_p3_16.ppm" interpolate 2 } }, -1.7, 1.7)
Tile(pigment { image_map { pgm "images/pgm_p5_8.pgm" } }, -0.5, 1.7)
Tile(pigment { image_map { pgm "images/pgm_p5_16.pgm" } }, 0.7, 1.7)
Tile(pigment { image_map { pgm "images/pgm_p2_8.pgm" filter all 0.5 } }, -1.7, 2.8)
Tile(pigment { image_map { pgm "images/pgm_p2_16.pgm" interpolate 2 } }, -0.5, 2.8)
Tile(pigment { image_pattern { ppm "images/ppm_p6_16.ppm" } color_map { [0 rgb <0.1, 0, 0.3>] [1 rgb <1, 0.8, 0.2>] } }, 0.7, 2.8)
height_field { pgm "images/pgm_p5_16.pgm" smooth
  scale <1.4, 0.5, 1> translate <0.3, 0, -1.25> pigment { rgb <0.9, 0.6, 0.3> } }
height_field { ppm "images/ppm_p6_16.ppm"
  scale <1.4, 0.5, 1> translate <-1.7, 0, -1.25> pigment { rgb <0.4, 0.7, 0.9> } }
