// Tests: colour components first in a pigment that modifies a texture's (`texture { T pigment
// { transmit 0.6 filter 0.1 } }`) or after a pigment identifier start a black colour, as
// povray reads them; after a colour (`pigment { C green 0.5 }`) they modify it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> }
light_source { <-4, 8, -6>, rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.4 scale 0.8 } }
#declare RedT = texture { pigment { rgb <1, 0.1, 0.1> } finish { phong 0.4 } }
#declare GreenP = pigment { rgb <0.1, 1, 0.1> }
#declare Named = rgb <0.2, 0.2, 1>;
box { <-3, 0, -0.2>, <-1.2, 1.8, 0.2> texture { RedT pigment { transmit 0.6 filter 0.1 } } }
box { <-0.9, 0, -0.2>, <0.9, 1.8, 0.2> pigment { GreenP transmit 0.5 } }
box { <1.2, 0, -0.2>, <3, 1.8, 0.2> pigment { Named green 0.6 } }
sphere { <0, 0.6, 2>, 0.6 pigment { rgb <1, 0.7, 0.1> } }
