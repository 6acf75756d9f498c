// Meshes with an inside_vector are solids in CSG: an octahedron mesh cut from a box, a
// sphere intersected with it, and an inverted one in an intersection.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0, 0> angle 45 }
light_source { <4, 8, -6> rgb 1 }
#declare Octahedron = mesh {
  #local P = array[6] { <1, 0, 0>, <-1, 0, 0>, <0, 1, 0>, <0, -1, 0>, <0, 0, 1>, <0, 0, -1> }
  #for (I, 0, 1)
    #for (J, 2, 3)
      #for (K, 4, 5)
        triangle { P[I], P[J], P[K] }
      #end
    #end
  #end
  inside_vector <0.2, 0.3, 1>
}
difference {
  box { <-1.9, -0.6, -0.6>, <-0.7, 0.6, 0.6> }
  object { Octahedron scale 0.8 translate <-1.3, 0.2, -0.5> }
  pigment { rgb <1, 0.6, 0.3> }
}
intersection {
  sphere { 0, 0.75 }
  object { Octahedron }
  pigment { rgb <0.3, 0.7, 1> }
}
intersection {
  box { <0.8, -0.6, -0.6>, <2, 0.6, 0.6> }
  object { Octahedron scale 0.7 translate <1.4, 0, -0.4> inverse }
  pigment { rgb <0.5, 1, 0.4> }
}
// The same solid split into 32 triangles (a wide node: its triangles are indexed by box).
#declare Fine = mesh {
  #local P = array[6] { <1, 0, 0>, <-1, 0, 0>, <0, 1, 0>, <0, -1, 0>, <0, 0, 1>, <0, 0, -1> }
  #for (I, 0, 1)
    #for (J, 2, 3)
      #for (K, 4, 5)
        #local A = P[I]; #local B = P[J]; #local C = P[K];
        triangle { A, (A + B) / 2, (A + C) / 2 }
        triangle { B, (B + C) / 2, (A + B) / 2 }
        triangle { C, (A + C) / 2, (B + C) / 2 }
        triangle { (A + B) / 2, (B + C) / 2, (A + C) / 2 }
      #end
    #end
  #end
  inside_vector <0.3, 1, 0.2>
}
difference {
  box { <-0.5, -0.9, -1.4>, <0.5, -0.5, -0.9> }
  object { Fine scale 0.45 translate <0, -0.5, -1.15> }
  pigment { rgb <1, 0.9, 0.3> }
}
plane { y, -1 pigment { checker rgb 1 rgb 0.6 } }
