// error: 5:29 a value is not allowed inside `box`
// (durer prints no help line)
// POV-Ray: Parse Error: No matching } in 'box', ,  found instead
// Mistake: box with a third corner
box { <0, 0, 0>, <1, 1, 1>, <2, 2, 2> }
