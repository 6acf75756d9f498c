// error: 5:7 expected the opposite corner, found the end of the block
// error-text: after this
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: box with one corner
box { <0, 0, 0> }
