// spotlight_falloff_over_90: a spotlight whose falloff (135) and radius (90, 120) reach past 90 degrees lights nothing behind the plane through it across its axis, as POV-Ray renders it (the wall above the lamps stays dark); durer lit up to the falloff angle (wild: hjw3001 BaseCity candles.inc turned a distant control tower yellow)
#version 3.7;
global_settings { assumed_gamma 1 ambient_light 0 }
camera { location <0, 1, -12> look_at <0, 1, 0> angle 60 }
light_source { <-2.5, 1, 0> rgb <1, 0.9, 0.3> spotlight point_at <-2.5, -1, 0> radius 90 falloff 135 }
light_source { <2.5, 1, 0> rgb <0.3, 0.9, 1> spotlight point_at <2.5, -1, 0> radius 120 falloff 170 tightness 0 }
light_source { <0, 8, -10> rgb 0.2 }
plane { z, 1 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
plane { y, -1 pigment { checker rgb 1 rgb 0.4 } finish { ambient 0 diffuse 1 } }
sphere { <0, 0, -1>, 1 pigment { rgb <0.9, 0.3, 0.2> } finish { ambient 0 diffuse 1 } }
