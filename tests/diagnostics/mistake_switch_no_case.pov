// error: 7:3 expected `#end`, found `sphere`
// (durer prints no help line)
// POV-Ray: Parse Error: #switch not followed by #case or #range.
// Mistake: content before the first `#case` of a `#switch`
#declare A = 1;
#switch (A)
  sphere { 0, 1 }
#end
