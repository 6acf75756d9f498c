// error: 5:19 `rand` needs a stream made by `seed`
// (durer prints no help line)
// POV-Ray: Parse Error: Illegal random number generator.
// Mistake: `rand` given a number instead of a `seed`
#declare R = rand(1);
