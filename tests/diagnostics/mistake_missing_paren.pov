// error: 5:14 unclosed `(`
// error-text: add the matching `)`
// POV-Ray: Parse Error: Expected ')', ; found instead
// Mistake: expression without its closing `)`
#declare A = (1 + 2;
