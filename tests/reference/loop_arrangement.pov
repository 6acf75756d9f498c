// Objects placed by nested #for and #while loops, with colours computed from the indices.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -9> look_at <0, 0, 0> angle 50 }
light_source { <4, 10, -6> rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }

#for (Row, -3, 3)
  #for (Column, -3, 3)
    #local Height = 0.3 + 0.15 * (abs(Row) + abs(Column));
    box {
      <-0.4, 0, -0.4>, <0.4, Height, 0.4>
      pigment { rgb <(Row + 3) / 6, 0.5, (Column + 3) / 6> }
      translate <Column, 0, Row>
    }
  #end
#end
#declare Angle = 0;
#while (Angle < 360)
  sphere { <4.5, 0.3, 0>, 0.25 pigment { rgb <1, Angle / 360, 0.2> } rotate Angle * y }
  #declare Angle = Angle + 30;
#end
