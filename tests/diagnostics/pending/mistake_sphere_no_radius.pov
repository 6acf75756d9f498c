// error: 1:1 expected the radius, found the end of the block
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: sphere without its radius
sphere { <0, 0, 0> }
