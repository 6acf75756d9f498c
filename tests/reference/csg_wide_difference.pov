// A difference with 401 children (a slab minus a 20x20 grid of cylinders and spheres) and a
// merge of 64 overlapping glassy spheres: wide CSG nodes, which durer indexes by child boxes.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -6> look_at <0, 0, 0.5> angle 45 }
light_source { <4, 10, -5> rgb 1 }
difference {
  box { <-2, -0.3, -2>, <2, 0.3, 2> }
  #for (I, 0, 19)
    #for (J, 0, 19)
      #local P = <-2 + (I + 0.5) / 5, 0, -2 + (J + 0.5) / 5>;
      #if (mod(I + J, 3) = 0)
        sphere { P + 0.3 * y, 0.09 }
      #else
        cylinder { P - y, P + y, 0.05 }
      #end
    #end
  #end
  pigment { rgb <1, 0.7, 0.4> }
}
merge {
  #for (I, 0, 63)
    sphere { <mod(I, 8) * 0.25 - 0.9, 0.9 + div(I, 8) * 0.05, 1.5 + div(I, 8) * 0.1>, 0.2 }
  #end
  pigment { rgbt <0.5, 0.8, 1, 0.5> }
}
plane { y, -0.3 pigment { checker rgb 1 rgb 0.4 } }
