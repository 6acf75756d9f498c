// error: 5:13 expected a float, found a string
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'numeric expression', string literal found instead
// Mistake: string where a number is expected
sphere { 0, "1" }
