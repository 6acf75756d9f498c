//! Reading typed values from an item stream: a value, a float, a vector, an optional
//! boolean, the end of a block; and the wording of an unexpected item.
//!
//! In: a block's item stream. Out: the value read, or a spanned "expected X, found Y"
//! diagnostic. Holds: a leading comma is skipped, as POV-Ray's optional commas allow.

use crate::eval::language::stream::Stream;
use crate::eval::language::value::Value;
use crate::eval::{EvalResult, Evaluator};
use crate::syntax::ast::{BlockHead, Item};
use glam::DVec3;

impl Evaluator {
    /// Reads the next item as a value (skipping one leading comma).
    pub(crate) fn expect_value(
        &mut self,
        stream: &mut Stream,
        what: &str,
    ) -> EvalResult<(Value, crate::diag::Span)> {
        let mut item = self.next_item(stream)?;
        if let Some(Item::Comma(_)) = item {
            item = self.next_item(stream)?;
        }
        match item {
            Some(Item::Expr(expr)) => {
                // `"text" -1` is two values in POV-Ray: a sign after a non-number starts
                // the next value.
                let (value, rest) = self.eval_value_pair(&expr)?;
                if let Some(rest) = rest {
                    stream.push_back(Item::Expr(rest));
                }
                Ok((value, expr.span()))
            }
            Some(item @ Item::Block(_)) => {
                let span = item.span();
                Ok((self.item_value(&item)?, span))
            }
            Some(other) => Err(self
                .runtime
                .error(
                    other.span(),
                    format!("expected {what}, found {}", describe_item(&other)),
                )
                .with_label(format!("expected {what}"))
                .into()),
            None => Err(self.block_ended_early(stream, &format!("expected {what}"))),
        }
    }

    pub(crate) fn expect_float(&mut self, stream: &mut Stream, what: &str) -> EvalResult<f64> {
        let (value, span) = self.expect_value(stream, what)?;
        self.to_float(value, span)
    }

    pub(crate) fn expect_vector(&mut self, stream: &mut Stream, what: &str) -> EvalResult<DVec3> {
        let (value, span) = self.expect_value(stream, what)?;
        self.to_vector3(value, span)
    }

    /// Reads an optional float argument (e.g. `hollow` or `hollow off`).
    pub(crate) fn optional_bool(&mut self, stream: &mut Stream) -> EvalResult<bool> {
        match self.next_item(stream)? {
            Some(Item::Expr(expr)) => {
                let value = self.eval_expr(&expr)?;
                match value {
                    Value::Float(f) => Ok(f != 0.0),
                    other => {
                        stream.push_back(Item::Expr(expr));
                        let _ = other;
                        Ok(true)
                    }
                }
            }
            Some(other) => {
                stream.push_back(other);
                Ok(true)
            }
            None => Ok(true),
        }
    }

    /// "expected X, found the end of the block", pointing at the block's last item (or,
    /// in a block with nothing read, at the innermost macro call or include).
    pub(crate) fn block_ended_early(
        &self,
        stream: &Stream,
        expected: &str,
    ) -> Box<crate::diag::Diagnostic> {
        let message = format!("{expected}, found the end of the block");
        match stream.last_read() {
            Some(last) => self
                .runtime
                .error(last, message)
                .with_label(format!("{expected} after this"))
                .into(),
            None => self
                .runtime
                .error(
                    self.runtime
                        .trace
                        .last()
                        .map(|t| t.span)
                        .unwrap_or_default(),
                    message,
                )
                .into(),
        }
    }

    /// Errors if anything but commas is left in the block.
    pub(crate) fn expect_end(&mut self, stream: &mut Stream, block: &str) -> EvalResult<()> {
        while let Some(item) = self.next_item(stream)? {
            if !matches!(item, Item::Comma(_)) {
                return Err(self.unexpected_in(&item, block));
            }
        }
        Ok(())
    }

    /// "`x` is not allowed inside `block`" with a did-you-mean for misspelt keywords.
    pub(crate) fn unexpected_in(&self, item: &Item, block: &str) -> Box<crate::diag::Diagnostic> {
        let mut d = self
            .runtime
            .error(
                item.span(),
                format!("{} is not allowed inside `{block}`", describe_item(item)),
            )
            .with_label("unexpected here");
        if let Item::Expr(crate::syntax::ast::Expr::Ident(name, _)) = item {
            if self.runtime.lookup(*name).is_none() {
                d.message = format!("unknown keyword or identifier `{name}` inside `{block}`");
                if let Some(s) =
                    crate::diag::suggest_name(name, crate::syntax::keywords::ALL.iter().copied())
                {
                    d = d.with_help(format!("did you mean `{s}`?"));
                }
            }
        }
        d.into()
    }
}

/// A short description of an item for messages.
pub(crate) fn describe_item(item: &Item) -> String {
    match item {
        Item::Keyword(word, _) => format!("`{word}`"),
        Item::Block(block) => match &block.head {
            BlockHead::Word(w) => format!("`{w} {{ .. }}`"),
            BlockHead::Conditional(_) => "a block".to_string(),
        },
        Item::Expr(crate::syntax::ast::Expr::Ident(name, _)) => format!("`{name}`"),
        Item::Expr(_) => "a value".to_string(),
        Item::Comma(_) => "`,`".to_string(),
        Item::MapEntry(..) => "a map entry `[ .. ]`".to_string(),
        Item::Directive(_) => "a directive".to_string(),
    }
}
