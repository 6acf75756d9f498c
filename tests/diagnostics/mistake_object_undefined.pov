// error: 5:10 undefined identifier `Undefined`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'object', undeclared identifier 'Undefined' found instead
// Mistake: `object { }` of an undeclared identifier
object { Undefined }
