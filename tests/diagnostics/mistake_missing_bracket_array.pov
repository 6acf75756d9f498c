// error: 5:20 unclosed `[`
// error-text: add the matching `]`
// POV-Ray: Parse Error: Expected ']', { found instead
// Mistake: array size without its closing `]`
#declare Ar = array[3 { 1, 2, 3 };
