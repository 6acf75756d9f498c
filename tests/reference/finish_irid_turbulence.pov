// finish_irid_turbulence: irid `turbulence` varying the film thickness around `thickness`
// (5 octaves of noise turbulence at the world point), at three amounts and thicknesses
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at <0, 0, 0> angle 36 }
light_source { <150, 150, -2500> rgb 0.9 }
#macro IridBall(Where, Thickness, Turbulence)
  sphere { Where, 0.9 pigment { rgb 1 }
    finish { diffuse 0.3 specular 0.6 roughness 0.01 irid { 0.6 thickness Thickness turbulence Turbulence } } }
#end
IridBall(<-2, 1, 0>, 0.3, 0.25)
IridBall(< 0, 1, 0>, 0.5, 0.75)
IridBall(< 2, 1, 0>, 1.5, 0.5)
IridBall(<-1, -1, 0>, 0.8, 1)
IridBall(< 1, -1, 0>, 0.2, 2)
