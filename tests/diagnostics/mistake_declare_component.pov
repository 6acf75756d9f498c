// error: 6:11 expected a directive, block or value, found `.`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected '=', . (period) found instead
// Mistake: assigning one component of a vector
#declare P = <1, 2, 3>;
#declare P.x = 5;
