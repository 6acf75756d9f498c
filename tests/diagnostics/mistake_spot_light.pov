// error: 5:32 unknown keyword or identifier `spot_light` inside `light_source`
// error-text: did you mean `spotlight`?
// POV-Ray: Parse Error: No matching } in 'light_source', undeclared identifier 'spot_light' found instead
// Mistake: `spotlight` written `spot_light`
light_source { <0, 5, 0> rgb 1 spot_light point_at 0 }
