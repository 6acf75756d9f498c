// image_formats_hdr: Radiance HDR files (flat and run-length encoded scanlines) as
// image_map, linear light brighter than 1 (POV-Ray's RGBE rounding: mantissa + 1/2), with
// `interpolate 4`, a `gamma 2.2` in the block, `filter all`, and as image_pattern
// whose grey level stops at 1. Images: images/make_images.py.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 1.7, -5> look_at <0, 1.45, 0> angle 58 }
light_source { <-2, 6, -8> rgb 1 }
background { rgb <0.1, 0.12, 0.2> }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.35 } }

#macro Tile(Pigment, X, Y)
  box { <0, 0, 0>, <1, 1, 0.2> pigment { Pigment } finish { ambient 0 diffuse 0.5 } translate <X, Y, 0> }
#end

Tile(pigment { image_map { hdr "images/hdr_flat.hdr" } }, -1.7, 0.1)
Tile(pigment { image_map { hdr "images/hdr_rle.hdr" interpolate 4 } }, -0.5, 0.1)
Tile(pigment { image_map { hdr "images/hdr_rle.hdr" gamma 2.2 } }, 0.7, 0.1)
Tile(pigment { image_map { hdr "images/hdr_flat.hdr" filter all 0.5 } }, -1.7, 1.2)
Tile(pigment { image_pattern { hdr "images/hdr_rle.hdr" } color_map { [0 rgb <0.1, 0, 0.3>] [1 rgb <1, 0.8, 0.2>] } }, -0.5, 1.2)
Tile(pigment { image_map { hdr "images/hdr_flat.hdr" map_type 1 } }, 0.7, 1.2)
sphere { <0, 2.8, 0.5>, 0.5 pigment { image_map { hdr "images/hdr_rle.hdr" map_type 1 interpolate 2 } } finish { ambient 0.2 diffuse 0.3 } }
