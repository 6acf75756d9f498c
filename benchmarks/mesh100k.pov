// A mesh of 125,000 triangles: a rippled sheet written by #for loops into a
// mesh2, placed four times (object { Ident } shares the mesh).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6, -9> look_at <0, 0, 0> angle 50 }
light_source { <5, 12, -6> rgb 1 }
#declare N = 250;
#declare Height = function(U, V) { 0.15 * sin(12 * U) * cos(9 * V) + 0.1 * sin(25 * (U + V)) }
#declare Sheet = mesh2 {
  vertex_vectors {
    (N + 1) * (N + 1)
    #for (J, 0, N)
      #for (I, 0, N)
        #local U = I / N; #local V = J / N;
        <U * 2 - 1, Height(U, V), V * 2 - 1>
      #end
    #end
  }
  face_indices {
    N * N * 2
    #for (J, 0, N - 1)
      #for (I, 0, N - 1)
        #local A = J * (N + 1) + I;
        <A, A + 1, A + N + 2>, <A, A + N + 2, A + N + 1>
      #end
    #end
  }
  pigment { rgb <0.9, 0.7, 0.4> }
  finish { phong 0.5 }
}
object { Sheet translate <-1.1, 0, -1.1> }
object { Sheet translate <1.1, 0, -1.1> }
object { Sheet translate <-1.1, 0, 1.1> }
object { Sheet translate <1.1, 0, 1.1> }
plane { y, -0.5 pigment { rgb 0.5 } }
