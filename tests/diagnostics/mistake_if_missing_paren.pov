// error: 7:3 expected a directive, block or value, found `sphere`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected ')', sphere found instead
// Mistake: `#if` condition without its closing `)`
#declare A = 2;
#if ((A + 1) > 2
  sphere { 0, 1 }
#end
