// shape_new_csg: the new shapes inside CSG: an isosurface minus a sphere sweep, a height field
// intersected with a sphere, and a sphere sweep merged with a box, transformed.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.7, 0> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
difference {
  isosurface { function { sqrt(x*x + y*y + z*z) - 0.9 } contained_by { box { -1, 1 } } }
  sphere_sweep { linear_spline 2, <-1.2, 0.3, -1.2>, 0.35, <1.2, 0.3, 1.2>, 0.35 }
  pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 }
  translate <-1.9, 1, 0.5>
}
intersection {
  height_field { function 24, 24 { 0.6 + 0.3 * sin(9 * x) * cos(7 * y) } smooth
    translate <-0.5, 0, -0.5> scale <2, 1.2, 2> }
  sphere { <0, 0.2, 0>, 0.9 }
  pigment { rgb <0.2, 0.5, 0.9> }
  translate <0, 0.4, 0.6>
}
merge {
  sphere_sweep { cubic_spline 4, <-0.6, -0.6, 0>, 0.2, <-0.4, 0, 0>, 0.25, <0.4, 0.3, 0>, 0.25, <0.6, 1, 0>, 0.2 }
  box { <-0.3, -0.3, -0.3>, <0.3, 0.3, 0.3> rotate <20, 30, 0> }
  pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.4 }
  rotate <0, 0, -20> translate <1.9, 1, 0.3>
}
