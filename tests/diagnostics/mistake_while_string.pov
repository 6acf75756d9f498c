// error: 5:9 expected a float, found a string
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'string comparison operator', ) found instead
// Mistake: `#while` condition that is a string
#while ("yes")
#end
