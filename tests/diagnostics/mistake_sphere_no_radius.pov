// error: 5:10 expected the radius, found the end of the block
// error-text: after this
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: sphere without its radius
sphere { <0, 0, 0> }
