// error: 6:3 expected an object, camera or light, found a pigment
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'object or directive', pigment found instead
// Mistake: pigment written after the object's closing `}`
sphere { 0, 1 }
  pigment { rgb 1 }
