// error: 1:1 expected the minor radius, found the end of the block
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: torus with one radius
torus { 1 }
