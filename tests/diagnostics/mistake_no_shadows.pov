// error: 5:33 undefined identifier `no_shadows`
// error-text: did you mean `no_shadow`?
// POV-Ray: Parse Error: No matching } in 'sphere', undeclared identifier 'no_shadows' found instead
// Mistake: `no_shadow` written `no_shadows`
sphere { 0, 1 pigment { rgb 1 } no_shadows }
