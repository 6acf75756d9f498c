// shape_isosurface: a user function (sphere blended with a wave) in a box container, an
// internal function (f_torus) in a sphere container, and an open container cutting a box
// function.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.6, 0> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
#declare f_torus = function { internal(70) } // as functions.inc declares it
#declare Radius = 0.8;
#declare Wavy = function { sqrt(x*x + y*y + z*z) - Radius + 0.08 * sin(8 * x) * cos(6 * y) }
isosurface {
  function { Wavy(x, y, z) }
  contained_by { box { -1, 1 } }
  max_gradient 2
  pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 }
  translate <-1.9, 1, 0.5>
}
isosurface {
  function { f_torus(x, y, z, 0.7, 0.25) }
  contained_by { sphere { 0, 1 } }
  pigment { rgb <0.2, 0.5, 0.9> }
  rotate <-60, 0, 0>
  translate <0, 1, 0>
}
isosurface {
  function { max(abs(x), abs(y), abs(z)) - 0.9 }
  contained_by { sphere { 0, 1.1 } }
  open
  pigment { rgb <0.3, 0.8, 0.3> }
  rotate <0, 30, 0>
  translate <1.9, 1, 0.5>
}
