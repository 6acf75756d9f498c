// error: 5:12 expected a directive, block or value, found `-`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected '=', - found instead
// Mistake: identifier with a hyphen
#declare my-radius = 2;
