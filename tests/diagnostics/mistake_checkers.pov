// error: 5:24 undefined identifier `checkers`
// error-text: did you mean `checker`?
// POV-Ray: Parse Error: No matching } in 'pigment', undeclared identifier 'checkers' found instead
// Mistake: `checker` written `checkers`
plane { y, 0 pigment { checkers rgb 0, rgb 1 } }
