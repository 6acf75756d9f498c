// image_map_legacy_scene: a scene with no #version and no assumed_gamma uses its images as
// stored (left), decoded only by a `gamma` given in the block (right, `gamma 2.0`)
camera { location <0, 0, -4> look_at 0 angle 50 }
plane { z, 1 pigment { image_map { png "images/colours16.png" } translate <-1.5, -0.5, 0> scale 1.5 }
  finish { ambient 1 diffuse 0 } }
box { <0, -1.4, 0>, <1.8, 1.4, 0.5>
  pigment { image_map { png "images/colours16.png" gamma 2.0 } scale 0.9 }
  finish { ambient 1 diffuse 0 } }
