// error: 5:10 `Ar` is not an array
// (durer prints no help line)
// POV-Ray: Parse Error: Expected '=', [ found instead
// Mistake: element of an undeclared array set
#declare Ar[0] = 1;
