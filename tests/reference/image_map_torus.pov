// image_map_torus: map_type 5 (the image around a torus of major radius 1: u around Y, v
// around the tube from its inner rim), on a matching torus and on a plane through the axis
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0, 0> angle 50 }
light_source { <3, 9, -6> rgb 1 }
background { rgb <0.15, 0.15, 0.2> }
torus { 1, 0.45 pigment { image_map { png "images/colours16.png" map_type 5 } } rotate <-30, 20, 0> translate <-1.4, 0.5, 0> }
torus { 1, 0.45 pigment { image_map { png "images/colours16.png" map_type 5 interpolate 2 } } rotate <50, 0, 0> translate <1.4, 0.5, 0> }
plane { z, 1.5 pigment { image_map { png "images/colours16.png" map_type 5 } scale 1.5 } }
