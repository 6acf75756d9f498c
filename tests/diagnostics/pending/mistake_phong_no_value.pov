// error: 1:1 expected a float, found the end of the block
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: `phong` without its value
sphere { 0, 1 texture { finish { phong } } }
