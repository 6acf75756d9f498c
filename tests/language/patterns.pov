// Every pattern, pattern modifier and warp evaluates (no rendering); the values are checked
// by the pattern_* reference scenes and the unit tests in src/pattern.
#version 3.7;
global_settings { assumed_gamma 1.0 noise_generator 3 }
#declare Map = color_map { [0 rgb 0] [1 rgb 1] }
#declare Patterns = array[34] {
  pigment { agate agate_turb 0.5 color_map { Map } },
  pigment { boxed color_map { Map } },
  pigment { bozo turbulence 0.3 octaves 3 omega 0.6 lambda 2.5 color_map { Map } },
  pigment { brick rgb 0.5, rgb <0.7, 0.2, 0.1> brick_size <2, 1, 1.5> mortar 0.1 },
  pigment { brick brick_size 2 mortar 0.2 },
  pigment { bumps noise_generator 1 color_map { Map } },
  pigment { cells color_map { Map } },
  pigment { checker rgb 1, rgb 0 turbulence <0.1, 0.2, 0> },
  pigment { crackle form <1, 0, 0> metric 1 offset 0.1 solid color_map { Map } },
  pigment { cubic rgb 0, rgb 0.2, rgb 0.4, rgb 0.6, rgb 0.8, rgb 1 },
  pigment { cylindrical color_map { Map } sine_wave },
  pigment { dents color_map { Map } scallop_wave },
  pigment { gradient <1, 1, 0> color_map { Map } cubic_wave frequency 2 phase 0.5 },
  pigment { granite color_map { Map } poly_wave },
  pigment { hexagon rgb 0, rgb 0.5, rgb 1 },
  pigment { julia <0.3, 0.2>, 20 exponent 3 interior 1, 2 exterior 2, 0.5 color_map { Map } },
  pigment { leopard color_map { Map } poly_wave 2 },
  pigment { magnet 1 mandel 10 color_map { Map } },
  pigment { magnet 2 julia <1, 0.5>, 10 exterior 7, 3 color_map { Map } },
  pigment { mandel 25 color_map { Map } },
  pigment { marble turbulence 0.5 ramp_wave color_map { Map } },
  pigment { onion color_map { Map } },
  pigment { planar color_map { Map } triangle_wave },
  pigment { quilted control0 0.2 control1 0.8 color_map { Map } },
  pigment { radial frequency 6 color_map { Map } },
  pigment { ripples color_map { Map } },
  pigment { spherical color_map { Map } },
  pigment { spiral1 4 color_map { Map } },
  pigment { spiral2 2 color_map { Map } },
  pigment { spotted color_map { Map } },
  pigment { square rgb 0, rgb 0.3, rgb 0.6, rgb 1 },
  pigment { tiling 1 color_map { Map } },
  pigment { pavement number_of_sides 4 number_of_tiles 3 pattern 2 form 1 interior 1 exterior 2 },
  pigment { triangular rgb 0, rgb 0.2, rgb 0.4, rgb 0.6, rgb 0.8, rgb 1 }
}
#declare MorePatterns = array[3] {
  pigment { waves color_map { Map } },
  pigment { wood turbulence 0.1 color_map { Map } },
  pigment { wrinkles color_map { Map } }
}
#declare Warped = pigment {
  checker rgb 1, rgb 0
  scale 0.5
  warp { repeat x * 2 offset <0, 0.5, 0> flip <1, 0, 0> }
  rotate 30 * y
  warp { black_hole <1, 0, 0>, 0.5 falloff 3 strength 1.5 inverse repeat <2, 2, 2> turbulence 0.1 }
  warp { turbulence <0.3, 0.1, 0> octaves 4 omega 0.4 lambda 3 }
  warp { cylindrical orientation y dist_exp 1 }
  warp { spherical dist_exp 0.5 }
  warp { toroidal major_radius 2 }
  warp { planar }
  warp { planar y, 1 }
  translate x
}

// A pigment identifier may come before the pattern (POV-Ray reads it first); value printed
// by povray 3.7.
#declare Base = pigment { rgb <1, 0, 0> }
#declare Stirred = pigment { Base gradient x color_map { [0 rgb 0] [1 rgb 1] } }
#declare StirredFn = function { pigment { Stirred } }
#if (abs(StirredFn(0.25, 0, 0).red - 0.25) > 1e-6)
  #error "failed: a pigment identifier before a pattern"
#end
