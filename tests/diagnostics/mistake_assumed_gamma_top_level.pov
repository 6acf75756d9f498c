// error: 5:1 `assumed_gamma` cannot stand at the top level of a scene
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'object or directive', assumed_gamma found instead
// Mistake: `assumed_gamma` outside `global_settings`
assumed_gamma 1.0
