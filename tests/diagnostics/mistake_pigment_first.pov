// error: 5:10 expected a vector, found a pigment
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'numeric expression', pigment found instead
// Mistake: pigment before the sphere's centre and radius
sphere { pigment { rgb 1 } 0, 1 }
