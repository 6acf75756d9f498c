// error: 5:65 expected the number of lights along axis 2, found the end of the block
// error-text: after this
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: area_light with one count missing
light_source { <0, 5, 0> rgb 1 area_light <1, 0, 0>, <0, 0, 1>, 4 }
