// error: 7:1 expected a block or an expression, found end of file
// (durer prints no help line)
// POV-Ray: Parse Error: Expected ')', End of File found instead
// Mistake: macro call without its closing `)`
#macro Ball(R) sphere { 0, R } #end
Ball(1
