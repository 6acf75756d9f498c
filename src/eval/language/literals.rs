//! Literals that build values from parts: colours (`rgb`, `color red 1`, `srgb`) and arrays
//! with their initialisers.

use super::value::{Array, Value};
use crate::eval::{EvalResult, Evaluator};
use crate::math::Colour;
use crate::syntax::ast::{
    ArrayElement, ArrayInit, ArrayLiteral, ColourComponent, ColourLiteral, ColourType, Item,
};
use std::rc::Rc;

impl Evaluator {
    pub(crate) fn eval_colour_literal(&mut self, literal: &ColourLiteral) -> EvalResult<Value> {
        let mut colour = Colour::BLACK;
        if let Some(base) = &literal.base {
            let value = self.eval_expr(base)?;
            let span = base.span();
            colour = match literal.kind {
                None => self.to_colour(value, span)?,
                Some(kind) => {
                    let srgb = matches!(
                        kind,
                        ColourType::Srgb
                            | ColourType::Srgbf
                            | ColourType::Srgbt
                            | ColourType::Srgbft
                    );
                    // How many components the value brings: a colour always has five.
                    let (c, given): ([f64; 5], usize) = match value {
                        Value::Float(f) => ([f, f, f, f, f], 1),
                        // A shorter vector has its missing components 0, as povray reads
                        // `rgbf <r, g, b>` and `rgb <r, g>` (measured, no warning).
                        Value::Vector(v) => {
                            let mut components = [0.0; 5];
                            let given = (v.len as usize).min(5);
                            components[..given].copy_from_slice(&v.components[..given]);
                            (components, given)
                        }
                        Value::Colour(c) => (c.to_array(), 5),
                        other => {
                            return Err(self
                                .runtime
                                .error(
                                    span,
                                    format!("expected a vector, found {}", other.type_name()),
                                )
                                .into())
                        }
                    };
                    // More components than the keyword names are kept, not dropped, as
                    // povray reads them (measured with `vstr`): `rgb <r, g, b, f, t>` has
                    // that filter and transmit, `rgbf` keeps the fifth as transmit, `rgbt`
                    // takes the fourth as transmit and drops the fifth; povray warns
                    // "Suspicious expression after rgb", and so does durer.
                    let needed = match kind {
                        ColourType::Rgb | ColourType::Srgb => 3,
                        ColourType::Rgbf
                        | ColourType::Srgbf
                        | ColourType::Rgbt
                        | ColourType::Srgbt => 4,
                        ColourType::Rgbft | ColourType::Srgbft => 5,
                    };
                    if given > needed {
                        self.runtime.warn(
                            span,
                            format!(
                                "suspicious expression after `{}`: {given} components where \
                                 {needed} are expected",
                                kind.keyword()
                            ),
                        );
                    }
                    let mut result = Colour::rgb(c[0], c[1], c[2]);
                    match kind {
                        ColourType::Rgbt | ColourType::Srgbt => result.transmit = c[3],
                        ColourType::Rgb | ColourType::Srgb => {
                            if given > 3 {
                                result.filter = c[3];
                                result.transmit = c[4];
                            }
                        }
                        ColourType::Rgbf | ColourType::Srgbf => {
                            result.filter = c[3];
                            if given > 4 {
                                result.transmit = c[4];
                            }
                        }
                        ColourType::Rgbft | ColourType::Srgbft => {
                            result.filter = c[3];
                            result.transmit = c[4];
                        }
                    }
                    if srgb {
                        result.red = srgb_to_linear(result.red);
                        result.green = srgb_to_linear(result.green);
                        result.blue = srgb_to_linear(result.blue);
                    }
                    result
                }
            };
        }
        self.apply_colour_components(&mut colour, literal)?;
        Ok(Value::Colour(colour))
    }

    /// Sets the components a colour literal names (`red 1 green 0.5`) on `colour`.
    pub(crate) fn apply_colour_components(
        &mut self,
        colour: &mut Colour,
        literal: &ColourLiteral,
    ) -> EvalResult<()> {
        for (component, expr) in &literal.components {
            let v = self.eval_float(expr)?;
            match component {
                ColourComponent::Red => colour.red = v,
                ColourComponent::Green => colour.green = v,
                ColourComponent::Blue => colour.blue = v,
                ColourComponent::Filter => colour.filter = v,
                ColourComponent::Transmit => colour.transmit = v,
                ColourComponent::Grey => {
                    colour.red = v;
                    colour.green = v;
                    colour.blue = v;
                }
            }
        }
        Ok(())
    }

    pub(crate) fn eval_array(&mut self, literal: &ArrayLiteral) -> EvalResult<Value> {
        let mut sizes = Vec::new();
        let limit = self.runtime.options().limits.array_size;
        for size in &literal.sizes {
            let n = self.eval_float(size)?;
            if !(1.0..=limit as f64).contains(&n.trunc()) {
                return Err(self
                    .runtime
                    .error(
                        size.span(),
                        format!("array size {n} is not between 1 and {limit}"),
                    )
                    .with_help(crate::limits::Limits::raise_hint("array-size", limit))
                    .into());
            }
            sizes.push(n as usize);
        }
        let mut values = Vec::new();
        if let Some(init) = &literal.initialiser {
            self.collect_array_init(init, &mut values)?;
        }
        if sizes.is_empty() {
            sizes.push(values.len().max(1));
        }
        let total = sizes
            .iter()
            .try_fold(1usize, |a, s| a.checked_mul(*s))
            .unwrap_or(usize::MAX);
        if total as u64 > limit {
            return Err(self
                .runtime
                .error(
                    literal.span,
                    format!("array of {total} elements is larger than the limit of {limit}"),
                )
                .with_help(crate::limits::Limits::raise_hint("array-size", limit))
                .into());
        }
        if literal.initialiser.is_some() && values.len() != total {
            return Err(self
                .runtime
                .error(
                    literal.span,
                    format!(
                        "array initialiser has {} elements, the array holds {total}",
                        values.len()
                    ),
                )
                .into());
        }
        let mut elements: Vec<Option<Value>> = values.into_iter().map(Some).collect();
        elements.resize(total, None);
        Ok(Value::Array(Rc::new(Array { sizes, elements })))
    }

    fn collect_array_init(&mut self, init: &ArrayInit, out: &mut Vec<Value>) -> EvalResult<()> {
        let items: Vec<Item> = init
            .elements
            .iter()
            .filter_map(|e| match e {
                ArrayElement::Item(item) => Some(item.clone()),
                ArrayElement::Nested(_) => None,
            })
            .collect();
        if init
            .elements
            .iter()
            .any(|e| matches!(e, ArrayElement::Nested(_)))
        {
            for element in &init.elements {
                if let ArrayElement::Nested(nested) = element {
                    self.collect_array_init(nested, out)?;
                }
            }
            return Ok(());
        }
        let mut stream = super::stream::Stream::new(Rc::from(items));
        while let Some(item) = self.next_item(&mut stream)? {
            if matches!(item, Item::Comma(_)) {
                continue;
            }
            let value = self.item_value(&item)?;
            out.push(value);
            if out.len() as u64 > self.runtime.options().limits.array_size {
                return Err(self
                    .runtime
                    .error(init.span, "array initialiser is too large")
                    .into());
            }
        }
        Ok(())
    }
}

/// sRGB-encoded component to linear.
fn srgb_to_linear(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}
