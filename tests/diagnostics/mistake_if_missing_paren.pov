// error: 6:5 unclosed `(`
// error-text: add the matching `)`
// POV-Ray: Parse Error: Expected ')', sphere found instead
// Mistake: `#if` condition without its closing `)`
#declare A = 2;
#if ((A + 1) > 2
  sphere { 0, 1 }
#end
