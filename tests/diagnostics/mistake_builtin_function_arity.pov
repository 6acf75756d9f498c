// error: 5:25 `sin` takes 1 arguments, found 2
// (durer prints no help line)
// POV-Ray: Parse Error: Invalid number of parameters for 'sin': Only one parameter expected!
// Mistake: built-in function with the wrong number of arguments in a function
#declare F = function { sin(x, y) }
