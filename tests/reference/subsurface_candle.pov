// subsurface_candle: a wax blob candle (translucency in millimetres, 40 mm per unit) on a
// subsurface marble plane, lit from the side and from behind: the dipole's blur of the
// candle's terminator and shadow, the plane's doubled diffuse light, specular highlights kept
#version 3.7;
global_settings { assumed_gamma 1 mm_per_unit 40 ambient_light 0.3 subsurface { samples 80, 16 } }
camera { location <0, 2.2, -4> look_at <0, 0.9, 0> angle 45 }
light_source { <-30, 30, -30> rgb 1 }
light_source { <20, 15, 30> rgb 0.4 }
plane { y, 0
  pigment { rgb <0.83, 0.79, 0.75> }
  finish { diffuse 0.8 specular 0.6 subsurface { translucency <0.4562, 0.3811, 0.3325> } }
  interior { ior 1.5 }
}
blob {
  threshold 0.5
  cylinder { <0, 0, 0>, <0, 2, 0>, 1, 1 }
  sphere { <0, 2.5, 0>, 0.8, -2 }
  sphere { <0, -0.52, 0>, 0.8, -2 }
  texture {
    pigment { rgb <0.8, 0.5, 0.01> }
    finish { diffuse 0.6 specular 0.6 roughness 0.1 subsurface { translucency <5, 3, 1> * 0.5 } }
  }
  interior { ior 1.45 }
}
