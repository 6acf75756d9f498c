// error: 5:15 a float cannot modify an object
// (durer prints no help line)
// POV-Ray: Parse Error: No matching } in 'sphere', ,  found instead
// Mistake: decimal comma (European style) in a radius
sphere { 0, 0,5 }
