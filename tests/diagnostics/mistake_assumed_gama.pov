// error: 5:19 unknown keyword or identifier `assumed_gama` inside `global_settings`
// error-text: did you mean `assumed_gamma`?
// POV-Ray: Parse Error: No matching } in 'global_settings', undeclared identifier 'assumed_gama' found instead
// Mistake: `assumed_gamma` misspelt `assumed_gama`
global_settings { assumed_gama 1.0 }
