// error: 5:14 a value is not allowed inside `sky_sphere`
// (durer prints no help line)
// POV-Ray: Parse Error: No matching } in 'sky_sphere', color keyword 'rgb' found instead
// Mistake: a colour directly in `sky_sphere` (needs a pigment)
sky_sphere { rgb <0.5, 0.7, 1> }
