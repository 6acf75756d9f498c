// error: 6:1 expected an object, camera or light, found a macro
// (durer prints no help line)
// POV-Ray: Parse Error: Expected '(', End of File found instead
// Mistake: macro called without parentheses
#macro Ball(R) sphere { 0, R } #end
Ball
