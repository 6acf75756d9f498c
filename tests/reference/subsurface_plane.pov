// subsurface_plane: a subsurface plane (POV-Ray lights a surface that nothing closes behind
// twice as brightly) under a subsurface box (closed) and a classic diffuse box, lit at an
// angle: Fresnel transmission in and out, mm_per_unit scaling the translucency
#version 3.7;
global_settings { assumed_gamma 1 mm_per_unit 40 subsurface { samples 250, 30 } }
camera { location <0, 3, -4> look_at <0, 0.3, 0> angle 45 }
light_source { <-20, 30, -15> rgb 1 }
plane { y, 0
  pigment { checker rgb <0.83, 0.79, 0.75> rgb 0.2 scale 0.5 }
  finish { diffuse 0.8 subsurface { translucency <0.4562, 0.3811, 0.3325> } }
  interior { ior 1.5 }
}
box { <-1.2, 0, -0.4>, <-0.2, 0.8, 0.4>
  pigment { rgb <0.9, 0.6, 0.3> }
  finish { diffuse 0.9 specular 0.3 subsurface { translucency 0.5 } }
  interior { ior 1.4 }
}
box { <0.3, 0, -0.4>, <1.3, 0.8, 0.4> pigment { rgb <0.9, 0.6, 0.3> } finish { diffuse 0.9 } }
