// Alpha output (+UA): four boxes (opaque red; transmit 0.5 green; filter 0.5 green; transmit
// 0.25 blue with reflection 0.5 over the lower half) before a background whose filter F and
// transmit T come from Declare=F=.. / Declare=T=... tests/integration/povray_cli.rs holds the
// RGBA values povray 3.7 wrote for it at 8x6 (`povray -D +Ialpha.pov +W8 +H6 +UA Declare=T=1`).
#version 3.7;
global_settings { assumed_gamma 1 }
#ifndef (T) #declare T = 0; #end
#ifndef (F) #declare F = 0; #end
background { rgbft <0.2, 0.3, 0.4, F, T> }
camera { orthographic location <0, 0, -5> look_at 0 right x*4 up y*3 }
light_source { <0, 0, -10> rgb 1 }
box { <-2, -1.5, 0>, <-1, 1.5, 1> pigment { rgb <1, 0, 0> } finish { ambient 1 diffuse 0 } }
box { <-1, -1.5, 0>, <0, 1.5, 1> pigment { rgbt <0, 1, 0, 0.5> } finish { ambient 1 diffuse 0 } }
box { <0, -1.5, 0>, <1, 1.5, 1> pigment { rgbf <0, 1, 0, 0.5> } finish { ambient 1 diffuse 0 } }
box { <1, -1.5, 0>, <2, 0, 1> pigment { rgbt <0, 0, 1, 0.25> }
  finish { ambient 1 diffuse 0 reflection 0.5 } }
