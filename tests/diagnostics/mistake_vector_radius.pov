// error: 5:13 expected a float, found a vector
// (durer prints no help line)
// POV-Ray: Parse Error: Float expected but vector or color expression found.
// Mistake: vector where a float (radius) is expected
sphere { 0, <1, 1, 1> }
