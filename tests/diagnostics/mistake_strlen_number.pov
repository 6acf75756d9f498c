// error: 5:21 expected a string, found a float
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'string expression', float function 'float constant' found instead
// Mistake: `strlen` of a number
#declare A = strlen(5);
