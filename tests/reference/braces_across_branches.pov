// braces_across_branches: blocks opened in one #if/#switch branch and closed in another or after #end, as real scenes write them; the file is run token by token
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Smooth = 1;
camera { location <0, 1, -5> look_at 0 }
light_source { <3, 5, -5> rgb 1 }
#if (Smooth)
  merge {
#else
  union {
#end
    sphere { <-0.5, 0, 0>, 0.8 }
    sphere { <0.5, 0, 0>, 0.8 }
    pigment { rgbf <1, 0.2, 0.1, 0.5> }
  }
#declare K = 2;
#switch (K)
  #case (1)
    box { -1, 1
  #break
  #case (2)
    cylinder { <0, -1, 2>, <0, 1, 2>, 0.5
  #break
#end
    pigment { rgb <0.2, 0.3, 1> }
  }
#for (I, 0, 2)
  sphere { <I - 1, -1, -1>, 0.3
  #if (I = 1) pigment { rgb <0.1, 0.8, 0.2> } } #else pigment { rgb <1, 0.9, 0.1> } } #end
#end
plane { y, -1.3 pigment { checker rgb 1 rgb 0.5 } }
