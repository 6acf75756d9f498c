// error: 6:1 `#end` without an opening directive
// (durer prints no help line)
// POV-Ray: Parse Error: Mis-matched '#end'.
// Mistake: `#end` without an opening directive
sphere { 0, 1 }
#end
