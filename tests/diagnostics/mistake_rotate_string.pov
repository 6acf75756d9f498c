// error: 5:22 expected a vector, found a string
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'numeric expression', string literal found instead
// Mistake: `rotate` given a string
sphere { 0, 1 rotate "y" }
