// text_internal_fonts: `text { internal N }` is one of POV-Ray's built-in fonts, read from the font files it installs (1 timrom.ttf, 3 crystal.ttf; POV-Ray's own benchmark scene uses internal 1)
// needs: timrom.ttf
// needs: crystal.ttf
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 8, -6> rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
text { internal 1 "POV-Ray" 0.3, 0 pigment { rgb <0.9, 0.3, 0.2> } translate <-1.7, 0.1, 0> }
text { internal 3 "Text" 0.4, 0 pigment { rgb <0.2, 0.5, 0.9> } rotate y*20 translate <-0.8, 1.2, 0.8> }
