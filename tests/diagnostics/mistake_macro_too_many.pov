// error: 6:1 macro `Ball` takes 1 argument, found 2
// (durer prints no help line)
// POV-Ray: Parse Error: Expected ')', float function 'float constant' found instead
// Mistake: macro called with too many arguments
#macro Ball(R) sphere { 0, R } #end
Ball(1, 2)
