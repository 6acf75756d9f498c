// error: 6:10 expected an object, found a pigment
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'object', pigment identifier found instead
// Mistake: `object { }` of a pigment identifier
#declare P = pigment { rgb 1 }
object { P }
