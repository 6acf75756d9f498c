// error: 1:1 expected the opposite corner, found the end of the block
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: box with one corner
box { <0, 0, 0> }
