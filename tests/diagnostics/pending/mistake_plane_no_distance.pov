// error: 1:1 expected the distance, found the end of the block
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: plane without its distance
plane { y }
