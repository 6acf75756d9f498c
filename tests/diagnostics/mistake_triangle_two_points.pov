// error: 5:30 expected a corner, found the end of the block
// error-text: after this
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: triangle with two vertices
mesh { triangle { <0, 0, 0>, <1, 0, 0> } }
