// uv_mapping on ovus and parametric surfaces, which POV-Ray also gives uv coordinates: an
// ovus has a sphere's uv around the middle of its height (half the top radius up, or the
// top sphere's centre when that sphere swallows the bottom one); a parametric surface shows
// its own (u, v) parameters as they are, not rescaled to the unit square (its checker is
// coarse and its accuracy fine: POV-Ray finds the parameters of a hit only to about its
// accuracy).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3.5, -7> look_at <0, 0.2, 0> angle 45 }
light_source { <-4, 9, -7> rgb 1 }
#declare Checker = texture {
  uv_mapping pigment { checker rgb <1, 0.5, 0.1>, rgb <0.1, 0.3, 0.8> scale <0.0625, 0.1, 1> }
  finish { ambient 0.35 }
}
#declare Ramps = texture {
  uv_mapping pigment { gradient x color_map { [0 rgb <0, 0, 0.2>] [1 rgb <1, 1, 0.3>] } }
  finish { ambient 0.4 }
}
ovus { 1, 0.6 texture { Checker } rotate <-30, 20, 0> translate <-2.2, 0, 0> }
ovus { 0.4, 0.9 texture { Checker } rotate <20, 0, -30> translate <-0.3, 0.4, -1.5> }
ovus { 0.8, 1.1 texture { Ramps } rotate 40 * x translate <0.2, 0.4, 1.5> }
parametric {
  function { u } function { v } function { 0.25 * sin(4 * u) * v }
  <-0.6, 0.1>, <1.4, 1.3>
  contained_by { box { <-1, 0, -1>, <2, 1.5, 1> } } accuracy 0.0001
  texture {
    uv_mapping pigment { checker rgb <1, 0.5, 0.1>, rgb <0.1, 0.3, 0.8> scale <0.25, 0.2, 1> }
    finish { ambient 0.35 }
  }
  rotate -20 * y translate <1.4, -0.9, -0.8>
}
plane { y, -1.2 pigment { rgb 0.5 } }
