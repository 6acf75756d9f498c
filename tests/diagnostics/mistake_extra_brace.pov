// error: 5:17 unexpected `}`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'object or directive', } found instead
// Mistake: an extra `}` after an object
sphere { 0, 1 } }
