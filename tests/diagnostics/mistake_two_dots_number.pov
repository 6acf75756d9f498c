// error: 5:17 expected an object, camera or light, found a float
// (durer prints no help line)
// POV-Ray: Parse Error: Unexpected additional '.' in floating-point number
// Mistake: number with two decimal points
#declare A = 0.5.3;
