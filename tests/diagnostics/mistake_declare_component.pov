// error: 6:11 a vector component cannot be assigned
// error-text: declare the whole vector again, as in `#declare P = <5, P.y, P.z>;`
// POV-Ray: Parse Error: Expected '=', . (period) found instead
// Mistake: assigning one component of a vector
#declare P = <1, 2, 3>;
#declare P.x = 5;
