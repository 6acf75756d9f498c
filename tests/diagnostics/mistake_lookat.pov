// error: 5:30 undefined identifier `lookat`
// error-text: did you mean `look_at`?
// POV-Ray: Parse Error: No matching } in 'camera', undeclared identifier 'lookat' found instead
// Mistake: camera `look_at` written `lookat`
camera { location <0, 1, -5> lookat 0 }
