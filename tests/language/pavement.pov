// The pavement pattern: values at a few points (measured with POV-Ray 3.7) through a
// black-to-white colour map, for squares, triangles and hexagons, and settings that wrap.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
#macro Near(A, B) (abs((A) - (B)) < 1e-5) #end
#declare Map = color_map { [0 rgb 0] [1 rgb 1] }
// One square per tile: 1 on the border, 0 in the middle.
#declare Square = function { pigment { pavement number_of_sides 4 number_of_tiles 1
  color_map { Map } } }
#declare Value = Square(0.5, 0, 0.5).red;
Check(Near(Value, 0), "square centre")
#declare Value = Square(0.3, 7, 0.2).red;
Check(Near(Value, 0.6), "square at (0.3, 0.2)")
// The L tromino's turn with form 1: cut straight across.
#declare Turn = function { pigment { pavement number_of_sides 4 number_of_tiles 3 pattern 2
  form 1 color_map { Map } } }
#declare Value = Turn(0.75, 0, 1.5).red;
Check(Near(Value, 0.5), "L turn, form 1")
// Single triangles (the default): 0 at the incentre.
#declare Triangle = function { pigment { pavement color_map { Map } } }
#declare Value = Triangle(0.5, 0, sqrt(3) / 6).red;
Check(Near(Value, 0), "triangle incentre")
// Single hexagons (side 1, centred at (1, 0) and its lattice): 0 in the middle, and
// 1 - d / (sqrt(3) / 6) along a border.
#declare Hexagon = function { pigment { pavement number_of_sides 6 color_map { Map } } }
#declare Value = Hexagon(1, 0, 0.1).red;
Check(Near(Value, 0), "hexagon middle")
#declare Value = Hexagon(-0.5, 0, 0.125).red;
Check(Near(Value, 1 - 0.125 / (sqrt(3) / 6)), "hexagon border band")
// exterior -1 wraps to 0 (a square corner), exterior 4 to 1 (a cut corner).
#declare Wrapped = function { pigment { pavement number_of_sides 4 exterior -1
  color_map { Map } } }
#declare Value = Wrapped(0.1, 0, 0.1).red;
Check(Near(Value, 0.8), "exterior -1")
#declare Cut = function { pigment { pavement number_of_sides 4 exterior 4
  color_map { Map } } }
#declare Value = Cut(0.2, 0, 0.2).red;
Check(Near(Value, 1), "exterior 4")
