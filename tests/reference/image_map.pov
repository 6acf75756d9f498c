// Tests: image_map — planar (repeated, scaled), spherical (map_type 1) and cylindrical
// (map_type 2) projections, `once`, bilinear and normalised-distance interpolation, sRGB
// decoding of 8-bit PNGs, the alpha channel as transmit, `filter all` and `transmit all`.
// The images in images/ are 16x16 PNGs written by a Python script for these tests.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -6.5> look_at <0, 0.8, 0> angle 60 }
light_source { <3, 9, -6> rgb 1 }
background { rgb <0.15, 0.15, 0.2> }

plane { y, 0 pigment { image_map { png "images/colours16.png" } rotate x*90 scale 2 } }
sphere { 0, 0.9 pigment { image_map { png "images/colours16.png" map_type 1 interpolate 2 } } rotate y*30 translate <-2.1, 0.9, 0> }
cylinder { <0, 0, 0>, <0, 1.6, 0>, 0.7 pigment { image_map { png "images/colours16.png" map_type 2 interpolate 4 } scale <1, 1.6, 1> } }
box { <-0.6, 0, -0.6>, <0.6, 1.4, 0.6> rotate y*-30 translate <2.1, 0, 0>
  pigment { image_map { png "images/alpha16.png" once } scale 0.9 translate <1.6, 0.2, 0> } }
box { <-1.2, 0, -0.1>, <1.2, 0.5, 0.1> translate <0, 0, -1.8>
  pigment { image_map { png "images/colours16.png" filter all 0.3 transmit all 0.3 } scale 0.5 } }
