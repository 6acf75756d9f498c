// error: 5:15 a float cannot modify an object
// (durer prints no help line)
// POV-Ray: Parse Error: No matching } in 'sphere', float function 'float constant' found instead
// Mistake: sphere with an extra number
sphere { 0, 1 2 }
