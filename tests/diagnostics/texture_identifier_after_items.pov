// error: 6:33 a pigment identifier inside `texture` must come before its other items
// error-text: move it to the start of the texture

#declare Red = pigment { rgb <1, 0, 0> }
// POV-Ray refuses this too: identifiers go before the texture's other items.
sphere { 0, 1 texture { scale 2 Red } }
