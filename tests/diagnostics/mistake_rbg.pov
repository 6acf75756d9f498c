// error: 5:31 undefined identifier `rbg`
// error-text: did you mean `rgb`?
// POV-Ray: Parse Error: No matching } in 'pigment', undeclared identifier 'rbg' found instead
// Mistake: `rgb` written `rbg`
sphere { 0, 1 pigment { color rbg <1, 0, 0> } }
