// error: 5:9 expected the distance, found the end of the block
// error-text: after this
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: plane without its distance
plane { y }
