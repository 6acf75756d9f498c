// error: 5:22 a matrix has 12 numbers, found 9
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'numeric expression', > found instead
// Mistake: `matrix` with 9 values instead of 12
sphere { 0, 1 matrix <1, 0, 0, 0, 1, 0, 0, 0, 1> }
