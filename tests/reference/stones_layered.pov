// Tests: stones.inc's layered stone textures on six balls: crackle layers (T_Stone25),
// granite under gradient and agate layers with classic turbulence (T_Stone26), onion over
// granite (T_Stone42), a granite normal under wrinkles (T_Stone44), granite and marble
// building blocks with a crack overlay (T_Stone5) and agate_turb with granite (T_Stone43).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"
#include "stones.inc"

camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * 6 up y * 4.5 }
light_source { <-4, 6, -12> rgb 1 }
background { rgb <0.15, 0.2, 0.3> }

#macro Ball(Column, Row, Stone)
  sphere { <-2 + 2 * Column, 1 - 2 * Row, 0>, 0.95 texture { Stone } }
#end

Ball(0, 0, T_Stone25)
Ball(1, 0, T_Stone26)
Ball(2, 0, T_Stone42)
Ball(0, 1, T_Stone44)
Ball(1, 1, T_Stone5)
Ball(2, 1, T_Stone43)
