// error: 5:12 a name cannot contain `-`
// error-text: names are letters, digits and `_`: write `my_radius`
// POV-Ray: Parse Error: Expected '=', - found instead
// Mistake: identifier with a hyphen
#declare my-radius = 2;
