//! Built-in functions callable from expressions: math, vectors and strings.

use super::c_format::general_format;
use super::value::{Value, Vector};
use crate::eval::{EvalResult, Evaluator};
use crate::math::Transform;
use crate::syntax::ast::Call;
use glam::DVec3;
use std::rc::Rc;
use std::sync::Arc;

/// Names of every built-in function, for suggestions.
pub(crate) const FUNCTIONS: &[&str] = &[
    "abs",
    "max_extent",
    "min_extent",
    "trace",
    "inside",
    "datetime",
    "rand",
    "seed",
    "acos",
    "acosh",
    "asc",
    "asin",
    "asinh",
    "atan",
    "atan2",
    "atanh",
    "bitwise_and",
    "bitwise_or",
    "bitwise_xor",
    "ceil",
    "chr",
    "concat",
    "cos",
    "cosh",
    "defined",
    "degrees",
    "dimension_size",
    "dimensions",
    "div",
    "exp",
    "file_exists",
    "floor",
    "int",
    "ln",
    "log",
    "max",
    "min",
    "mod",
    "pow",
    "radians",
    "select",
    "sin",
    "sinh",
    "sqr",
    "sqrt",
    "str",
    "strcmp",
    "strlen",
    "strlwr",
    "strupr",
    "substr",
    "tan",
    "tanh",
    "val",
    "vaxis_rotate",
    "vcross",
    "vdot",
    "vlength",
    "vnormalize",
    "vrotate",
    "vstr",
    "vturbulence",
];

pub(crate) fn call_builtin(ev: &mut Evaluator, call: &Call) -> EvalResult<Value> {
    let name = &*call.name;
    let arity_error = |ev: &Evaluator, n: usize| -> Box<crate::diag::Diagnostic> {
        let plural = if n == 1 { "" } else { "s" };
        ev.runtime
            .error(
                call.span,
                format!(
                    "`{name}` takes {n} argument{plural}, found {}",
                    call.arguments.len()
                ),
            )
            .with_label("called here")
            .into()
    };
    let arity = |ev: &Evaluator, n: usize| -> EvalResult<()> {
        if call.arguments.len() != n {
            return Err(arity_error(ev, n));
        }
        Ok(())
    };
    let unary = |f: fn(f64) -> f64| -> Option<fn(f64) -> f64> { Some(f) };
    let one: Option<fn(f64) -> f64> = match name {
        "abs" => unary(f64::abs),
        "acos" => unary(f64::acos),
        "acosh" => unary(f64::acosh),
        "asin" => unary(f64::asin),
        "asinh" => unary(f64::asinh),
        "atan" => unary(f64::atan),
        "atanh" => unary(f64::atanh),
        "ceil" => unary(f64::ceil),
        "cos" => unary(f64::cos),
        "cosh" => unary(f64::cosh),
        "degrees" => unary(f64::to_degrees),
        "exp" => unary(f64::exp),
        "floor" => unary(f64::floor),
        "int" => unary(f64::trunc),
        "ln" => unary(f64::ln),
        "log" => unary(f64::log10),
        "radians" => unary(f64::to_radians),
        "sin" => unary(f64::sin),
        "sinh" => unary(f64::sinh),
        "sqr" => unary(|x| x * x),
        "sqrt" => unary(f64::sqrt),
        "tan" => unary(f64::tan),
        "tanh" => unary(f64::tanh),
        _ => None,
    };
    if let Some(f) = one {
        arity(ev, 1)?;
        let x = ev.argument_float(call, 0)?;
        return Ok(Value::Float(f(x)));
    }
    let float2 = |ev: &mut Evaluator| -> EvalResult<(f64, f64)> {
        arity(ev, 2)?;
        Ok((ev.argument_float(call, 0)?, ev.argument_float(call, 1)?))
    };
    let vector = |ev: &mut Evaluator, i: usize| -> EvalResult<DVec3> {
        let value = ev.argument(call, i)?;
        ev.to_vector3(value, call.arguments[i].span())
    };
    let v3 = |v: DVec3| Value::Vector(Vector::from_dvec3(v));
    Ok(match name {
        "internal" => {
            return Err(ev
                .runtime.error(call.span, "POV-Ray's internal functions are not available yet")
                .with_label("called here")
                .with_help("functions.inc defines its f_* functions with these; they arrive with isosurfaces")
                .into());
        }
        "min_extent" | "max_extent" => {
            arity(ev, 1)?;
            let argument = ev.argument(call, 0)?;
            let world = object_world(ev, argument, call.arguments[0].span())?;
            // POV-Ray reports unbounded objects as reaching 1e10 in every direction.
            let corner = match (world.bounds(), name) {
                (Some(bounds), "min_extent") => bounds.min,
                (Some(bounds), _) => bounds.max,
                (None, "min_extent") => DVec3::splat(-UNBOUNDED_EXTENT),
                (None, _) => DVec3::splat(UNBOUNDED_EXTENT),
            };
            v3(corner)
        }
        "inside" => {
            arity(ev, 2)?;
            let argument = ev.argument(call, 0)?;
            if let Value::Object(object) = &argument {
                if let Some(part) = first_non_solid(object) {
                    return Err(ev
                        .runtime
                        .error(call.arguments[0].span(), "`inside` needs a solid object")
                        .with_label(format!(
                            "this object contains a {part}, which has no inside"
                        ))
                        .into());
                }
            }
            let world = object_world(ev, argument, call.arguments[0].span())?;
            let point = vector(ev, 1)?;
            Value::Float(f64::from(world.inside(point)))
        }
        "trace" => {
            if !(3..=4).contains(&call.arguments.len()) {
                return Err(ev
                    .runtime
                    .error(call.span, "`trace` takes 3 or 4 arguments")
                    .into());
            }
            let argument = ev.argument(call, 0)?;
            let world = object_world(ev, argument, call.arguments[0].span())?;
            let origin = vector(ev, 1)?;
            let direction = vector(ev, 2)?.normalize_or_zero();
            let ray = crate::geometry::Ray::new(origin, direction);
            // A miss gives <0, 0, 0> and a zero normal, as in POV-Ray.
            let (point, normal) = match world.first_hit(&ray, 0.0, f64::INFINITY) {
                Some(hit) if direction != DVec3::ZERO => (hit.point, hit.normal),
                _ => (DVec3::ZERO, DVec3::ZERO),
            };
            if let Some(crate::syntax::ast::Argument::Expr(crate::syntax::ast::Expr::Ident(
                variable,
                _,
            ))) = call.arguments.get(3)
            {
                ev.assign_declare_name(variable, v3(normal));
            }
            v3(point)
        }
        "datetime" => {
            if !(1..=2).contains(&call.arguments.len()) {
                return Err(ev
                    .runtime
                    .error(call.span, "`datetime` takes 1 or 2 arguments")
                    .with_label("called here")
                    .into());
            }
            let days = ev.argument_float(call, 0)?;
            let format = match call.arguments.len() {
                2 => string_argument(ev, call, 1)?,
                _ => super::datetime::DEFAULT_FORMAT.to_string(),
            };
            match super::datetime::format_days(days, &format) {
                Ok(text) => Value::String(Rc::from(text)),
                Err(message) => {
                    let span = call.arguments.get(1).unwrap_or(&call.arguments[0]).span();
                    return Err(ev
                        .runtime
                        .error(span, message)
                        .with_label("in this datetime")
                        .into());
                }
            }
        }
        "seed" => {
            arity(ev, 1)?;
            let start = ev.argument_float(call, 0)?;
            // The stream's state is the seed as a 32-bit integer (negative values wrap).
            ev.runtime.random_streams.push(start.trunc() as i64 as u32);
            Value::Float((ev.runtime.random_streams.len() - 1) as f64)
        }
        "rand" => {
            arity(ev, 1)?;
            let stream = ev.argument_float(call, 0)?;
            let index = stream.trunc();
            if index < 0.0 || index as usize >= ev.runtime.random_streams.len() {
                return Err(ev
                    .runtime
                    .error(
                        call.arguments[0].span(),
                        "`rand` needs a stream made by `seed`",
                    )
                    .with_label(format!("{stream} is not a random stream"))
                    .into());
            }
            Value::Float(next_random(&mut ev.runtime.random_streams[index as usize]))
        }
        "atan2" => {
            let (a, b) = float2(ev)?;
            Value::Float(a.atan2(b))
        }
        "pow" => {
            let (a, b) = float2(ev)?;
            Value::Float(a.powf(b))
        }
        "mod" => {
            let (a, b) = float2(ev)?;
            Value::Float(a % b)
        }
        "div" => {
            let (a, b) = float2(ev)?;
            Value::Float((a / b).trunc())
        }
        "min" | "max" => {
            if call.arguments.is_empty() {
                return Err(ev
                    .runtime
                    .error(call.span, format!("`{name}` needs at least one argument"))
                    .into());
            }
            let mut result = ev.argument_float(call, 0)?;
            for i in 1..call.arguments.len() {
                let x = ev.argument_float(call, i)?;
                result = if name == "min" {
                    result.min(x)
                } else {
                    result.max(x)
                };
            }
            Value::Float(result)
        }
        "bitwise_and" | "bitwise_or" | "bitwise_xor" => {
            let mut result = ev.argument_float(call, 0)? as i64;
            for i in 1..call.arguments.len() {
                let x = ev.argument_float(call, i)? as i64;
                result = match name {
                    "bitwise_and" => result & x,
                    "bitwise_or" => result | x,
                    _ => result ^ x,
                };
            }
            Value::Float(result as f64)
        }
        "select" => {
            if !(3..=4).contains(&call.arguments.len()) {
                return Err(ev
                    .runtime
                    .error(call.span, "`select` takes 3 or 4 arguments")
                    .into());
            }
            let a = ev.argument_float(call, 0)?;
            let index = if a < 0.0 {
                1
            } else if call.arguments.len() == 4 && a == 0.0 {
                2
            } else {
                call.arguments.len() - 1
            };
            ev.argument(call, index)?
        }
        "vlength" => {
            arity(ev, 1)?;
            Value::Float(vector(ev, 0)?.length())
        }
        "vnormalize" => {
            arity(ev, 1)?;
            let v = vector(ev, 0)?;
            let length = v.length();
            v3(if length > 0.0 {
                v / length
            } else {
                DVec3::ZERO
            })
        }
        "vdot" => {
            arity(ev, 2)?;
            Value::Float(vector(ev, 0)?.dot(vector(ev, 1)?))
        }
        "vcross" => {
            arity(ev, 2)?;
            v3(vector(ev, 0)?.cross(vector(ev, 1)?))
        }
        "vrotate" => {
            arity(ev, 2)?;
            let v = vector(ev, 0)?;
            let angles = vector(ev, 1)?;
            v3(Transform::rotation_degrees(angles).point_to_outer(v))
        }
        "vaxis_rotate" => {
            arity(ev, 3)?;
            let v = vector(ev, 0)?;
            let axis = vector(ev, 1)?.normalize_or_zero();
            let angle = ev.argument_float(call, 2)?.to_radians();
            let rotation = glam::DMat3::from_axis_angle(axis, angle);
            v3(rotation * v)
        }
        "vturbulence" => {
            // vturbulence(Lambda, Omega, Octaves, <P>): the turbulence warp's displacement.
            arity(ev, 4)?;
            let lambda = ev.argument_float(call, 0)?;
            let omega = ev.argument_float(call, 1)?;
            // POV-Ray truncates the octave count (the noise module clamps it to 1..=10).
            let octaves = ev.argument_float(call, 2)?.trunc() as u32;
            let point = vector(ev, 3)?;
            let shape = crate::noise::TurbulenceShape {
                octaves,
                omega,
                lambda,
            };
            v3(crate::noise::vector_turbulence(
                point,
                &shape,
                crate::noise::NoiseGenerator::default(),
            ))
        }
        "defined" => {
            arity(ev, 1)?;
            let defined = match &call.arguments[0] {
                crate::syntax::ast::Argument::Expr(crate::syntax::ast::Expr::Ident(n, _)) => {
                    ev.runtime.lookup(*n).is_some()
                }
                _ => true,
            };
            Value::Float(f64::from(defined))
        }
        "dimensions" => {
            arity(ev, 1)?;
            Value::Float(array_argument(ev, call, 0)?.sizes.len() as f64)
        }
        "dimension_size" => {
            arity(ev, 2)?;
            let array = array_argument(ev, call, 0)?;
            let dimension = ev.argument_float(call, 1)? as usize;
            let size = dimension.checked_sub(1).and_then(|d| array.sizes.get(d));
            Value::Float(size.map_or(0.0, |s| *s as f64))
        }
        "str" => {
            arity(ev, 3)?;
            let value = ev.argument_float(call, 0)?;
            let width = ev.argument_float(call, 1)?;
            let precision = ev.argument_float(call, 2)?;
            ev.checked_string(format_float(value, width, precision), call.span)?
        }
        "vstr" => {
            arity(ev, 5)?;
            let count = ev.argument_float(call, 0)?.clamp(1.0, 5.0) as usize;
            let components = match ev.argument(call, 1)? {
                Value::Vector(v) => v.components,
                Value::Colour(c) => c.to_array(),
                // A float fills only the first component here.
                Value::Float(f) => [f, 0.0, 0.0, 0.0, 0.0],
                other => {
                    return Err(ev
                        .runtime
                        .error(
                            call.span,
                            format!("expected a vector, found {}", other.type_name()),
                        )
                        .into())
                }
            };
            let separator = string_argument(ev, call, 2)?;
            let width = ev.argument_float(call, 3)?;
            let precision = ev.argument_float(call, 4)?;
            let parts: Vec<String> = components[..count]
                .iter()
                .map(|c| format_float(*c, width, precision))
                .collect();
            ev.checked_string(parts.join(&separator), call.span)?
        }
        "concat" => {
            let mut out = String::new();
            for i in 0..call.arguments.len() {
                out.push_str(&string_argument(ev, call, i)?);
            }
            ev.checked_string(out, call.span)?
        }
        "chr" => {
            arity(ev, 1)?;
            let code = ev.argument_float(call, 0)? as u32;
            Value::String(Rc::from(char::from_u32(code).unwrap_or('?').to_string()))
        }
        "asc" => {
            arity(ev, 1)?;
            let s = string_argument(ev, call, 0)?;
            Value::Float(s.chars().next().map_or(0.0, |c| c as u32 as f64))
        }
        "strlen" => {
            arity(ev, 1)?;
            // Counted in bytes, as POV-Ray does.
            Value::Float(string_argument(ev, call, 0)?.len() as f64)
        }
        "strupr" => {
            arity(ev, 1)?;
            Value::String(Rc::from(string_argument(ev, call, 0)?.to_uppercase()))
        }
        "strlwr" => {
            arity(ev, 1)?;
            Value::String(Rc::from(string_argument(ev, call, 0)?.to_lowercase()))
        }
        "strcmp" => {
            arity(ev, 2)?;
            let a = string_argument(ev, call, 0)?;
            let b = string_argument(ev, call, 1)?;
            // Like C's strcmp: the difference of the first bytes that differ (the shorter
            // string ends in a zero byte).
            let difference = a
                .bytes()
                .chain(std::iter::once(0))
                .zip(b.bytes().chain(std::iter::once(0)))
                .map(|(x, y)| i32::from(x) - i32::from(y))
                .find(|d| *d != 0)
                .unwrap_or(0);
            Value::Float(f64::from(difference))
        }
        "substr" => {
            arity(ev, 3)?;
            let s = string_argument(ev, call, 0)?;
            let start = ev.argument_float(call, 1)? as i64;
            let length = ev.argument_float(call, 2)? as i64;
            let chars: Vec<char> = s.chars().collect();
            if start < 1 || length < 0 || (start - 1 + length) as usize > chars.len() {
                return Err(ev
                    .runtime
                    .error(
                        call.span,
                        format!(
                            "substr({start}, {length}) is outside a string of length {}",
                            chars.len()
                        ),
                    )
                    .into());
            }
            let part: String = chars[(start - 1) as usize..(start - 1 + length) as usize]
                .iter()
                .collect();
            Value::String(Rc::from(part))
        }
        "val" => {
            arity(ev, 1)?;
            let s = string_argument(ev, call, 0)?;
            Value::Float(leading_float(&s))
        }
        "file_exists" => {
            arity(ev, 1)?;
            let s = string_argument(ev, call, 0)?;
            // A path the file policy refuses is not probed: the answer is "no", with a
            // warning saying why.
            match ev.runtime.find_include(&s) {
                Ok(_) => Value::Float(1.0),
                Err(missing) => {
                    if let Some(refusal) = missing.refused {
                        let warning = format!("file_exists(\"{s}\") answers false: {refusal}");
                        ev.runtime.warn(call.name_span, warning);
                    }
                    Value::Float(0.0)
                }
            }
        }
        _ => {
            // A declared value of another kind (`#declare A = 5;` then `A(2)`).
            if let Some(value) = ev.runtime.lookup(call.name) {
                return Err(ev
                    .runtime
                    .error(
                        call.name_span,
                        format!("`{name}` is {}, not a function or macro", value.type_name()),
                    )
                    .with_label("called here")
                    .with_help(format!(
                        "only functions, macros and splines can be called; write `{name}` without \
                         the parentheses to use its value"
                    ))
                    .into());
            }
            let mut d = ev.runtime.undefined(name, call.name_span);
            d.message = format!("unknown function or macro `{name}`");
            if d.help.is_none() {
                if let Some(s) = crate::diag::suggest_name(name, FUNCTIONS.iter().copied()) {
                    d.help = Some(format!("did you mean `{s}`?"));
                }
            }
            return Err(d.into());
        }
    })
}

/// Advances a random stream and returns its next value in [0, 1]: the linear congruential
/// sequence state' = 1812433253 * state + 12345 (mod 2^32), scaled by 1 / (2^32 - 1), which
/// reproduces the values POV-Ray 3.7 prints for `rand(seed(N))`.
fn next_random(state: &mut u32) -> f64 {
    *state = state.wrapping_mul(1_812_433_253).wrapping_add(12_345);
    f64::from(*state) / f64::from(u32::MAX)
}

fn array_argument(
    ev: &mut Evaluator,
    call: &Call,
    index: usize,
) -> EvalResult<Rc<crate::eval::Array>> {
    match ev.argument(call, index)? {
        Value::Array(array) => Ok(array),
        other => Err(ev
            .runtime
            .error(
                call.arguments[index].span(),
                format!("expected an array, found {}", other.type_name()),
            )
            .into()),
    }
}

/// The first shape in an object without an inside (a triangle, or a mesh without
/// `inside_vector`), which POV-Ray refuses in `inside`.
fn first_non_solid(object: &crate::scene::Object) -> Option<&'static str> {
    use crate::scene::Shape;
    match &object.shape {
        Shape::Triangle { .. } => Some("triangle"),
        Shape::SmoothTriangle { .. } => Some("smooth_triangle"),
        Shape::Mesh(mesh) if mesh.inside_vector.is_none() => Some("mesh without inside_vector"),
        Shape::Csg { children, .. } => children.iter().find_map(first_non_solid),
        _ => None,
    }
}

/// Most prepared worlds kept for `trace`, `inside`, `min_extent` and `max_extent`.
const QUERY_WORLD_CACHE: usize = 64;

/// Extent reported for objects without finite bounds.
const UNBOUNDED_EXTENT: f64 = 1e10;

/// The geometry of an object argument, prepared for bounds and ray queries; cached per
/// object value, since scenes call `trace` in loops.
fn object_world(
    ev: &mut Evaluator,
    argument: Value,
    span: crate::diag::Span,
) -> EvalResult<Rc<crate::geometry::World>> {
    match argument {
        Value::Object(object) => {
            let key = Arc::as_ptr(&object) as usize;
            if let Some((_, world)) = ev.runtime.query_worlds.get(&key) {
                return Ok(world.clone());
            }
            let world = Rc::new(crate::geometry::World::build_from_objects(vec![
                (*object).clone()
            ]));
            // Objects written inline in a loop are new every time: keep the cache small.
            if ev.runtime.query_worlds.len() >= QUERY_WORLD_CACHE {
                ev.runtime.query_worlds.clear();
            }
            // The cache holds the object too, so its address cannot be reused meanwhile.
            ev.runtime.query_worlds.insert(key, (object, world.clone()));
            Ok(world)
        }
        other => Err(ev
            .runtime
            .error(
                span,
                format!("expected an object, found {}", other.type_name()),
            )
            .into()),
    }
}

fn string_argument(ev: &mut Evaluator, call: &Call, index: usize) -> EvalResult<String> {
    match ev.argument(call, index)? {
        Value::String(s) => Ok(s.to_string()),
        other => Err(ev
            .runtime
            .error(
                call.arguments[index].span(),
                format!("expected a string, found {}", other.type_name()),
            )
            .into()),
    }
}

/// Longest text `str` and `vstr` produce; a longer one is `<invalid>` (measured: POV-Ray
/// formats into a buffer of this size).
const MAX_FORMATTED_LENGTH: usize = 254;
/// Precisions above this give the same text: a double's exact decimal expansion has at most
/// 767 significant digits, and a fixed text this long is over `MAX_FORMATTED_LENGTH` anyway.
const MAX_PRECISION: f64 = 1100.0;

/// `str(value, width, precision)` as POV-Ray formats it (measured): C's `%W.Pf` (a negative
/// width pads with zeros, a negative precision means 6); a text over 254 characters is made
/// again as `%W.Pg`, and when that is still too long the result is `<invalid>`.
fn format_float(value: f64, width: f64, precision: f64) -> String {
    let precision = if precision < 0.0 {
        6
    } else {
        precision.min(MAX_PRECISION) as usize
    };
    // C pads `nan` and `inf` with spaces even when asked for zeros.
    let zero_padded = width < 0.0 && value.is_finite();
    // Any width over the limit is invalid whatever the value; clamping keeps `format!` safe
    // (a NaN width is 0, as C's conversion to int would make it).
    let width = if width.is_nan() {
        0
    } else {
        width.abs().min((MAX_FORMATTED_LENGTH + 1) as f64) as usize
    };
    let fixed = if value.is_finite() {
        format!("{value:.precision$}")
    } else {
        // C writes `nan`, `inf` and `-inf` whatever the precision.
        general_format(value, precision)
    };
    let fixed = padded(fixed, value, width, zero_padded);
    if fixed.len() <= MAX_FORMATTED_LENGTH {
        return fixed;
    }
    let general = padded(general_format(value, precision), value, width, zero_padded);
    if general.len() <= MAX_FORMATTED_LENGTH {
        general
    } else {
        "<invalid>".to_string()
    }
}

/// `text` right-aligned in `width` characters, padded with spaces or, after the sign, zeros.
fn padded(text: String, value: f64, width: usize, zero_padded: bool) -> String {
    match (width > text.len(), zero_padded) {
        (true, true) if value < 0.0 => format!("-{:0>w$}", &text[1..], w = width - 1),
        (true, true) => format!("{text:0>width$}"),
        (true, false) => format!("{text:>width$}"),
        _ => text,
    }
}

/// The float at the start of a string (0 when there is none), like C's `strtod`: leading
/// white space, a sign, then a decimal number with optional exponent, a hexadecimal number
/// (`0x1f`, `0x1.8p3`), `inf`/`infinity` or `nan`.
fn leading_float(s: &str) -> f64 {
    let s = s.trim_start();
    let (negative, body) = match s.as_bytes().first() {
        Some(b'-') => (true, &s[1..]),
        Some(b'+') => (false, &s[1..]),
        _ => (false, s),
    };
    let magnitude = unsigned_leading_float(body);
    if negative {
        -magnitude
    } else {
        magnitude
    }
}

/// [`leading_float`] after the sign.
fn unsigned_leading_float(s: &str) -> f64 {
    let bytes = s.as_bytes();
    let lower = s.get(..8.min(s.len())).unwrap_or("").to_ascii_lowercase();
    if lower.starts_with("inf") {
        return f64::INFINITY;
    }
    if lower.starts_with("nan") {
        return f64::NAN;
    }
    if lower.starts_with("0x")
        && bytes
            .get(2)
            .is_some_and(|b| b.is_ascii_hexdigit() || *b == b'.')
    {
        return hexadecimal_float(&s[2..]);
    }
    let digits = |from: usize| {
        bytes[from.min(bytes.len())..]
            .iter()
            .take_while(|b| b.is_ascii_digit())
            .count()
    };
    let whole = digits(0);
    let mut end = whole;
    let mut fraction = 0;
    if bytes.get(end) == Some(&b'.') {
        fraction = digits(end + 1);
        end += 1 + fraction;
    }
    if whole + fraction == 0 {
        return 0.0;
    }
    if matches!(bytes.get(end), Some(b'e' | b'E')) {
        let sign = usize::from(matches!(bytes.get(end + 1), Some(b'+' | b'-')));
        let exponent = digits(end + 1 + sign);
        if exponent > 0 {
            end += 1 + sign + exponent;
        }
    }
    s[..end].parse().unwrap_or(0.0)
}

/// A hexadecimal float after its `0x`: digits, an optional fraction and a binary exponent.
fn hexadecimal_float(s: &str) -> f64 {
    let mut value = 0.0;
    let mut scale = 1.0;
    let mut in_fraction = false;
    let mut rest = "";
    for (at, c) in s.char_indices() {
        if let Some(digit) = c.to_digit(16) {
            if in_fraction {
                scale /= 16.0;
                value += f64::from(digit) * scale;
            } else {
                value = value * 16.0 + f64::from(digit);
            }
        } else if c == '.' && !in_fraction {
            in_fraction = true;
        } else {
            rest = &s[at..];
            break;
        }
    }
    if let Some(exponent) = rest.strip_prefix(['p', 'P']) {
        let unsigned = exponent.trim_start_matches(['+', '-']);
        let digits: String = unsigned.chars().take_while(char::is_ascii_digit).collect();
        if let Ok(power) = digits.parse::<i32>() {
            let power = if exponent.starts_with('-') {
                -power
            } else {
                power
            };
            value *= 2f64.powi(power);
        }
    }
    value
}

#[cfg(test)]
mod tests {
    #[test]
    fn str_formats_long_texts_as_povray() {
        use super::format_float;
        // Values printed by POV-Ray 3.7.
        assert_eq!(format_float(1.5, 0.0, 2.0), "1.50");
        assert_eq!(format_float(1.5, 0.0, -3.0), "1.500000");
        assert_eq!(format_float(-1.5, -10.0, 2.0), "-000001.50");
        assert_eq!(format_float(1.5, 0.0, 252.0).len(), 254);
        assert_eq!(format_float(1.5, 0.0, 253.0), "1.5");
        assert_eq!(format_float(123.5, 0.0, 252.0), "123.5");
        assert_eq!(format_float(1.5, 5.0, 253.0), "  1.5");
        assert_eq!(format_float(1.5, 254.0, 2.0).len(), 254);
        assert_eq!(format_float(1.5, 255.0, 2.0), "<invalid>");
        assert_eq!(format_float(1.5, 1e12, 2.0), "<invalid>");
        assert_eq!(format_float(1.5, 20.0, 1000.0), "                 1.5");
        assert_eq!(format_float(-1.5, -20.0, 1e9), "-00000000000000001.5");
        assert_eq!(
            format_float(1.0 / 3.0, 0.0, 1000.0),
            "0.333333333333333314829616256247390992939472198486328125"
        );
        assert_eq!(
            format_float(1e20 / 3.0, 0.0, 1000.0),
            "33333333333333331968"
        );
        assert_eq!(format_float(1e300, 0.0, 2.0), "1e+300");
        assert_eq!(format_float(1e300, 0.0, 300.0), "<invalid>");
        assert_eq!(format_float(1e-300, 0.0, 400.0), "<invalid>");
        assert_eq!(format_float(1e200, 250.0, 2.0).len(), 250);
        assert_eq!(format_float(f64::INFINITY, 0.0, 2.0), "inf");
        assert_eq!(format_float(f64::NEG_INFINITY, 6.0, 2.0), "  -inf");
        assert_eq!(format_float(f64::NAN, 0.0, 2.0), "nan");
        assert_eq!(format_float(1.5, f64::NAN, 2.0), "1.50");
        assert_eq!(format_float(f64::NEG_INFINITY, -6.0, 2.0), "  -inf");
    }

    use super::leading_float;

    #[test]
    fn leading_float_reads_like_strtod() {
        let cases = [
            ("  12.5abc", 12.5),
            ("abc", 0.0),
            ("-1e3x", -1000.0),
            ("1e", 1.0),
            ("0x10", 16.0),
            ("0x1.8p1", 3.0),
            (".5", 0.5),
            ("+4", 4.0),
            ("-", 0.0),
        ];
        for (text, expected) in cases {
            assert_eq!(leading_float(text), expected, "{text:?}");
        }
        assert!(leading_float("inf") == f64::INFINITY);
    }
}
