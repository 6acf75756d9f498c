// interior_caustics: fake caustics under a bumpy transparent surface and a tilted glass
// box (every crossed surface brightens the light by 1 + |cos|^(45 caustics))
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -6> look_at <0, 0, 0> angle 60 }
light_source { <0, 100, 0> rgb 0.6 }
light_source { <-20, 30, -20> rgb 0.3 }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.8 } }
disc { <0, 0, 0>, y, 2 translate <-1.5, 2, 0.5> pigment { rgbf <0.8, 0.9, 1, 0.9> }
  interior { caustics 0.8 } normal { bumps 0.6 scale 0.3 } no_image }
box { <-0.8, -0.1, -0.8>, <0.8, 0.1, 0.8> rotate <8, 0, 12> translate <1.8, 1.5, 0>
  pigment { rgbf 1 } finish { specular 0.5 } interior { caustics 2 } }
sphere { <0.5, 2.5, -2>, 0.6 pigment { rgbt <1, 0.8, 0.6, 0.8> } interior { caustics 0.5 } no_image }
