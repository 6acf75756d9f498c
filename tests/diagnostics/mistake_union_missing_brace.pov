// error: 5:7 unclosed `{`
// error-text: add the matching `}`
// POV-Ray: Parse Error: No matching } in 'union', End of File found instead
// Mistake: `union` without its closing `}`
union {
  sphere { 0, 1 }
  sphere { x, 1 }
