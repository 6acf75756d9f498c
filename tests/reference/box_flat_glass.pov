// Tests: flat boxes (no thickness) of refracting glass: a ray enters and leaves at one point,
// so the floor shows through unbent, with a fresnel reflection on one and plain reflection
// on the other.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, -10, 5> look_at <0, 0, 0.5> angle 50 }
light_source { <10, -20, 30> rgb 1 }
sky_sphere { pigment { rgb <0.5, 0.6, 1> } }
plane { z, 0 pigment { checker rgb 1 rgb 0.3 } }
box { <-3.5, -2, 0.25>, <-0.5, 3, 0.25>
  material { texture { pigment { rgbt <0, 1, 0, 1> } finish { ambient 0 diffuse 0
    reflection { 0, 1 fresnel on } conserve_energy } } interior { ior 1.3 } } }
box { <0.5, -2, 0.25>, <3.5, 3, 0.25>
  material { texture { pigment { rgbt <0.3, 0.6, 0.3, 0.8> } finish { ambient 0.1
    reflection 0.3 } } interior { ior 1.5 } } }
