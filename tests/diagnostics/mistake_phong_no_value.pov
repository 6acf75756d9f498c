// error: 5:34 expected a float, found the end of the block
// error-text: after this
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: `phong` without its value
sphere { 0, 1 texture { finish { phong } } }
