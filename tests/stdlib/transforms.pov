// Builds transforms with every macro of transforms.inc and writes, one `name values..` line
// each, where they take the origin and the points x, y and z (a box shrunk to a point, moved
// by the transform, and read back from its bounding box); tests/integration/includes.rs runs
// this with durer's embedded transforms.inc and compares the result with POV-Ray's output.
#version 3.7;
#include "transforms.inc"
#fopen Out "probe.txt" write
#macro Moved(Point, Transform)
  #local Moved_Box = box { Point, Point transform { Transform } }
  ((min_extent(Moved_Box) + max_extent(Moved_Box)) / 2)
#end
#macro Put(Name, Transform)
  #write (Out, Name, " ", vstr(3, Moved(<0, 0, 0>, Transform), " ", 0, 9), "  ",
    vstr(3, Moved(x, Transform), " ", 0, 9), "  ", vstr(3, Moved(y, Transform), " ", 0, 9),
    "  ", vstr(3, Moved(z, Transform), " ", 0, 9), "\n")
#end

#declare Directions = array[7] {
  <1, 2, 3>, <-0.5, 0.25, 2>, <0, 1, 0>, <0, -1, 0>, <3, -3, 0.5>, <1, 2, 3>, <0, 0, -2>
}
#declare Thing = union {
  box { <-1, -2, -3>, <2, 3, 4> }
  sphere { <2, 1, 0>, 2.5 }
}
#for (I, 0, 5)
  #declare A = Directions[I];
  #declare B = Directions[I + 1];
  #declare S = str(I, 0, 0);
  Put(concat("Matrix_Trans ", S), Matrix_Trans(x + A * 0.3, y - B * 0.2, z + A * 0.1, <I, 2, -1>))
  Put(concat("Shear_Trans ", S), Shear_Trans(x * 2 - B * 0.1, y + A * 0.2, z * 0.5 + B * 0.1))
  Put(concat("Axis_Rotate_Trans ", S), Axis_Rotate_Trans(A, 37 * I - 50))
  Put(concat("Rotate_Around_Trans ", S), Rotate_Around_Trans(B * 20, A))
  Put(concat("Reorient_Trans ", S), Reorient_Trans(A, B))
  Put(concat("Reorient_Trans back ", S), Reorient_Trans(B, A))
  Put(concat("Point_At_Trans ", S), Point_At_Trans(A))
  Put(concat("Axial_Scale_Trans ", S), Axial_Scale_Trans(A, 0.5 + I))
  Put(concat("Center_Trans ", S), Center_Trans(object { Thing scale 1 + I / 3 translate A }, <I, 1, 0>))
  Put(concat("Align_Trans ", S), Align_Trans(object { Thing scale 1 + I / 4 }, B, A))
  Put(concat("Align_Trans float ", S), Align_Trans(Thing, B, I - 2))
#end
Put("Reorient_Trans same", Reorient_Trans(<1, 2, 3>, <2, 4, 6>))
Put("Reorient_Trans opposite", Reorient_Trans(<1, 2, 3>, <-1, -2, -3>))

#declare Path = spline {
  natural_spline
  0, <0, 0, 0>, 1, <1, 1, 0>, 2, <2, 0, 1>, 3, <3, 1, 1>, 4, <2, 2, 3>
}
#declare Linear_Path = spline { linear_spline 0, <0, 0, 0>, 1, <4, 0, 1>, 2, <4, 1, 3> }
#for (Time, 0.5, 3.5, 0.75)
  #declare S = str(Time, 0, 2);
  Put(concat("Spline_Trans ", S), Spline_Trans(Path, Time, y, 0.1, 0.5))
  Put(concat("Spline_Trans tilted ", S), Spline_Trans(Path, Time, <0.2, 1, 0.1>, 0.05, 2))
  Put(concat("Spline_Trans linear ", S), Spline_Trans(Linear_Path, Time / 2, y, 0.01, 1))
#end
#fclose Out
