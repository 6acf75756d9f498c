// error: 5:1 unknown block keyword `Sphere`
// error-text: did you mean `sphere`?
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'Sphere' found instead
// Mistake: `sphere` written `Sphere`
Sphere { 0, 1 }
