// subsurface_shadow_edge: a translucent slab under an overhead light, half of it in the shadow of
// an unseen board; subsurface light blurs the shadow's edge by the dipole's profile
// (translucency 1 mm at 10 mm per unit) and single scattering adds a faint glow
#version 3.7;
global_settings { assumed_gamma 1 ambient_light 2 mm_per_unit 10 subsurface { samples 400, 40 } }
camera { location <0, 4, -1.5> look_at <0, 0, 0> angle 40 }
light_source { <0.5, 100, -0.3> rgb 1 }
box { <-10, 1, -10>, <0, 1.05, 10> pigment { rgb 0 } no_image }
box { <-1.5, -0.5, -1>, <1.5, 0, 1>
  pigment { rgb <0.8, 0.6, 0.4> }
  finish { ambient 0.05 diffuse 1 subsurface { translucency <1.5, 1, 0.5> } }
  interior { ior 1.3 }
}
