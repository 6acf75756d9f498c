// error: 5:8 unclosed `{`
// error-text: add the matching `}`
// POV-Ray: Parse Error: No matching } in 'pigment', finish found instead
// Mistake: a pigment's `}` missing inside an object
sphere { 0, 1
  pigment { rgb 1
  finish { phong 1 }
}
