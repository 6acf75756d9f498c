// error: 5:28 expected an expression, found `,`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'numeric expression', ,  found instead
// Mistake: two commas in a row inside a vector
sphere { 0, 1 translate <1,, 2> }
