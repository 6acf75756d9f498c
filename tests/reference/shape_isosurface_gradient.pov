// shape_isosurface_gradient: a too-low max_gradient leaves POV-Ray's holes (left), a
// threshold and all_intersections seen through a clear container face (right), scaled.
// tolerance: 0.03 (the rings of misplaced hits a too-low max_gradient causes depend on POV-Ray's
// exact interval arithmetic; durer reproduces them in kind, 2.3% of pixels differ)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.7, 0> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
isosurface {
  function { 3 * (sqrt(x*x + y*y + z*z) - 0.8) + 0.3 * sin(5 * x) }
  contained_by { box { -1, 1 } }
  max_gradient 1.2
  pigment { rgb <0.9, 0.3, 0.2> }
  translate <-1.4, 1, 0>
}
isosurface {
  function { abs(x) + abs(y) + abs(z) }
  threshold 1.2
  contained_by { sphere { 0, 1 } }
  all_intersections
  pigment { rgb <0.2, 0.5, 0.9> filter 0.5 }
  scale <1, 1.2, 0.8>
  rotate <0, 30, 0>
  translate <1.4, 1.1, 0>
}
