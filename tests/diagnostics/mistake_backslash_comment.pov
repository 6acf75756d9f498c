// error: 5:1 expected `,`, a block or something else, found `\`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'object or directive', \ found instead
// Mistake: `\\` written instead of `//` for a comment
\\ a comment
sphere { 0, 1 }
