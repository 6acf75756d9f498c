// block_pattern_missing_entries: block patterns given fewer entries than they have: colours left out take the pattern's defaults (brick: grey mortar, red brick), pigments left out after a pigment block are black
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0, 0> angle 60 }
light_source { <3, 10, -5> rgb 1 }
plane { y, 0 pigment { checker pigment { rgb <0.1, 0.8, 0.2> } } clipped_by { box { <-6, -1, -4>, <-2, 1, 4> } } }
plane { y, 0 pigment { brick rgb <0.9, 0.9, 0.2> scale 0.1 } clipped_by { box { <-2, -1, -4>, <2, 1, 4> } } }
plane { y, 0 pigment { hexagon rgb <0.9, 0.3, 0.1> scale 0.5 } clipped_by { box { <2, -1, -4>, <6, 1, 0> } } }
plane { y, 0 pigment { brick } scale 0.08 clipped_by { box { <2, -1, 0>, <6, 1, 4> } } }
