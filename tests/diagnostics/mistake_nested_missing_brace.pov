// error: 5:8 unclosed `{`
// error-text: add the matching `}`
// POV-Ray: Parse Error: No matching } in 'sphere', sphere found instead
// Mistake: a `}` missing so the next object lands inside the previous one
sphere { 0, 1
  pigment { rgb 1 }
sphere { x, 1 }
