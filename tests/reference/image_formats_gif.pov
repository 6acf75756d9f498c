// image_formats_gif: GIF files as image_map — a 16-colour palette, a transparent palette
// entry (as transmit), an interlaced file (POV-Ray keeps its rows in stored order), palette
// `filter`/`transmit` entries — as image_pattern, as a `use_index` bump_map and as a height
// field (palette index x 256). Images: images/make_images.py.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.1, -5> look_at <0, 1.6, 0> angle 60 }
light_source { <-2, 6, -8> rgb 1 }
background { rgb <0.1, 0.12, 0.2> }
plane { y, 0 pigment { checker rgb 0.7 rgb 0.35 } }

#macro Tile(Pigment, X, Y)
  box { <0, 0, 0>, <1, 1, 0.2> pigment { Pigment } translate <X, Y, 0> }
#end

Tile(pigment { image_map { gif "images/gif_palette.gif" } }, -1.7, 0.6)
Tile(pigment { image_map { gif "images/gif_transparent.gif" } }, -0.5, 0.6)
Tile(pigment { image_map { gif "images/gif_interlaced.gif" interpolate 2 } }, 0.7, 0.6)
Tile(pigment { image_map { gif "images/gif_palette.gif" filter 2, 1.0 transmit 9, 0.7 transmit 15, 1 } }, -1.7, 1.7)
Tile(pigment { image_pattern { gif "images/gif_palette.gif" } color_map { [0 rgb <0.1, 0, 0.3>] [1 rgb <1, 0.8, 0.2>] } }, -0.5, 1.7)
box { <0, 0, 0>, <1, 1, 0.2> pigment { rgb <0.9, 0.85, 0.7> }
  normal { bump_map { gif "images/gif_palette.gif" use_index bump_size 0.05 } }
  translate <0.7, 1.7, 0> }
height_field { gif "images/gif_palette.gif"
  scale <1.4, 6, 1> translate <-1.7, 0, -1.25> pigment { rgb <0.4, 0.7, 0.9> } }
height_field { gif "images/gif_interlaced.gif" smooth
  scale <1.4, 6, 1> translate <0.3, 0, -1.25> pigment { rgb <0.9, 0.6, 0.3> } }
