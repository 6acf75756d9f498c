// error: 6:14 `.t` does not exist on a 3-component vector
// (durer prints no help line)
// POV-Ray: Parse Error: Bad operands for period operator.
// Mistake: `.t` of a three-component vector
#declare V = <1, 2, 3>;
#declare A = V.t;
