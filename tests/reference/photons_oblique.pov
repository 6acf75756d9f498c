// photons_oblique: caustics from a light low in the sky. Photons through a pane of index 1
// light the floor as the light does at any angle and brilliance (a photon weighs
// cos^(brilliance-1)), the light's fade follows each photon's whole path, and a glass
// pane with `conserve_energy` passes only what its Fresnel reflection leaves.
#version 3.7;
global_settings { photons { spacing 0.03 } }
camera { location <0, 7, -5> look_at <0, 0, 0> angle 50 }
light_source { <-10, 5, 2> rgb 1.6 fade_distance 8 fade_power 2 }
plane { y, 0 pigment { rgb 0.8 } finish { diffuse 0.8 brilliance 0.6 } }
box {
  <-2.5, 1, -2.5>, <-0.5, 1.2, -0.5>
  pigment { rgbf 1 }
  interior { ior 1 }
  photons { target refraction on reflection off }
}
box {
  <-2, 0.5, 0.5>, <-1.6, 2.5, 2.5>
  pigment { rgbf <0.8, 0.9, 1, 1> }
  finish { reflection { 0, 1 fresnel on } conserve_energy }
  interior { ior 2 }
  photons { target refraction on reflection on }
}
