// error: 5:14 `pow` takes 2 arguments, found 1
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'numeric expression', ) found instead
// Mistake: `pow` with one argument
#declare A = pow(2);
