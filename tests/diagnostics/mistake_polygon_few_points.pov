// error: 5:30 expected a point, found the end of the block
// error-text: after this
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: polygon with fewer points than its count
polygon { 4, <0, 0>, <1, 0>, <1, 1> }
