// error: 5:1 `\\` does not start a comment
// error-text: comments start with `//` (or are written `/* ... */`)
// POV-Ray: Parse Error: Expected 'object or directive', \ found instead
// Mistake: `\\` written instead of `//` for a comment
\\ a comment
sphere { 0, 1 }
