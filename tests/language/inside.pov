// `inside` for many shapes, CSG, inverse and transforms: each line lists, for 60 random
// points, whether POV-Ray 3.7 found the point inside (1) or not (0).
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
#declare Objects = array[17] {
  sphere { <0.2,0.1,0>, 1 }
  box { <-1,-0.5,-0.7>, <0.8,1,0.6> rotate <10,20,30> }
  cylinder { <-1,0,0>, <1,0.3,0>, 0.6 }
  cylinder { <-1,0,0>, <1,0.3,0>, 0.6 open }
  cone { <0,-1,0>, 1, <0,1,0>, 0.2 }
  torus { 0.8, 0.3 rotate x*40 }
  plane { <1,1,0>, 0.2 }
  union { sphere { -x*0.5, 0.6 } box { 0, 1 } }
  merge { sphere { -x*0.5, 0.6 } box { 0, 1 } }
  intersection { sphere { 0, 1 } box { -0.5, 2 } }
  difference { sphere { 0, 1 } cylinder { -2*z, 2*z, 0.4 } }
  sphere { 0, 1 inverse }
  difference { box { -1, 1 } sphere { 0, 1.2 } inverse }
  sphere { 0, 1 scale <1.5,0.5,1> translate <0.3,0,0> rotate z*30 }
  quadric { <1,1,-1>, <0,0,0>, <0,0,0>, -0.5 }
  disc { 0, y, 1 }
  superellipsoid { <0.3, 0.7> scale 0.9 }
}
#declare Expected = array[17] {
  "000000000000110101000000000000000000000000000000000000010001",
  "000001000110000100000000100000000010000000001000100100000000",
  "000000000000000100000000000000000000000000100000000000000000",
  "000000010010000000000000000000001000000000001000000000000000",
  "100000100000000100000000001000000001000001100001000000000000",
  "000000000010000000000000000000100000010000000000000000010000",
  "111110010111100110111111111011100001010001000100101011101000",
  "000000000000000100000000000000000000000001000010000000000000",
  "000000000000001000000000000000000000000001000000011000000000",
  "000000000100000000000100000000000000000000000000000000000001",
  "000000010000000000000000000000000001001010100000000000000000",
  "111111111111111111111111111111101111110110001111101111111011",
  "110111111110111111111110111111111111110111111111111111011111",
  "001000000000110000000010000010000000000000010001100001000100",
  "011110101000010000010100000001100011000101000011001100001000",
  "010001111110010111101100101011010010000000101111011001110011",
  "000000010010010000000000000000000001000000000000000000010000"
}
#declare S = seed(11);
#for (I, 0, dimension_size(Objects,1)-1)
  #declare Line = "";
  #for (J, 0, 59)
    #declare P = <rand(S)*3-1.5, rand(S)*3-1.5, rand(S)*3-1.5>;
    #declare Line = concat(Line, str(inside(Objects[I], P),0,0));
  #end
  Check((strcmp(Line, Expected[I]) = 0), concat("inside object ", str(I,0,0), ": ", Line))
#end
// Points on surfaces: on a sphere is outside, on a box face or a plane inside.
#declare Sp = sphere{0,1}
#declare Bx = box{-1,1}
#declare Pl = plane{y,0}
#declare Cy = cylinder{0, y, 1}
#declare Tr = sphere { 0, 1 scale 2 translate x }
Check((!inside(Sp, <1,0,0>)), "a point on a sphere")
Check((inside(Bx, <1,0,0>)), "a point on a box face")
Check((inside(Pl, <0,0,0>)), "a point on a plane")
Check((!inside(Cy, <0,1,0>)), "a point on a cylinder cap")
Check((!inside(Cy, <1,0.5,0>)), "a point on a cylinder side")
Check((inside(Tr, <2.9,0,0>) & !inside(Tr, <3.1,0,0>)), "a transformed sphere")
// A mesh with an inside_vector is a solid: the same 60 random points as POV-Ray 3.7 sees them.
#declare Oct = mesh {
  #local P = array[6] { <1, 0, 0>, <-1, 0, 0>, <0, 1, 0>, <0, -1, 0>, <0, 0, 1>, <0, 0, -1> }
  #for (I, 0, 1) #for (J, 2, 3) #for (K, 4, 5) triangle { P[I], P[J], P[K] } #end #end #end
  inside_vector <0.2, 0.3, 1>
  scale <1.2, 0.8, 1> rotate z*20 translate x*0.1
}
#declare MeshSeed = seed(7);
#declare MeshInside = "";
#for (I, 0, 59)
  #local Pt = <rand(MeshSeed), rand(MeshSeed), rand(MeshSeed)> * 2.4 - 1.2;
  #declare MeshInside = concat(MeshInside, str(inside(Oct, Pt), 0, 0));
#end
Check(MeshInside = "000000000100000001000000000000000000010000000011000100010001", "inside a mesh with inside_vector")
