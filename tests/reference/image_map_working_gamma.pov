// image_map_working_gamma: image colours join the scene in the gamma in force when the image
// is read: with `assumed_gamma 2.2` an ambient-only image_map shows its stored values (left);
// an image given `gamma 1.0` is brighter (middle); a lit sphere shows the gamma-2.2 shading
#version 3.7;
global_settings { assumed_gamma 2.2 }
camera { location <0, 0, -4> look_at 0 angle 50 }
light_source { <-5, 5, -5> rgb 1 }
plane { z, 1 pigment { image_map { png "images/colours16.png" } translate <-1.5, -0.5, 0> scale 1.5 }
  finish { ambient 1 diffuse 0 } }
box { <-0.45, -1.4, 0>, <0.45, 1.4, 0.5>
  pigment { image_map { png "images/colours16.png" gamma 1.0 } scale 0.9 translate <-0.45, -0.45, 0> }
  finish { ambient 1 diffuse 0 } }
sphere { <1.5, 0, 0>, 0.8 pigment { image_map { png "images/colours16.png" map_type 1 } } }
