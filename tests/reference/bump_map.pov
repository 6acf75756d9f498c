// bump_map: per-pixel tilts from neighbouring pixels' stored grey levels (a grey image on
// the floor, a colour image on a rotated box, bump_size given inside and after the block;
// use_index on a palette image: the heights are the palette indices themselves)
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { rgb <0.3, 0.4, 0.5> }
camera { location <0, 4, -4> look_at <0, 0, 0.3> angle 55 }
light_source { <-6, 3, -2> rgb 1 }
light_source { <4, 5, -6> rgb 0.4 }
plane { y, 0
  pigment { rgb <0.9, 0.85, 0.7> }
  normal { bump_map { png "images/bumps16.png" bump_size 2 } rotate x*90 scale 1.5 }
}
box { <-1, 0, -1>, <1, 0.8, 1>
  pigment { rgb <0.4, 0.6, 0.9> }
  normal { bump_map { png "images/colours16.png" interpolate 2 } bump_size 1.5 scale 0.7 }
  finish { phong 0.4 }
  rotate y*25 translate <1.5, 0, 1>
}
box { <-1, 0, -1>, <1, 0.3, 1>
  pigment { rgb <0.9, 0.5, 0.3> }
  normal { bump_map { png "images/palette8.png" use_index } bump_size 0.08 rotate x*90 scale 2 translate <-1, 0, -1> }
  translate <-1.7, 0, 0.3>
}
