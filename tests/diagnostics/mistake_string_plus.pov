// error: 5:14 operator `+` cannot combine two strings
// error-text: use concat(a, b) to join strings
// POV-Ray: Parse Error: Expected 'object or directive', + found instead
// Mistake: strings joined with `+` instead of `concat`
#declare S = "a" + "b";
