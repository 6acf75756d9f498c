//! User functions written back as SDL expressions. A function called from another is
//! declared once (`#declare Function_N = function(..) { .. }`) and called by name; an
//! internal function is declared as `function { internal(N) }`.

use super::appearance::{write_pigment, PigmentRole};
use super::patterns::write_pattern_block;
use super::{matrix, number, Unsupported, Writer, Written};
use crate::math::Transform;
use crate::texture::function::spline::{Spline, SplineKind};
use crate::texture::function::{Binary, Body, Component, Function, Internal, Node, Output, Unary};
use std::fmt::Write as _;
use std::sync::Arc;

/// Writes `function { .. }` for `function`, its parameters named by `names`.
pub(super) fn write_function_block(
    writer: &mut Writer,
    out: &mut String,
    function: &Arc<Function>,
    names: &[&str],
) -> Written {
    out.push_str("function { ");
    write_function_body(writer, out, function, names)?;
    out.push_str(" }");
    Ok(())
}

/// The inside of a `function { }` block.
fn write_function_body(
    writer: &mut Writer,
    out: &mut String,
    function: &Function,
    names: &[&str],
) -> Written {
    match function.body() {
        Body::Expression(node) => {
            if let Some(number) = whole_internal(node, function.arity()) {
                let _ = write!(out, "internal({number})");
                return Ok(());
            }
            write_node(writer, out, node, names)
        }
        Body::Pattern { pattern, transform } => {
            out.push_str("pattern { ");
            write_pattern_block(writer, out, pattern, transform, &Transform::IDENTITY)?;
            out.push_str(" }");
            Ok(())
        }
        Body::Pigment(pigment) => write_pigment(
            writer,
            out,
            pigment,
            &Transform::IDENTITY,
            PigmentRole::Pigment,
        ),
        Body::Transform(transform) => {
            let _ = write!(out, "transform {{{} }}", matrix(transform));
            Ok(())
        }
        Body::Spline(spline) => {
            write_spline(out, spline);
            Ok(())
        }
    }
}

/// The internal function's number when `node` is that function applied to the parameters
/// in order (what `function { internal(N) }` compiles to).
fn whole_internal(node: &Node, arity: usize) -> Option<u8> {
    let (internal, arguments) = match node {
        Node::Internal(internal, arguments) => (*internal, arguments),
        Node::SceneNoise(_, arguments) => (Internal::Noise3d, arguments),
        _ => return None,
    };
    let in_order = arguments.len() == arity
        && arguments
            .iter()
            .enumerate()
            .all(|(i, a)| matches!(a, Node::Parameter(p) if *p == i));
    in_order.then(|| internal.number())
}

/// `spline { kind t, <..> .. }`.
pub(super) fn write_spline(out: &mut String, spline: &Spline) {
    let kind = match spline.kind {
        SplineKind::Linear => "linear_spline",
        SplineKind::Quadratic => "quadratic_spline",
        SplineKind::Cubic => "cubic_spline",
        SplineKind::Natural => "natural_spline",
    };
    let _ = write!(out, "spline {{ {kind}");
    let components = usize::from(spline.components.clamp(2, 5));
    for (t, point) in spline.points() {
        let values: Vec<String> = point[..components].iter().map(|v| number(*v)).collect();
        let _ = write!(out, " {}, <{}>", number(*t), values.join(", "));
    }
    out.push_str(" }");
}

/// The name of parameter `index`.
fn parameter_name(names: &[&str], index: usize) -> String {
    names
        .get(index)
        .map_or_else(|| format!("p{index}"), |name| name.to_string())
}

/// The parameter names of a declared function of `arity` parameters.
fn declared_names(arity: usize) -> Vec<String> {
    if arity == 3 {
        return vec!["x".into(), "y".into(), "z".into()];
    }
    (0..arity).map(|i| format!("p{i}")).collect()
}

/// The name under which `function` is declared (declaring it the first time).
fn declared_function(writer: &mut Writer, function: &Arc<Function>) -> Result<String, Unsupported> {
    writer.declared(super::address(function), "Function", |writer, text| {
        let names = declared_names(function.arity());
        let name_refs: Vec<&str> = names.iter().map(String::as_str).collect();
        match function.body() {
            Body::Expression(node) if whole_internal(node, function.arity()).is_none() => {
                let _ = write!(text, "function({}) {{ ", names.join(", "));
                write_node(writer, text, node, &name_refs)?;
            }
            _ => {
                text.push_str("function { ");
                write_function_body(writer, text, function, &name_refs)?;
            }
        }
        text.push_str(" }");
        Ok(())
    })
}

/// The name of a declared internal function.
fn declared_internal(writer: &mut Writer, internal: Internal) -> Result<String, Unsupported> {
    // Keys below any real address (allocations are never in the first page).
    let key = usize::from(internal.number()) + 1;
    writer.declared(key, "Internal", |_, text| {
        let _ = write!(text, "function {{ internal({}) }}", internal.number());
        Ok(())
    })
}

fn write_arguments(
    writer: &mut Writer,
    out: &mut String,
    arguments: &[Node],
    names: &[&str],
) -> Written {
    out.push('(');
    for (i, argument) in arguments.iter().enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        write_node(writer, out, argument, names)?;
    }
    out.push(')');
    Ok(())
}

fn write_node(writer: &mut Writer, out: &mut String, node: &Node, names: &[&str]) -> Written {
    match node {
        Node::Constant(value) => {
            if *value < 0.0 || (*value == 0.0 && value.is_sign_negative()) {
                let _ = write!(out, "({})", number(*value));
            } else {
                out.push_str(&number(*value));
            }
        }
        Node::Parameter(index) => out.push_str(&parameter_name(names, *index)),
        Node::Unary(op, a) => {
            match op {
                Unary::Negate => out.push_str("(-"),
                Unary::Not => out.push_str("(!"),
                _ => {
                    out.push_str(unary_name(*op));
                    out.push('(');
                }
            }
            write_node(writer, out, a, names)?;
            out.push(')');
        }
        Node::Binary(op, parts) => {
            let [a, b] = &**parts;
            if let Some(symbol) = binary_symbol(*op) {
                out.push('(');
                write_node(writer, out, a, names)?;
                let _ = write!(out, " {symbol} ");
                write_node(writer, out, b, names)?;
                out.push(')');
            } else {
                out.push_str(binary_name(*op));
                out.push('(');
                write_node(writer, out, a, names)?;
                out.push_str(", ");
                write_node(writer, out, b, names)?;
                out.push(')');
            }
        }
        Node::Conditional(parts) => {
            let [a, b, c] = &**parts;
            out.push('(');
            write_node(writer, out, a, names)?;
            out.push_str(" ? ");
            write_node(writer, out, b, names)?;
            out.push_str(" : ");
            write_node(writer, out, c, names)?;
            out.push(')');
        }
        Node::Select(parts) => {
            out.push_str("select");
            write_arguments(writer, out, &parts[..], names)?;
        }
        Node::Series {
            product,
            counter,
            parts,
        } => {
            let [from, to, body] = &**parts;
            let _ = write!(
                out,
                "{}({}, ",
                if *product { "prod" } else { "sum" },
                parameter_name(names, *counter)
            );
            write_node(writer, out, from, names)?;
            out.push_str(", ");
            write_node(writer, out, to, names)?;
            out.push_str(", ");
            write_node(writer, out, body, names)?;
            out.push(')');
        }
        Node::Call(function, arguments) => {
            let name = declared_function(writer, function)?;
            out.push_str(&name);
            write_arguments(writer, out, arguments, names)?;
        }
        Node::Member(function, component, arguments) => {
            let name = declared_function(writer, function)?;
            out.push_str(&name);
            write_arguments(writer, out, arguments, names)?;
            out.push('.');
            out.push_str(&member_name(*component, function.output())?);
        }
        Node::Internal(internal, arguments) => {
            let name = declared_internal(writer, *internal)?;
            out.push_str(&name);
            write_arguments(writer, out, arguments, names)?;
        }
        Node::SceneNoise(_, arguments) => {
            let name = declared_internal(writer, Internal::Noise3d)?;
            out.push_str(&name);
            write_arguments(writer, out, arguments, names)?;
        }
    }
    Ok(())
}

fn member_name(component: Component, output: Output) -> Result<String, Unsupported> {
    Ok(match component {
        Component::Gray => "gray".into(),
        Component::HeightField => "hf".into(),
        Component::Index(i) => {
            let names: &[&str] = match output {
                Output::Colour => &["red", "green", "blue", "filter", "transmit"],
                _ => &["x", "y", "z", "t"],
            };
            names
                .get(usize::from(i))
                .ok_or_else(|| Unsupported(format!("component {i} of a function")))?
                .to_string()
        }
    })
}

fn unary_name(op: Unary) -> &'static str {
    match op {
        Unary::Negate => "-",
        Unary::Not => "!",
        Unary::Abs => "abs",
        Unary::Acos => "acos",
        Unary::Acosh => "acosh",
        Unary::Asin => "asin",
        Unary::Asinh => "asinh",
        Unary::Atan => "atan",
        Unary::Atanh => "atanh",
        Unary::Ceil => "ceil",
        Unary::Cos => "cos",
        Unary::Cosh => "cosh",
        Unary::Degrees => "degrees",
        Unary::Exp => "exp",
        Unary::Floor => "floor",
        Unary::Int => "int",
        Unary::Ln => "ln",
        Unary::Log => "log",
        Unary::Radians => "radians",
        Unary::Sin => "sin",
        Unary::Sinh => "sinh",
        Unary::Sqrt => "sqrt",
        Unary::Tan => "tan",
        Unary::Tanh => "tanh",
    }
}

fn binary_symbol(op: Binary) -> Option<&'static str> {
    Some(match op {
        Binary::Add => "+",
        Binary::Subtract => "-",
        Binary::Multiply => "*",
        Binary::Divide => "/",
        Binary::Less => "<",
        Binary::LessEqual => "<=",
        Binary::Equal => "=",
        Binary::NotEqual => "!=",
        Binary::GreaterEqual => ">=",
        Binary::Greater => ">",
        Binary::And => "&",
        Binary::Or => "|",
        _ => return None,
    })
}

fn binary_name(op: Binary) -> &'static str {
    match op {
        Binary::Pow => "pow",
        Binary::Atan2 => "atan2",
        Binary::Mod => "mod",
        Binary::Min => "min",
        Binary::Max => "max",
        _ => "",
    }
}
