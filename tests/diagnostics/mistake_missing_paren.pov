// error: 5:20 expected a directive, block or value, found `;`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected ')', ; found instead
// Mistake: expression without its closing `)`
#declare A = (1 + 2;
