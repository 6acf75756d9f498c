// error: 6:25 undefined identifier `BallColor`
// error-text: did you mean `BallColour`?
// POV-Ray: Parse Error: No matching } in 'pigment', undeclared identifier 'BallColor' found instead
// Mistake: declared identifier misspelt (colour/color)
#declare BallColour = rgb <1, 0, 0>;
sphere { 0, 1 pigment { BallColor } }
