//! Syntax: source text to spanned AST.
mod grammar;
pub use grammar::{Rule, SdlParser};
