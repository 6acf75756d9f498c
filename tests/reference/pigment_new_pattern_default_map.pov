// A named pigment given a new pattern takes the new pattern's own default colour map when
// the old one had only its default (POV-Ray: bozo's map, not agate's).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0,0,-5> look_at 0 right x*4 up y*3 }
#declare P = pigment { agate }
plane { z, 0 pigment { P bozo scale 0.3 } finish { ambient 1 diffuse 0 } }
