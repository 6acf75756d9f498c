// error: 5:14 undefined identifier `I`
// (durer prints no help line)
// POV-Ray: Parse Error: Cannot assign uninitialized identifier.
// Mistake: counter used before it is declared
#declare I = I + 1;
