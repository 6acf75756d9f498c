// uv_mapping on bicubic patches: the patch parameters, mapped onto the default uv corners
// and onto corners given with uv_vectors.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3.5, -5> look_at <0, 0.2, 0> angle 50 }
light_source { <-3, 8, -6> rgb 1 }
#declare Checker = texture {
  uv_mapping pigment { checker rgb <1, 0.5, 0.1>, rgb <0.1, 0.3, 0.8> scale 0.125 }
}
#declare Patch = bicubic_patch { type 1 flatness 0 u_steps 4 v_steps 4
  uv_vectors <0.1, 0.2>, <0.9, 0>, <1, 0.7>, <0.3, 0.9>
  <-1, 0, -1>, <-0.3, 0.5, -1>, <0.3, 0.5, -1>, <1, 0, -1>,
  <-1, 0, -0.3>, <-0.3, 1, -0.3>, <0.3, 1, -0.3>, <1, 0, -0.3>,
  <-1, 0, 0.3>, <-0.3, 1, 0.3>, <0.3, 1, 0.3>, <1, 0, 0.3>,
  <-1, 0, 1>, <-0.3, 0.5, 1>, <0.3, 0.5, 1>, <1, 0, 1>
}
object { Patch texture { Checker } translate -1.2 * x }
bicubic_patch { type 0 u_steps 3 v_steps 3
  <-1, 0, -1>, <-0.3, 0.8, -1>, <0.3, 0.8, -1>, <1, 0, -1>,
  <-1, 0.4, -0.3>, <-0.3, 1, -0.3>, <0.3, 1, -0.3>, <1, 0.4, -0.3>,
  <-1, 0.4, 0.3>, <-0.3, 1, 0.3>, <0.3, 1, 0.3>, <1, 0.4, 0.3>,
  <-1, 0, 1>, <-0.3, 0.8, 1>, <0.3, 0.8, 1>, <1, 0, 1>
  texture { Checker } rotate y * 30 translate 1.2 * x
}
plane { y, -0.3 pigment { rgb 0.5 } }
