//! The spanned abstract syntax tree of a scene file.
//!
//! Block bodies are lists of generic [`Item`]s; which items a context accepts is decided by
//! the evaluator, so directives and macro calls can stand anywhere.

use crate::diag::Span;
use std::rc::Rc;

/// An identifier or keyword as written.
pub type Name = super::symbol::Symbol;

/// One element of a block body or of the file's top level.
#[derive(Clone, Debug)]
pub enum Item {
    /// `#declare`, `#if`, `#while`, ...
    Directive(Rc<Directive>),
    /// `word { items }`, e.g. `sphere { ... }` or `pigment { ... }`.
    Block(Rc<Block>),
    /// `[ items ]` in a map.
    MapEntry(Rc<[Item]>, Span),
    /// A separating comma.
    Comma(Span),
    /// A reserved word standing alone, e.g. `translate` or `hollow`.
    Keyword(Name, Span),
    /// A value: number, vector, colour, identifier, macro call...
    Expr(Expr),
}

impl Item {
    /// The source range of the item.
    pub fn span(&self) -> Span {
        match self {
            Item::Directive(d) => d.span,
            Item::Block(b) => b.span,
            Item::MapEntry(_, span) | Item::Comma(span) | Item::Keyword(_, span) => *span,
            Item::Expr(e) => e.span(),
        }
    }
}

/// `word { body }`.
#[derive(Clone, Debug)]
pub struct Block {
    /// The keyword (or, for a misspelling, the word) before the brace.
    pub head: BlockHead,
    /// Span of the head word.
    pub head_span: Span,
    /// The items between the braces.
    pub body: Rc<[Item]>,
    /// The whole block.
    pub span: Span,
}

/// What names a block.
#[derive(Clone, Debug)]
pub enum BlockHead {
    /// A plain keyword such as `sphere`.
    Word(Name),
    /// `#if (C) merge { #else union { #end`: the first branch whose condition holds.
    Conditional(Vec<(Option<Expr>, Name)>),
}

/// Unary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnaryOp {
    /// `-a`
    Negate,
    /// `+a`
    Plus,
    /// `!a`
    Not,
}

/// Binary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinaryOp {
    /// `+`
    Add,
    /// `-`
    Subtract,
    /// `*`
    Multiply,
    /// `/`
    Divide,
    /// `<`
    Less,
    /// `<=`
    LessEqual,
    /// `=`
    Equal,
    /// `!=`
    NotEqual,
    /// `>=`
    GreaterEqual,
    /// `>`
    Greater,
    /// `&`
    And,
    /// `|`
    Or,
}

impl BinaryOp {
    /// The operator as written.
    pub fn symbol(self) -> &'static str {
        match self {
            BinaryOp::Add => "+",
            BinaryOp::Subtract => "-",
            BinaryOp::Multiply => "*",
            BinaryOp::Divide => "/",
            BinaryOp::Less => "<",
            BinaryOp::LessEqual => "<=",
            BinaryOp::Equal => "=",
            BinaryOp::NotEqual => "!=",
            BinaryOp::GreaterEqual => ">=",
            BinaryOp::Greater => ">",
            BinaryOp::And => "&",
            BinaryOp::Or => "|",
        }
    }
}

/// An expression.
#[derive(Clone, Debug)]
pub enum Expr {
    /// A float literal.
    Number(f64, Span),
    /// A string literal, escapes already resolved.
    String(Rc<str>, Span),
    /// `<a, b, ...>`.
    Vector(Rc<[Expr]>, Span),
    /// An identifier (or built-in constant such as `pi` or `x`).
    Ident(Name, Span),
    /// `name(arguments)`: built-in function, macro or user function.
    Call(Rc<Call>),
    /// Unary operation.
    Unary(UnaryOp, Rc<Expr>, Span),
    /// Binary operation.
    Binary(BinaryOp, Rc<Expr>, Rc<Expr>, Span),
    /// `c ? a : b`.
    Conditional(Rc<(Expr, Expr, Expr)>, Span),
    /// `value.x`, `value.red`...
    Member(Rc<Expr>, Name, Span),
    /// `array[index]`.
    Index(Rc<Expr>, Rc<Expr>, Span),
    /// `color rgb <..> filter 0.5`...
    Colour(Rc<ColourLiteral>),
    /// `array[n] { ... }`.
    Array(Rc<ArrayLiteral>),
    /// `function(a, b) { ... }`.
    Function(Rc<FunctionLiteral>),
    /// A directive used as a value: `#if` inside an expression, or a directive standing alone
    /// as a call's argument (`Add(1, #include "value.inc")`).
    Directive(Rc<Directive>),
}

impl Expr {
    /// The source range of the expression.
    pub fn span(&self) -> Span {
        match self {
            Expr::Number(_, s)
            | Expr::String(_, s)
            | Expr::Vector(_, s)
            | Expr::Ident(_, s)
            | Expr::Unary(_, _, s)
            | Expr::Binary(_, _, _, s)
            | Expr::Conditional(_, s)
            | Expr::Member(_, _, s)
            | Expr::Index(_, _, s) => *s,
            Expr::Call(c) => c.span,
            Expr::Colour(c) => c.span,
            Expr::Array(a) => a.span,
            Expr::Function(f) => f.span,
            Expr::Directive(d) => d.span,
        }
    }
}

/// `name(arguments)`, or `array[i](arguments)`.
#[derive(Clone, Debug)]
pub struct Call {
    /// The called name; for an array element, the array's name.
    pub name: Name,
    /// For `array[i](arguments)`, the element called: the value the call applies to is this
    /// expression's, not the name's.
    pub element: Option<Rc<Expr>>,
    /// Span of the name.
    pub name_span: Span,
    /// The arguments; blocks (e.g. `texture { .. }`) are allowed for macros.
    pub arguments: Vec<Argument>,
    /// Directives written among the arguments (`M(1, #declare R = 5; R)`), in source order.
    pub directives: Vec<ArgumentDirective>,
    /// The whole call.
    pub span: Span,
}

/// A directive written among a call's arguments: it runs in the caller's scope after the
/// arguments before it are evaluated and before the ones after it.
#[derive(Clone, Debug)]
pub struct ArgumentDirective {
    /// The index of the argument it stands before (the number of arguments when it follows
    /// the last one).
    pub before_argument: usize,
    /// Whether it directly follows an argument, with no comma between (POV-Ray reads a
    /// directive there in a built-in function's call but not in a macro's).
    pub follows_argument: bool,
    /// The directive.
    pub directive: Rc<Directive>,
}

/// One argument of a call.
#[derive(Clone, Debug)]
pub enum Argument {
    /// An expression.
    Expr(Expr),
    /// A block such as `pigment { .. }`.
    Block(Rc<Block>),
}

impl Argument {
    /// The source range of the argument.
    pub fn span(&self) -> Span {
        match self {
            Argument::Expr(e) => e.span(),
            Argument::Block(b) => b.span,
        }
    }
}

/// The kind keyword of a colour literal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColourType {
    /// `rgb`
    Rgb,
    /// `rgbf`
    Rgbf,
    /// `rgbt`
    Rgbt,
    /// `rgbft`
    Rgbft,
    /// `srgb` (and friends): values given in sRGB.
    Srgb,
    /// `srgbf`
    Srgbf,
    /// `srgbt`
    Srgbt,
    /// `srgbft`
    Srgbft,
}

impl ColourType {
    /// The keyword as written in a scene.
    pub fn keyword(self) -> &'static str {
        match self {
            ColourType::Rgb => "rgb",
            ColourType::Rgbf => "rgbf",
            ColourType::Rgbt => "rgbt",
            ColourType::Rgbft => "rgbft",
            ColourType::Srgb => "srgb",
            ColourType::Srgbf => "srgbf",
            ColourType::Srgbt => "srgbt",
            ColourType::Srgbft => "srgbft",
        }
    }
}

/// A colour component keyword.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColourComponent {
    /// `red`
    Red,
    /// `green`
    Green,
    /// `blue`
    Blue,
    /// `filter`
    Filter,
    /// `transmit`
    Transmit,
    /// `gray`: all three colour channels.
    Grey,
}

/// `color rgb <..> filter 0.5` and the other colour forms.
#[derive(Clone, Debug)]
pub struct ColourLiteral {
    /// `rgb`, `rgbf`, ... when given.
    pub kind: Option<ColourType>,
    /// The base value, when given.
    pub base: Option<Expr>,
    /// Component overrides in order.
    pub components: Vec<(ColourComponent, Expr)>,
    /// Written with the `color` keyword.
    pub has_colour_word: bool,
    /// The whole literal.
    pub span: Span,
}

impl ColourLiteral {
    /// Only component keywords (`red 1 green 0.5`): in a pigment or a colour map entry
    /// they modify the colour before them rather than start a new one.
    pub fn is_components_only(&self) -> bool {
        !self.has_colour_word && self.kind.is_none() && self.base.is_none()
    }
}

/// `array[n][m] { ... }`.
#[derive(Clone, Debug)]
pub struct ArrayLiteral {
    /// Declared sizes, outermost first.
    pub sizes: Vec<Expr>,
    /// The initialiser, when given.
    pub initialiser: Option<ArrayInit>,
    /// The whole literal.
    pub span: Span,
}

/// One `{ ... }` level of an array initialiser.
#[derive(Clone, Debug)]
pub struct ArrayInit {
    /// Nested levels and items, in order.
    pub elements: Vec<ArrayElement>,
    /// The braces.
    pub span: Span,
}

/// An element of an array initialiser.
#[derive(Clone, Debug)]
pub enum ArrayElement {
    /// A nested `{ ... }` for the next dimension.
    Nested(ArrayInit),
    /// An item (value, comma, directive).
    Item(Item),
}

/// `function(params) { body }`.
#[derive(Clone, Debug)]
pub struct FunctionLiteral {
    /// Parameter names; empty means POV-Ray's default `x, y, z`.
    pub parameters: Vec<Name>,
    /// `W, H` written before the body (a height field's or an image's function); empty
    /// otherwise.
    pub resolution: Vec<Expr>,
    /// The body.
    pub body: FunctionBody,
    /// The whole literal.
    pub span: Span,
}

/// What a function literal contains.
#[derive(Clone, Debug)]
pub enum FunctionBody {
    /// An expression in x, y, z (or the parameters).
    Expr(Expr),
    /// Items, e.g. `pigment { .. }` or `pattern { .. }`.
    Items(Rc<[Item]>),
}

/// A macro parameter.
#[derive(Clone, Debug)]
pub struct Parameter {
    /// Its name.
    pub name: Name,
    /// Declared `optional`.
    pub optional: bool,
    /// Where it is declared.
    pub span: Span,
}

/// `#macro Name(params) body #end`.
#[derive(Debug)]
pub struct MacroDefinition {
    /// The macro's name.
    pub name: Name,
    /// Its parameters.
    pub parameters: Vec<Parameter>,
    /// The body.
    pub body: MacroBody,
    /// Span of the `#macro ... )` header.
    pub header_span: Span,
}

/// A macro's body: items, or text when its directives cut across braces.
#[derive(Debug)]
pub enum MacroBody {
    /// A body with a tree shape, and where its items are in their file (the span lets a
    /// text macro that calls this macro run its text token by token).
    Items(Rc<[Item]>, Span),
    /// A body whose directives cut across braces (`#if (F) #write(..) #else mesh2 { #end`),
    /// kept as text up to and including its closing `#end`; it is run token by token.
    Text {
        /// The body's text.
        text: Rc<str>,
        /// Where the text is in its file.
        span: Span,
    },
}

/// A directive with its span.
#[derive(Debug)]
pub struct Directive {
    /// What it is.
    pub kind: DirectiveKind,
    /// Written without its `#` (`declare A = 1;`, POV-Ray 2's spelling).
    pub without_hash: bool,
    /// The whole directive.
    pub span: Span,
}

/// Where `#declare`/`#local`/`#read` store a value: a name and optional array indices.
#[derive(Clone, Debug)]
pub struct Target {
    /// The identifier.
    pub name: Name,
    /// Array indices, outermost first.
    pub indices: Vec<Expr>,
    /// The whole target.
    pub span: Span,
}

/// One branch of a conditional.
#[derive(Clone, Debug)]
pub struct Branch {
    /// The condition; `None` for `#else`.
    pub condition: Option<Expr>,
    /// The items run when chosen.
    pub body: Rc<[Item]>,
}

/// A `#case` or `#range` clause of `#switch`.
#[derive(Clone, Debug)]
pub struct SwitchClause {
    /// What selects this clause.
    pub label: SwitchLabel,
    /// The items of the clause.
    pub body: Rc<[Item]>,
}

/// `#case (v)` or `#range (low, high)`.
#[derive(Clone, Debug)]
pub enum SwitchLabel {
    /// `#case (value)`.
    Case(Expr),
    /// `#range (low, high)`.
    Range(Expr, Expr),
}

/// Every directive.
#[derive(Debug)]
pub enum DirectiveKind {
    /// `#declare` (global) or `#local` (innermost scope).
    Declare {
        local: bool,
        target: Target,
        /// Directives written between `=` and the value, run before it.
        prelude: Rc<[Item]>,
        value: Item,
        layers: Vec<Rc<Block>>,
    },
    /// A whole file whose directives cut across braces, kept as text and run token by
    /// token (as a text macro's body is).
    TextRun { text: Rc<str>, span: Span },
    /// `#undef Name` or `#undef Name[i]..` (the element becomes uninitialised).
    Undef(Target),
    /// `#if`, `#ifdef`, `#ifndef` with `#elseif`/`#else` branches (an `#ifdef` test is
    /// lowered to a condition on `defined`).
    If {
        branches: Vec<Branch>,
        end_span: Span,
    },
    /// `#ifdef (Target)`/`#ifndef`: the first branch tests definedness.
    IfDefined {
        negate: bool,
        target: Target,
        then: Rc<[Item]>,
        rest: Vec<Branch>,
    },
    /// `#while (c) body #end`.
    While { condition: Expr, body: Rc<[Item]> },
    /// `#for (Name, start, end[, step]) body #end`.
    For {
        variable: Name,
        variable_span: Span,
        start: Expr,
        end: Expr,
        step: Option<Expr>,
        body: Rc<[Item]>,
    },
    /// `#switch (v) clauses [#else ..] #end`.
    Switch {
        value: Expr,
        clauses: Vec<SwitchClause>,
        otherwise: Option<Rc<[Item]>>,
    },
    /// `#break`.
    Break,
    /// `#macro`.
    Macro(Rc<MacroDefinition>),
    /// `#include "file"`.
    Include(Expr),
    /// `#version v;`.
    Version(Expr),
    /// `#default { .. }`.
    Default(Rc<[Item]>),
    /// `#debug`, `#warning`, `#error` with their message.
    Message { level: MessageLevel, text: Expr },
    /// `#fopen Name "file" read|write|append`.
    FileOpen {
        handle: Name,
        path: Expr,
        mode: Name,
    },
    /// `#fclose Name`.
    FileClose(Name),
    /// `#read (Handle, targets..)`.
    FileRead { handle: Name, targets: Vec<Target> },
    /// `#write (Handle, values..)`.
    FileWrite {
        handle: Name,
        values: Vec<WriteValue>,
    },
}

/// One value of `#write`: written as text, or as binary integers when a type such as `uint8`
/// precedes it.
#[derive(Debug)]
pub struct WriteValue {
    /// The integer type written, if any.
    pub binary: Option<BinaryInteger>,
    /// The value (a float, or a vector whose components are written one after another).
    pub value: Expr,
}

/// An integer encoding of `#write`: `uint8`, `sint8`, `uint16be`, `uint16le`, `sint16be`,
/// `sint16le`, `sint32be` or `sint32le`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BinaryInteger {
    /// Size in bytes: 1, 2 or 4.
    pub bytes: u8,
    /// Whether negative values are kept (two's complement).
    pub signed: bool,
    /// Most significant byte first.
    pub big_endian: bool,
}

impl BinaryInteger {
    /// The encoding named by a `#write` type keyword.
    pub fn from_keyword(keyword: &str) -> Option<BinaryInteger> {
        let (bytes, signed, big_endian) = match keyword {
            "uint8" => (1, false, false),
            "sint8" => (1, true, false),
            "uint16be" => (2, false, true),
            "uint16le" => (2, false, false),
            "sint16be" => (2, true, true),
            "sint16le" => (2, true, false),
            "sint32be" => (4, true, true),
            "sint32le" => (4, true, false),
            _ => return None,
        };
        Some(BinaryInteger {
            bytes,
            signed,
            big_endian,
        })
    }

    /// The bytes for `value`: rounded to the nearest integer (halves upwards) and held to
    /// the type's range, as POV-Ray writes them.
    pub fn encode(self, value: f64, out: &mut Vec<u8>) {
        let bits = 8 * u32::from(self.bytes);
        let (low, high) = if self.signed {
            (-(1i64 << (bits - 1)), (1i64 << (bits - 1)) - 1)
        } else {
            (0, (1i64 << bits) - 1)
        };
        // `as` maps NaN to 0 and saturates infinities before the clamp.
        let integer = ((value + 0.5).floor() as i64).clamp(low, high);
        let little = integer.to_le_bytes();
        let little = &little[..usize::from(self.bytes)];
        if self.big_endian {
            out.extend(little.iter().rev());
        } else {
            out.extend_from_slice(little);
        }
    }
}

/// The level of a message directive.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MessageLevel {
    /// `#debug`: printed to stderr.
    Debug,
    /// `#warning`: a warning diagnostic.
    Warning,
    /// `#error`: stops the scene.
    Error,
}

#[cfg(test)]
mod tests {
    use super::BinaryInteger;

    fn encoded(keyword: &str, value: f64) -> Vec<u8> {
        let mut out = Vec::new();
        BinaryInteger::from_keyword(keyword)
            .expect("known keyword")
            .encode(value, &mut out);
        out
    }

    #[test]
    fn binary_integers_round_halves_up_and_clamp_like_povray() {
        // Expected bytes measured with povray 3.7's `#write`.
        assert_eq!(encoded("uint8", 300.0), [0xff]);
        assert_eq!(encoded("uint8", -5.0), [0x00]);
        assert_eq!(encoded("uint8", 2.5), [0x03]);
        assert_eq!(encoded("uint8", 2.4999), [0x02]);
        assert_eq!(encoded("sint8", -2.5), [0xfe]);
        assert_eq!(encoded("sint8", -200.0), [0x80]);
        assert_eq!(encoded("sint16le", -300.0), [0xd4, 0xfe]);
        assert_eq!(encoded("sint16be", -300.0), [0xfe, 0xd4]);
        assert_eq!(encoded("uint16le", 70000.0), [0xff, 0xff]);
        assert_eq!(encoded("sint32le", -70000.6), [0x8f, 0xee, 0xfe, 0xff]);
        assert_eq!(encoded("sint32be", 1e10), [0x7f, 0xff, 0xff, 0xff]);
        assert_eq!(encoded("uint8", f64::NAN), [0x00]);
        assert!(BinaryInteger::from_keyword("uint32le").is_none());
    }
}
