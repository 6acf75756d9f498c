// error: 6:5 unclosed `(`
// error-text: add the matching `)`
// POV-Ray: Parse Error: Expected ')', End of File found instead
// Mistake: macro call without its closing `)`
#macro Ball(R) sphere { 0, R } #end
Ball(1
