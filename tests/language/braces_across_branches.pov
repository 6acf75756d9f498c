// Braces opened in one #if/#case branch and closed in another, or after #end: POV-Ray reads
// its token stream, so real scenes write this; durer runs such a file token by token.
// (Checked with povray: this file parses there too.)
#version 3.7;
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end

#declare Smooth = 1;
#declare Pair =
#if (Smooth)
  merge {
#else
  union {
#end
    sphere { <-0.5, 0, 0>, 0.8 }
    sphere { <0.5, 0, 0>, 0.8 }
  }
Check(inside(Pair, <0.9, 0, 0>), "the branch's merge holds both spheres")
Check((abs(max_extent(Pair).x - 1.3) < 1e-6), "the block closed after #end")

#declare K = 2;
#switch (K)
  #case (1)
    #declare Shape = box { -1, 1
  #break
  #case (2)
    #declare Shape = cylinder { <0, -1, 0>, <0, 1, 0>, 0.5
  #break
#end
  translate 2*x }
Check((inside(Shape, <2.4, 0.9, 0>) & !inside(Shape, <2.6, 0, 0>)), "the case's cylinder, moved after #end")

#declare Count = 0;
#for (I, 0, 2)
  #declare Ball = sphere { <I, 0, 0>, 0.3
  #if (I = 1) scale 2 } #else } #end
  #declare Count = Count + max_extent(Ball).x;
#end
Check((abs(Count - (0.3 + 2.6 + 2.3)) < 1e-6), "each pass closes its own sphere")
camera { location <0, 0, -5> look_at 0 }

// A block whose keyword a branch chose (LDView writes `material` or `texture` by version).
#declare Chosen = sphere { 0, 1 #if (version >= 3.1) material #else texture #end { texture { pigment { rgb <1, 0, 0> } } } }
Check((abs(max_extent(Chosen).x - 1) < 1e-6), "the branch chose the block's keyword")

// rand() in the file's text draws when it is read, before the directives after it (a
// Truchet tiling drew each tile's rotations after all the tiles' choices; povray: R2 is the
// third number of seed 15, the object drew the first two).
#declare S15 = seed(15);
#declare First = rand(S15);
#declare Second = rand(S15);
#declare Third = rand(S15);
#declare R = seed(15);
#switch (1)
  #case (1) object { Pair #break
#end
  rotate x*90*rand(R) rotate y*90*rand(R) }
#declare R2 = rand(R);
Check((R2 = Third), "the object's two rand() calls drew before the #declare after it")
