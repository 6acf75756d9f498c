// error: 5:33 expected a colour, found `rgb`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: `ambient_light` with `rgb` and no value
global_settings { ambient_light rgb }
