// error: 5:14 `vlength` takes 1 argument, found 2
// (durer prints no help line)
// POV-Ray: Parse Error: Expected ')', ,  found instead
// Mistake: `vlength` with two arguments
#declare A = vlength(1, 2);
