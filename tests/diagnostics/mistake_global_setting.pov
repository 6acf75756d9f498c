// error: 5:1 unknown block keyword `global_setting`
// error-text: did you mean `global_settings`?
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'global_setting' found instead
// Mistake: `global_settings` without the final `s`
global_setting { assumed_gamma 1 }
