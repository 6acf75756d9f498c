// The shapes3.inc macros whose POV-Ray text is a text macro (it opens and closes braces
// under separate #if directives): segments of objects, tube rings and tori, round tube
// polygons and round cylinder tubes, each with a few argument sets, on a 4 x 4 grid.
// shapes3.png is POV-Ray 3.7's render with its own shapes3.inc, made like the reference
// images (povray -D +Ishapes3.pov +Oshapes3.png +W160 +H120 +WT1 -GA); the includes test
// renders this scene with durer's embedded shapes3.inc and with POV-Ray's and compares.
#version 3.7;
#include "shapes3.inc"
camera { location <0, 0, -24> look_at <0, 0, 0> angle 40 }
light_source { <-5, 8, -12>, rgb 1 }
light_source { <6, 3, -6>, rgb 0.5 }
background { rgb <0.2, 0.3, 0.5> }
#declare Tan = pigment { rgb <1, 0.6, 0.3> }
#macro Place(Shape, Column, Row)
  object { Shape rotate <-30, 20, 0> pigment { Tan } translate <(Column - 1.5) * 4, (1.5 - Row) * 3.2, 0> }
#end
Place(Segment_of_Object(sphere { 0, 1 }, 90), 0, 0)
Place(Segment_of_Object(box { -1, 1 }, -120), 1, 0)
Place(Segment_of_Object(torus { 1, 0.3 }, 250), 2, 0)
Place(Segment_of_Object(sphere { 0, 1 }, 0), 3, 0)
Place(Segment_of_CylinderRing(1, 0.5, 1, 90), 0, 1)
Place(Segment_of_CylinderRing(0.5, 1, 1.5, -200), 1, 1)
Place(Segment_of_CylinderRing(1, 0, -1, 400), 2, 1)
Place(Segment_of_Torus(1, 0.3, 100), 3, 1)
Place(Segment_of_Torus(1, 0.3, -270), 0, 2)
Place(Round_N_Tube_Polygon(6, 0.1, 1, 0.3, 0, 0), 1, 2)
Place(Round_N_Tube_Polygon(5, 0.1, 1, 0.3, 1, 1), 2, 2)
Place(Round_N_Tube_Polygon(3.5, -0.2, 1, 1.5, 0.5, 0), 3, 2)
Place(Round_N_Tube_Polygon(4, 0.15, 1, 1, 1, 0), 0, 3)
Place(Round_Cylinder_Tube(<-1, 0, 0>, <1, 1, 0>, 0.6, 0.1, 1, 0), 1, 3)
Place(Round_Cylinder_Tube(<-1, 0, 0>, <1, 1, 0>, 0.6, 0.1, 0, 1), 2, 3)
Place(Round_Cylinder_Tube(<-1, 0, 0>, <1, 0, 0>, 0.2, 0.3, 1, 0), 3, 3)
