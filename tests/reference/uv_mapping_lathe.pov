// uv_mapping on lathes of every spline kind: u around the Y axis, v along the curve (each
// segment an equal share).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.2, 0> angle 50 }
light_source { <-3, 8, -6> rgb 1 }
#declare Checker = texture {
  uv_mapping pigment { checker rgb <1, 0.5, 0.1>, rgb <0.1, 0.3, 0.8> scale <0.0625, 0.1, 1> }
}
lathe { linear_spline 4, <0.5, -1>, <1, 0>, <0.8, 1>, <0.4, 1.2>
  texture { Checker } translate -1.8 * x }
lathe { cubic_spline 6, <0.2, -1.2>, <0.5, -1>, <1, 0>, <0.6, 0.6>, <0.8, 1>, <0.4, 1.2>
  texture { Checker } rotate y * 30 }
lathe { quadratic_spline 5, <0.3, -1>, <0.5, -1>, <1, 0>, <0.7, 0.8>, <0.4, 1.2>
  texture { Checker } translate 1.8 * x }
lathe { bezier_spline 8, <0.3, -1>, <1, -1>, <1, -0.5>, <0.8, 0>, <0.8, 0>, <0.3, 0.5>,
  <1, 1>, <0.4, 1.2> texture { Checker } translate <0.9, 0, -1.5> }
plane { y, -1.3 pigment { rgb 0.5 } }
