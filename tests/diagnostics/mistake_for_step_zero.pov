// error: 5:1 `#for` step is zero
// (durer prints no help line)
// POV-Ray: Parse Error: #for loop increment must be non-zero.
// Mistake: `#for` with step 0
#for (I, 0, 3, 0)
  sphere { x*I, 0.5 }
#end
