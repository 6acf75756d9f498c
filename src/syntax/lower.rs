//! Lowering pest pairs into the spanned AST (no `'input` lifetime leaks past this file).

use super::ast::*;
use super::grammar::Rule;
use super::mapping::OffsetMap;
use crate::diag::{FileId, Span};
use pest::iterators::Pair;
use pest::pratt_parser::{Assoc, Op, PrattParser};
use std::rc::Rc;
use std::sync::OnceLock;

/// Lowers pairs of one file (or of generated text, through its offset map) into AST nodes.
pub struct Lowerer<'m> {
    file: FileId,
    map: Option<&'m OffsetMap>,
}

fn pratt() -> &'static PrattParser<Rule> {
    static PRATT: OnceLock<PrattParser<Rule>> = OnceLock::new();
    PRATT.get_or_init(|| {
        PrattParser::new()
            .op(Op::infix(Rule::add, Assoc::Left) | Op::infix(Rule::sub, Assoc::Left))
            .op(Op::infix(Rule::mul, Assoc::Left) | Op::infix(Rule::div, Assoc::Left))
            .op(Op::prefix(Rule::neg) | Op::prefix(Rule::pos) | Op::prefix(Rule::not))
    })
}

impl<'m> Lowerer<'m> {
    /// A lowerer for the file with this id.
    pub fn new(file: FileId) -> Lowerer<'m> {
        Lowerer { file, map: None }
    }

    /// A lowerer for generated text whose offsets `map` leads back to source files.
    pub fn mapped(map: &'m OffsetMap) -> Lowerer<'m> {
        Lowerer {
            file: 0,
            map: Some(map),
        }
    }

    fn span(&self, pair: &Pair<Rule>) -> Span {
        let s = pair.as_span();
        match self.map {
            Some(map) => map.span(s.start(), s.end()),
            None => Span::new(self.file, s.start(), s.end()),
        }
    }

    /// Lowers one directive pair (`declare`, `write`, ...).
    pub fn directive_item(&self, pair: Pair<Rule>) -> Directive {
        self.directive(pair)
    }

    /// Lowers a `call` pair.
    pub fn macro_call(&self, pair: Pair<Rule>) -> Call {
        self.call(pair)
    }

    /// Lowers a `full_expr` pair.
    pub fn full_expression(&self, pair: Pair<Rule>) -> Expr {
        self.full_expr(pair)
    }

    /// Lowers an `ifdef_target` pair.
    pub fn ifdef_target(&self, pair: Pair<Rule>) -> Target {
        let span = self.span(&pair);
        let mut inner = pair.into_inner();
        let name = Name::from(inner.next().map(|p| p.as_str()).unwrap_or(""));
        let indices = inner
            .map(|p| self.full_expr(p.into_inner().next().expect("index")))
            .collect();
        Target {
            name,
            indices,
            span,
        }
    }

    /// Lowers an `items` pair.
    pub fn items(&self, pair: Pair<Rule>) -> Rc<[Item]> {
        pair.into_inner().filter_map(|p| self.item(p)).collect()
    }

    fn item(&self, pair: Pair<Rule>) -> Option<Item> {
        let span = self.span(&pair);
        Some(match pair.as_rule() {
            Rule::block => Item::Block(Rc::new(self.block(pair))),
            Rule::map_entry => {
                let inner = pair.into_inner().next();
                Item::MapEntry(
                    inner
                        .map(|p| self.items(p))
                        .unwrap_or_else(|| Rc::from(Vec::new())),
                    span,
                )
            }
            Rule::comma => Item::Comma(span),
            Rule::keyword => Item::Keyword(Name::from(pair.as_str()), span),
            Rule::expr => Item::Expr(self.expr(pair)),
            Rule::EOI => return None,
            _ => Item::Directive(Rc::new(self.directive(pair))),
        })
    }

    fn block(&self, pair: Pair<Rule>) -> Block {
        let span = self.span(&pair);
        let mut inner = pair.into_inner();
        let first = inner.next().expect("block has a head");
        let head_span = self.span(&first);
        let head = match first.as_rule() {
            Rule::block_head => BlockHead::Word(Name::from(first.as_str())),
            _ => {
                // conditional_head: (expr block_head)* (block_head)? end
                let mut branches = Vec::new();
                let mut pending: Option<Expr> = None;
                for p in first.into_inner() {
                    match p.as_rule() {
                        Rule::expr => pending = Some(self.expr(p)),
                        Rule::block_head => branches.push((pending.take(), Name::from(p.as_str()))),
                        _ => {}
                    }
                }
                BlockHead::Conditional(branches)
            }
        };
        let body = inner
            .next()
            .map(|p| self.items(p))
            .unwrap_or_else(|| Rc::from(Vec::new()));
        Block {
            head,
            head_span,
            body,
            span,
        }
    }

    /// Lowers an `expr` pair (arithmetic with Pratt precedence).
    pub fn expr(&self, pair: Pair<Rule>) -> Expr {
        pratt()
            .map_primary(|p| self.postfix_expr(p))
            .map_prefix(|op, operand| {
                let span = self.span(&op).join(operand.span());
                let op = match op.as_rule() {
                    Rule::neg => UnaryOp::Negate,
                    Rule::pos => UnaryOp::Plus,
                    _ => UnaryOp::Not,
                };
                Expr::Unary(op, Rc::new(operand), span)
            })
            .map_infix(|lhs, op, rhs| {
                let span = lhs.span().join(rhs.span());
                let op = match op.as_rule() {
                    Rule::add => BinaryOp::Add,
                    Rule::sub => BinaryOp::Subtract,
                    Rule::mul => BinaryOp::Multiply,
                    _ => BinaryOp::Divide,
                };
                Expr::Binary(op, Rc::new(lhs), Rc::new(rhs), span)
            })
            .parse(pair.into_inner())
    }

    fn full_expr(&self, pair: Pair<Rule>) -> Expr {
        let span = self.span(&pair);
        let mut inner = pair.into_inner();
        let logical = self.logical(inner.next().expect("full_expr has a condition"));
        match (inner.next(), inner.next()) {
            (Some(a), Some(b)) => Expr::Conditional(
                Rc::new((logical, self.full_expr(a), self.full_expr(b))),
                span,
            ),
            _ => logical,
        }
    }

    fn logical(&self, pair: Pair<Rule>) -> Expr {
        self.left_chain(pair, |l, p| l.relational(p))
    }

    fn relational(&self, pair: Pair<Rule>) -> Expr {
        self.left_chain(pair, |l, p| l.expr(p))
    }

    /// Folds `operand (op operand)*` left to right.
    fn left_chain(&self, pair: Pair<Rule>, operand: impl Fn(&Self, Pair<Rule>) -> Expr) -> Expr {
        let mut inner = pair.into_inner();
        let mut lhs = operand(self, inner.next().expect("chain has an operand"));
        while let (Some(op), Some(rhs)) = (inner.next(), inner.next()) {
            let rhs = operand(self, rhs);
            let op = match op.as_rule() {
                Rule::and => BinaryOp::And,
                Rule::or => BinaryOp::Or,
                Rule::lt => BinaryOp::Less,
                Rule::le => BinaryOp::LessEqual,
                Rule::eq => BinaryOp::Equal,
                Rule::ne => BinaryOp::NotEqual,
                Rule::ge => BinaryOp::GreaterEqual,
                _ => BinaryOp::Greater,
            };
            let span = lhs.span().join(rhs.span());
            lhs = Expr::Binary(op, Rc::new(lhs), Rc::new(rhs), span);
        }
        lhs
    }

    fn postfix_expr(&self, pair: Pair<Rule>) -> Expr {
        let mut inner = pair.into_inner();
        let mut value = self.primary(inner.next().expect("postfix_expr has a primary"));
        for post in inner {
            let span = value.span().join(self.span(&post));
            value = match post.as_rule() {
                Rule::member => {
                    let name = post.into_inner().next().map(|w| w.as_str()).unwrap_or("");
                    Expr::Member(Rc::new(value), Name::from(name), span)
                }
                Rule::element_call => {
                    // Follows an index: the element just indexed is called.
                    let (arguments, directives) = self.arguments(post.into_inner().next());
                    let name_span = value.span();
                    Expr::Call(Rc::new(Call {
                        name: root_name(&value),
                        element: Some(Rc::new(value)),
                        name_span,
                        arguments,
                        directives,
                        span,
                    }))
                }
                _ => {
                    let index = self.full_expr(post.into_inner().next().expect("index"));
                    Expr::Index(Rc::new(value), Rc::new(index), span)
                }
            };
        }
        value
    }

    fn primary(&self, pair: Pair<Rule>) -> Expr {
        let span = self.span(&pair);
        match pair.as_rule() {
            Rule::number => Expr::Number(pair.as_str().parse().unwrap_or(0.0), span),
            Rule::string => {
                let raw = pair.into_inner().next().map(|p| p.as_str()).unwrap_or("");
                Expr::String(Rc::from(unescape(raw)), span)
            }
            Rule::vector => Expr::Vector(pair.into_inner().map(|p| self.expr(p)).collect(), span),
            Rule::paren => self.full_expr(pair.into_inner().next().expect("paren")),
            Rule::ident => Expr::Ident(Name::from(pair.as_str()), span),
            Rule::call => Expr::Call(Rc::new(self.call(pair))),
            Rule::colour => Expr::Colour(Rc::new(self.colour(pair))),
            Rule::array_literal => Expr::Array(Rc::new(self.array(pair))),
            Rule::function_literal => Expr::Function(Rc::new(self.function(pair))),
            _ => Expr::Directive(Rc::new(self.directive(pair))),
        }
    }

    fn call(&self, pair: Pair<Rule>) -> Call {
        let span = self.span(&pair);
        let mut inner = pair.into_inner();
        let name = inner.next().expect("call name");
        let name_span = self.span(&name);
        let (arguments, directives) = self.arguments(inner.next());
        Call {
            name: Name::from(name.as_str()),
            element: None,
            name_span,
            arguments,
            directives,
            span,
        }
    }

    /// Lowers a call's argument list: the arguments, and the directives written among them.
    fn arguments(&self, list: Option<Pair<Rule>>) -> (Vec<Argument>, Vec<ArgumentDirective>) {
        let mut arguments = Vec::new();
        let mut directives = Vec::new();
        if let Some(list) = list {
            // The pieces of one comma-separated slot, sorted once the slot is complete.
            let mut slot = Vec::new();
            for piece in list.into_inner() {
                if piece.as_rule() == Rule::argument_comma {
                    self.sort_slot(&mut slot, &mut arguments, &mut directives);
                } else {
                    slot.push(self.argument_piece(piece));
                }
            }
            self.sort_slot(&mut slot, &mut arguments, &mut directives);
        }
        (arguments, directives)
    }

    /// Lowers one piece of a call's argument list: an argument or a directive.
    fn argument_piece(&self, pair: Pair<Rule>) -> ArgumentPiece {
        ArgumentPiece::Argument(match pair.as_rule() {
            Rule::block => Argument::Block(Rc::new(self.block(pair))),
            Rule::spline_kind => {
                Argument::Expr(Expr::Ident(Name::from(pair.as_str()), self.span(&pair)))
            }
            Rule::full_expr => Argument::Expr(self.full_expr(pair)),
            _ => return ArgumentPiece::Directive(Rc::new(self.directive(pair))),
        })
    }

    /// Moves the pieces of one argument slot into the call's arguments and directives. A
    /// directive ending a slot without an argument is the slot's argument, the value it leaves
    /// (`max(1, #if (C) 2 #else 3 #end)`, `Add(1, #include "value.inc")`; in a macro call it
    /// may leave none: `M(1, 2, #declare Z = 3;)`). A bare `#if` followed by more of its slot
    /// is a directive (`M(#if (C) #declare R = 1; #end R)`).
    fn sort_slot(
        &self,
        slot: &mut Vec<ArgumentPiece>,
        arguments: &mut Vec<Argument>,
        directives: &mut Vec<ArgumentDirective>,
    ) {
        let count = slot.len();
        let mut pieces: Vec<ArgumentPiece> = slot
            .drain(..)
            .enumerate()
            .map(|(index, piece)| match piece {
                ArgumentPiece::Argument(Argument::Expr(Expr::Directive(directive)))
                    if index + 1 < count =>
                {
                    ArgumentPiece::Directive(directive)
                }
                other => other,
            })
            .collect();
        let has_argument = pieces
            .iter()
            .any(|p| matches!(p, ArgumentPiece::Argument(_)));
        if !has_argument {
            if let Some(ArgumentPiece::Directive(directive)) = pieces.pop() {
                pieces.push(ArgumentPiece::Argument(Argument::Expr(Expr::Directive(
                    directive,
                ))));
            }
        }
        let mut follows_argument = false;
        for piece in pieces {
            match piece {
                ArgumentPiece::Argument(argument) => {
                    arguments.push(argument);
                    follows_argument = true;
                }
                ArgumentPiece::Directive(directive) => directives.push(ArgumentDirective {
                    before_argument: arguments.len(),
                    follows_argument,
                    directive,
                }),
            }
        }
    }

    fn colour(&self, pair: Pair<Rule>) -> ColourLiteral {
        let span = self.span(&pair);
        let mut literal = ColourLiteral {
            kind: None,
            base: None,
            components: Vec::new(),
            has_colour_word: false,
            span,
        };
        for p in pair.into_inner() {
            match p.as_rule() {
                Rule::colour_word => literal.has_colour_word = true,
                Rule::colour_type => {
                    literal.kind = Some(match p.as_str() {
                        "rgb" => ColourType::Rgb,
                        "rgbf" => ColourType::Rgbf,
                        "rgbt" => ColourType::Rgbt,
                        "rgbft" => ColourType::Rgbft,
                        "srgb" => ColourType::Srgb,
                        "srgbf" => ColourType::Srgbf,
                        "srgbt" => ColourType::Srgbt,
                        _ => ColourType::Srgbft,
                    })
                }
                Rule::expr => literal.base = Some(self.expr(p)),
                Rule::colour_component => {
                    let mut inner = p.into_inner();
                    let word = inner.next().map(|w| w.as_str()).unwrap_or("");
                    let component = match word {
                        "red" => ColourComponent::Red,
                        "green" => ColourComponent::Green,
                        "blue" => ColourComponent::Blue,
                        "filter" => ColourComponent::Filter,
                        "transmit" => ColourComponent::Transmit,
                        _ => ColourComponent::Grey,
                    };
                    let value = self.expr(inner.next().expect("component value"));
                    literal.components.push((component, value));
                }
                _ => {}
            }
        }
        literal
    }

    fn array(&self, pair: Pair<Rule>) -> ArrayLiteral {
        let span = self.span(&pair);
        let mut literal = ArrayLiteral {
            sizes: Vec::new(),
            initialiser: None,
            span,
        };
        for p in pair.into_inner() {
            match p.as_rule() {
                Rule::array_size => literal
                    .sizes
                    .push(self.full_expr(p.into_inner().next().expect("size"))),
                Rule::array_init => literal.initialiser = Some(self.array_init(p)),
                _ => {}
            }
        }
        literal
    }

    fn array_init(&self, pair: Pair<Rule>) -> ArrayInit {
        let span = self.span(&pair);
        let elements = pair
            .into_inner()
            .filter_map(|p| match p.as_rule() {
                Rule::array_init => Some(ArrayElement::Nested(self.array_init(p))),
                _ => self.item(p).map(ArrayElement::Item),
            })
            .collect();
        ArrayInit { elements, span }
    }

    fn function(&self, pair: Pair<Rule>) -> FunctionLiteral {
        let span = self.span(&pair);
        let mut parameters = Vec::new();
        let mut body = FunctionBody::Items(Rc::from(Vec::new()));
        let mut resolution = Vec::new();
        for p in pair.into_inner() {
            match p.as_rule() {
                Rule::expr => resolution.push(self.expr(p)),
                Rule::parameters => {
                    parameters = self.parameters(p).into_iter().map(|p| p.name).collect()
                }
                Rule::function_body => {
                    let inner = p.into_inner().next();
                    body = match inner {
                        Some(e) if e.as_rule() == Rule::full_expr => {
                            FunctionBody::Expr(self.full_expr(e))
                        }
                        Some(items) => FunctionBody::Items(self.items(items)),
                        None => FunctionBody::Items(Rc::from(Vec::new())),
                    };
                }
                _ => {}
            }
        }
        FunctionLiteral {
            parameters,
            resolution,
            body,
            span,
        }
    }

    fn parameters(&self, pair: Pair<Rule>) -> Vec<Parameter> {
        pair.into_inner()
            .map(|p| {
                let span = self.span(&p);
                let mut optional = false;
                let mut name = Name::from("");
                for q in p.into_inner() {
                    match q.as_rule() {
                        Rule::optional => optional = true,
                        _ => name = Name::from(q.as_str()),
                    }
                }
                Parameter {
                    name,
                    optional,
                    span,
                }
            })
            .collect()
    }

    fn target(&self, pair: Pair<Rule>) -> Target {
        let span = self.span(&pair);
        let mut inner = pair.into_inner();
        let name = Name::from(inner.next().map(|p| p.as_str()).unwrap_or(""));
        let indices = inner
            .map(|p| self.full_expr(p.into_inner().next().expect("index expression")))
            .collect();
        Target {
            name,
            indices,
            span,
        }
    }

    fn branches<'i>(&self, pairs: impl Iterator<Item = Pair<'i, Rule>>) -> (Vec<Branch>, Span) {
        let mut branches = Vec::new();
        let mut end_span = Span::default();
        for p in pairs {
            match p.as_rule() {
                Rule::elseif_branch => {
                    let mut inner = p.into_inner().filter(|p| !is_directive_word(p.as_rule()));
                    let condition = self.expr(inner.next().expect("elseif condition"));
                    let body = self.items(inner.next().expect("elseif body"));
                    branches.push(Branch {
                        condition: Some(condition),
                        body,
                    });
                }
                Rule::else_branch => {
                    let body = self.items(significant(p).next().expect("else body"));
                    branches.push(Branch {
                        condition: None,
                        body,
                    });
                }
                Rule::end => end_span = self.span(&p),
                _ => {}
            }
        }
        (branches, end_span)
    }

    fn directive(&self, pair: Pair<Rule>) -> Directive {
        let span = self.span(&pair);
        let rule = pair.as_rule();
        let without_hash = !pair.as_str().starts_with('#');
        let mut inner = pair
            .into_inner()
            .filter(|p| !is_directive_word(p.as_rule()));
        let kind = match rule {
            Rule::declare | Rule::local => {
                let mut first = inner.next().expect("declare target");
                if first.as_rule() == Rule::deprecation {
                    first = inner.next().expect("declare target");
                }
                let target = self.target(first);
                let mut prelude = Vec::new();
                let mut next = inner.next();
                while let Some(p) = next.take_if(|p| p.as_rule() == Rule::value_prelude) {
                    let directive = p
                        .into_inner()
                        .next()
                        .expect("value_prelude has a directive");
                    prelude.push(Item::Directive(Rc::new(self.directive(directive))));
                    next = inner.next();
                }
                let value = next.and_then(|p| match p.as_rule() {
                    Rule::expr | Rule::block => self.item(p),
                    _ => Some(Item::Directive(Rc::new(self.directive(p)))),
                });
                let value = value.unwrap_or(Item::Comma(span));
                let layers = inner
                    .filter(|p| p.as_rule() == Rule::texture_layer)
                    .filter_map(|p| p.into_inner().find(|b| b.as_rule() == Rule::block))
                    .map(|b| Rc::new(self.block(b)))
                    .collect();
                DirectiveKind::Declare {
                    local: rule == Rule::local,
                    target,
                    prelude: Rc::from(prelude),
                    value,
                    layers,
                }
            }
            Rule::undef => {
                DirectiveKind::Undef(self.ifdef_target(inner.next().expect("undef target")))
            }
            Rule::if_directive => {
                let condition = self.expr(inner.next().expect("if condition"));
                let body = self.items(inner.next().expect("if body"));
                let (rest, end_span) = self.branches(inner);
                let mut branches = vec![Branch {
                    condition: Some(condition),
                    body,
                }];
                branches.extend(rest);
                DirectiveKind::If { branches, end_span }
            }
            Rule::ifdef_directive | Rule::ifndef_directive => {
                let target = self.ifdef_target(inner.next().expect("ifdef target"));
                let then = self.items(inner.next().expect("ifdef body"));
                let (rest, _) = self.branches(inner);
                DirectiveKind::IfDefined {
                    negate: rule == Rule::ifndef_directive,
                    target,
                    then,
                    rest,
                }
            }
            Rule::while_directive => {
                let condition = self.expr(inner.next().expect("while condition"));
                let body = self.items(inner.next().expect("while body"));
                DirectiveKind::While { condition, body }
            }
            Rule::for_directive => {
                let variable = inner.next().expect("for variable");
                let variable_span = self.span(&variable);
                let variable = Name::from(variable.as_str());
                let start = self.full_expr(inner.next().expect("for start"));
                let end = self.full_expr(inner.next().expect("for end"));
                let mut step = None;
                let mut body = Rc::from(Vec::new());
                for p in inner {
                    match p.as_rule() {
                        Rule::full_expr => step = Some(self.full_expr(p)),
                        Rule::items => body = self.items(p),
                        _ => {}
                    }
                }
                DirectiveKind::For {
                    variable,
                    variable_span,
                    start,
                    end,
                    step,
                    body,
                }
            }
            Rule::switch_directive => {
                let value = self.expr(inner.next().expect("switch value"));
                let mut clauses = Vec::new();
                let mut otherwise = None;
                for p in inner {
                    match p.as_rule() {
                        Rule::switch_clause => {
                            let mut c = p.into_inner();
                            let label_pair = c.next().expect("switch label");
                            let label = if label_pair.as_rule() == Rule::case_label {
                                let mut l = label_pair
                                    .into_inner()
                                    .filter(|p| p.as_rule() == Rule::expr);
                                SwitchLabel::Case(self.expr(l.next().expect("case value")))
                            } else {
                                let mut l = label_pair
                                    .into_inner()
                                    .filter(|p| p.as_rule() == Rule::full_expr);
                                let low = self.full_expr(l.next().expect("range low"));
                                let high = self.full_expr(l.next().expect("range high"));
                                SwitchLabel::Range(low, high)
                            };
                            let body = self.items(c.next().expect("clause body"));
                            clauses.push(SwitchClause { label, body });
                        }
                        Rule::else_branch => {
                            otherwise = Some(self.items(significant(p).next().expect("else body")))
                        }
                        _ => {}
                    }
                }
                DirectiveKind::Switch {
                    value,
                    clauses,
                    otherwise,
                }
            }
            Rule::break_directive => DirectiveKind::Break,
            Rule::macro_directive => {
                let name = inner.next().expect("macro name");
                let params = inner.next().expect("macro parameters");
                let header_span = span.join(self.span(&params));
                let parameters = self.parameters(params);
                let body = match inner.next() {
                    Some(p) if p.as_rule() == Rule::items => {
                        let span = self.span(&p);
                        MacroBody::Items(self.items(p), span)
                    }
                    Some(p) => MacroBody::Text {
                        span: self.span(&p),
                        text: Rc::from(p.as_str()),
                    },
                    None => MacroBody::Items(Rc::from(Vec::new()), header_span),
                };
                DirectiveKind::Macro(Rc::new(MacroDefinition {
                    name: Name::from(name.as_str()),
                    parameters,
                    body,
                    header_span,
                }))
            }
            Rule::include => DirectiveKind::Include(self.expr(inner.next().expect("include"))),
            Rule::version => DirectiveKind::Version(self.expr(inner.next().expect("version"))),
            Rule::default => DirectiveKind::Default(self.items(inner.next().expect("default"))),
            Rule::debug | Rule::warning | Rule::error => {
                let level = match rule {
                    Rule::debug => MessageLevel::Debug,
                    Rule::warning => MessageLevel::Warning,
                    _ => MessageLevel::Error,
                };
                DirectiveKind::Message {
                    level,
                    text: self.expr(inner.next().expect("message")),
                }
            }
            Rule::fopen => {
                let handle = Name::from(inner.next().expect("handle").as_str());
                let path = self.expr(inner.next().expect("path"));
                let mode = Name::from(inner.next().expect("mode").as_str());
                DirectiveKind::FileOpen { handle, path, mode }
            }
            Rule::fclose => {
                DirectiveKind::FileClose(Name::from(inner.next().expect("handle").as_str()))
            }
            Rule::read => {
                let handle = Name::from(inner.next().expect("handle").as_str());
                DirectiveKind::FileRead {
                    handle,
                    targets: inner.map(|p| self.target(p)).collect(),
                }
            }
            Rule::write => {
                let handle = Name::from(inner.next().expect("handle").as_str());
                let mut values = Vec::new();
                let mut binary = None;
                for p in inner {
                    match p.as_rule() {
                        Rule::write_type => binary = BinaryInteger::from_keyword(p.as_str()),
                        Rule::full_expr => values.push(WriteValue {
                            binary: binary.take(),
                            value: self.full_expr(p),
                        }),
                        _ => {}
                    }
                }
                DirectiveKind::FileWrite { handle, values }
            }
            other => unreachable!("grammar rule {other:?} is not a directive"),
        };
        Directive {
            kind,
            without_hash,
            span,
        }
    }
}

/// One piece of a call's argument list, before its slot is sorted.
enum ArgumentPiece {
    Argument(Argument),
    Directive(Rc<Directive>),
}

/// The inner pairs of `pair` without its directive words.
/// The name an indexed expression starts from (`Fns` of `Fns[1][2]`), for messages.
fn root_name(expr: &Expr) -> Name {
    match expr {
        Expr::Index(base, _, _) => root_name(base),
        Expr::Ident(name, _) => *name,
        _ => Name::from("element"),
    }
}

fn significant(pair: Pair<Rule>) -> impl Iterator<Item = Pair<Rule>> {
    pair.into_inner()
        .filter(|p| !is_directive_word(p.as_rule()))
}

/// Directive words (`kw_*` rules) only mark where a directive starts.
fn is_directive_word(rule: Rule) -> bool {
    format!("{rule:?}").starts_with("kw_")
}

/// Resolves POV-Ray string escapes (`\n`, `\t`, `\\`, `\"`, ...).
fn unescape(raw: &str) -> String {
    let mut out = String::with_capacity(raw.len());
    let mut chars = raw.chars();
    while let Some(c) = chars.next() {
        if c != '\\' {
            out.push(c);
            continue;
        }
        match chars.next() {
            Some('n') => out.push('\n'),
            Some('t') => out.push('\t'),
            Some('r') => out.push('\r'),
            Some('a') => out.push('\u{7}'),
            Some('b') => out.push('\u{8}'),
            Some('f') => out.push('\u{c}'),
            Some('v') => out.push('\u{b}'),
            Some('0') => out.push('\0'),
            Some(other) => out.push(other),
            None => out.push('\\'),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use crate::syntax::ast::{Argument, Call, DirectiveKind, Expr, Item};

    /// The call that `text`, one call at the top level, lowers to.
    fn call(text: &str) -> Call {
        let items = crate::syntax::parse(text, 0).expect("parses");
        match items.first() {
            Some(Item::Expr(Expr::Call(call))) => (**call).clone(),
            other => panic!("not a call: {other:?}"),
        }
    }

    #[test]
    fn directives_among_arguments_are_placed_between_them() {
        let c = call("M(1, #declare R = 5; R, #local Q = 2;)");
        assert_eq!(c.arguments.len(), 3);
        assert_eq!(c.directives.len(), 1);
        assert_eq!(c.directives[0].before_argument, 1);
        assert!(!c.directives[0].follows_argument);
        // The directive alone after the last comma is that slot's argument.
        assert!(matches!(
            &c.arguments[2],
            Argument::Expr(Expr::Directive(_))
        ));
    }

    #[test]
    fn a_directive_right_after_an_argument_is_marked() {
        let c = call("M(1, 2 #declare Z = 3;)");
        assert_eq!(c.arguments.len(), 2);
        assert_eq!(c.directives[0].before_argument, 2);
        assert!(c.directives[0].follows_argument);
    }

    #[test]
    fn a_bare_if_is_a_value_at_the_end_of_its_slot_and_a_directive_before_more() {
        let c = call("max(1, #if (1) 2 #else 3 #end)");
        assert_eq!(c.arguments.len(), 2);
        assert!(c.directives.is_empty());
        let c = call("M(1, #if (1) #declare Y = 2; #end Y)");
        assert_eq!(c.arguments.len(), 2);
        assert!(matches!(&c.arguments[1], Argument::Expr(Expr::Ident(..))));
        assert!(matches!(
            c.directives[0].directive.kind,
            DirectiveKind::If { .. }
        ));
    }

    #[test]
    fn an_empty_slot_between_commas_is_refused() {
        assert!(crate::syntax::parse("M(1, , 2)", 0).is_err());
        assert!(crate::syntax::parse("M(1, #declare X = 1;, 2)", 0).is_err());
        assert!(crate::syntax::parse("M(, 1)", 0).is_err());
        assert!(crate::syntax::parse("M(1, 2,)", 0).is_ok());
    }
}
