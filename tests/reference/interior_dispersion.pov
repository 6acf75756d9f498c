// Tests: dispersion: a glass prism and sphere split white light into coloured fringes.
// Band colours follow POV-Ray 3.7's measured spectrum (src/render/dispersion.rs).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 1.5, -6> look_at <0, 1, 0> angle 45 }
light_source { <-4, 8, -6> rgb 1 }
background { rgb 0 }
plane { z, 3 pigment { checker rgb 1 rgb 0 scale 0.5 } finish { ambient 1 diffuse 0 } }
prism { linear_sweep linear_spline -0.8, 0.8, 4, <-1, -0.6>, <1, -0.6>, <0, 1.1>, <-1, -0.6>
  rotate <-90, 0, 0> translate <-1.3, 1, 0>
  pigment { rgbf 1 } finish { ambient 0 diffuse 0 } interior { ior 1.5 dispersion 1.15 } }
sphere { <1.4, 1, 0>, 0.9 pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { ior 1.4 dispersion 1.1 dispersion_samples 12 } }
