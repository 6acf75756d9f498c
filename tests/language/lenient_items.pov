// Items POV-Ray 3.7 reads more leniently than its manual says, as real scenes write them;
// each was checked with povray (this file parses there too).
#version 3.7;
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end

// A value that cannot be called, then a parenthesised float: two items, not a call.
#declare Down = plane { y (-1) }
Check((vlength(trace(Down, <0, 5, 0>, -y) - <0, -1, 0>) < 1e-9), "`y (-1)` is a normal and a distance")
#declare V = <0, 0, 1>;
#declare Back = plane { V (2) }
Check((inside(Back, <0, 0, 1.5>) & !inside(Back, <0, 0, 2.5>)), "a vector identifier, then a float in parentheses")

// Pigment, finish and normal identifiers straight inside `texture`, before its other items.
#declare P = pigment { rgb <1, 0, 0> }
#declare F = finish { phong 1 }
#declare N = normal { bumps 0.5 }
#declare T1 = texture { P F N }
#declare T2 = texture { T1 P scale 2 }
#declare T3 = texture { N P F }
sphere { 0, 1 texture { T2 } }
