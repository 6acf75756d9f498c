// error: 6:46 `interior { .. }` is not allowed inside `blob component`
// error-text: unexpected here
// A blob component takes only transformations, texture, pigment, normal and finish (POV-Ray
// refuses interior, material, no_shadow and the other object modifiers there).
blob { threshold 0.5
  sphere { <0, 0, 0>, 1, 1 pigment { rgb 1 } interior { ior 1.5 } }
}
