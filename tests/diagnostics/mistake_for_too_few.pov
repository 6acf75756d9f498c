// error: 5:11 expected a directive, block or value, found `)`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'numeric expression', ) found instead
// Mistake: `#for` without its end value
#for (I, 0)
  sphere { x*I, 0.5 }
#end
