//! Pattern syntax: the pattern keywords and pattern modifiers that may appear in `pigment`,
//! `normal`, `texture` and `density` blocks.
//!
//! In: a keyword (or block) already taken from the owner's item stream. Out: a
//! [`PatternSpec`] or a modification of one. Holds: the owner (appearance.rs) parses maps,
//! block lists and transforms; everything specific to one pattern is parsed here.

use super::stream::Stream;
use super::{EvalResult, Evaluator};
use crate::diag::Span;
use crate::pattern::{PatternKind, PatternSpec};
use crate::syntax::ast::Block;

impl Evaluator {
    /// When `word` names a pattern, parses the pattern's own operands (such as gradient's
    /// direction) and returns it; `None` when `word` is not a pattern keyword. Block lists
    /// (`checker pigment {..}, pigment {..}`) are left for the owner.
    pub(crate) fn pattern_keyword(
        &mut self,
        word: &str,
        span: Span,
        stream: &mut Stream,
    ) -> EvalResult<Option<PatternSpec>> {
        let _ = span;
        let kind = match word {
            "checker" => PatternKind::Checker,
            "gradient" => PatternKind::Gradient(self.expect_vector(stream, "a direction")?),
            _ => return Ok(None),
        };
        Ok(Some(PatternSpec::new(kind)))
    }

    /// When `word` is a pattern modifier (`turbulence`, `octaves`, `frequency`, wave types,
    /// pattern-specific settings such as `brick_size`...), parses its operands into `pattern`
    /// and returns true; false when `word` is not a pattern modifier.
    pub(crate) fn pattern_modifier(
        &mut self,
        word: &str,
        span: Span,
        stream: &mut Stream,
        pattern: &mut PatternSpec,
    ) -> EvalResult<bool> {
        let _ = (word, span, stream, pattern);
        Ok(false)
    }

    /// When `block` is a pattern modifier block (`warp { .. }`), applies it to `pattern` and
    /// returns true; false for other blocks.
    pub(crate) fn pattern_block(
        &mut self,
        block: &Block,
        pattern: &mut PatternSpec,
    ) -> EvalResult<bool> {
        let _ = (block, pattern);
        Ok(false)
    }
}
