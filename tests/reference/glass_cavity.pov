// glass_cavity: an air bubble cut out of glass by difference is entered from the glass and left into it (it shows the sky above it upright, as povray refracts there), with and without an interior of its own
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 15 }
light_source { <500, 50, -5> rgb 1 }
camera { location <1.2, 1, -4> look_at <0, 0.9, 0> angle 45 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.3, 0.05, 0.15>] [1 rgb 1] } translate -0.1*y } }
plane { y, 0 pigment { checker rgb 1 rgb <0, 0, 1> scale 0.5 } }
difference {
  box { <-1.1, 0, -0.5>, <-0.1, 1.8, 0.5> pigment { rgbf 1 } interior { ior 1.5 } }
  sphere { <-0.6, 0.9, 0>, 0.35 pigment { rgbf 1 } }
}
difference {
  box { <0.1, 0, -0.5>, <1.1, 1.8, 0.5> pigment { rgbf 1 } finish { reflection { 0, 1 fresnel } } interior { ior 1.5 } }
  sphere { <0.6, 0.9, 0>, 0.35 pigment { rgbf 1 } finish { reflection { 0, 1 fresnel } } interior { ior 1.2 } }
}
