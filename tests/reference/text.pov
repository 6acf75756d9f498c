// text: TrueType glyphs (kerning, first-glyph left edge, per-character offset), two fonts.
// needs: timrom.ttf
// needs: cyrvetic.ttf
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
text { ttf "timrom.ttf" "AVAg%" 0.3, 0 pigment { rgb <0.9, 0.3, 0.2> } translate <-1.7, 0.1, 0> }
text { ttf "cyrvetic.ttf" "Text" 0.5, <0.1, 0> pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.5 } scale 0.8 rotate y*20 translate <-0.8, 1.2, 0.8> }
