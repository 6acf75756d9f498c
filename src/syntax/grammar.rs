//! The pest parser generated from `grammar/sdl.pest`.

/// Parser for POV-Ray's scene description language.
#[derive(pest_derive::Parser)]
#[grammar = "../grammar/sdl.pest"]
pub struct SdlParser;
