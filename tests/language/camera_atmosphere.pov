// Camera types, focal blur and atmospheric blocks evaluate, also through identifiers.
#version 3.7;
#declare Wide = camera { fisheye location <0, 1, -3> look_at 0 angle 200 }
camera { Wide rotate y*10 }
camera { spherical angle 360, 180 location 0 }
camera { spherical angle 270 90 }
camera { cylinder 3 angle 120 up y*2 }
camera { ultra_wide_angle angle 240 } camera { panoramic } camera { omnimax } camera { orthographic }
camera { location <0, 1, -5> look_at 0 aperture 0.3 blur_samples 4, 32 focal_point 0 confidence 0.8 variance 1/500 }
camera { aperture 0.3 blur_samples 10 }
#declare Haze = fog { fog_type 2 distance 5 colour rgbt <1, 1, 1, 0.2> fog_offset 1 fog_alt 0.5 up y rotate x*5 }
fog { Haze }
fog { Haze distance 10 }
fog { distance 3 rgb 0.5 turbulence 0.3 turb_depth 0.2 octaves 3 omega 0.4 lambda 2.5 translate x }
#declare Sky = sky_sphere { pigment { gradient y colour_map { [0 rgb 1] [1 rgb <0, 0, 1>] } } emission 1.2 }
sky_sphere { Sky rotate z*5 }
sky_sphere { pigment { rgb <0.2, 0.3, 0.5> } pigment { rgbt <1, 1, 1, 0.5> } scale 2 }
#declare Bow = rainbow { angle 42 width 5 direction <0, 0, 1> colour_map { [0 rgbt 1] [1 rgb <1, 0, 0>] } }
rainbow { Bow jitter 0.01 arc_angle 120 falloff_angle 40 up y distance 100 rotate y*20 }
