//! Pattern syntax: the pattern keywords and pattern modifiers that may appear in `pigment`,
//! `normal`, `texture` and `density` blocks, and `warp { }` blocks.
//!
//! In: a keyword (or block) already taken from the owner's item stream. Out: a
//! [`Pattern`] or a modification of one. Holds: the owner (appearance.rs) parses maps,
//! block lists and transforms; everything specific to one pattern is parsed here. A
//! pattern without its own noise generator gets the global one in force when it is parsed
//! (patterns without their own follow the scene's last one, read when evaluated); `ripples` and `waves`
//! share the scene's wave sources, fixed from the last `number_of_waves` when parsing ends.

use glam::{DVec2, DVec3};
use std::sync::Arc;

use crate::diag::Span;
use crate::eval::language::stream::Stream;
use crate::eval::language::value::Value;
use crate::eval::{EvalResult, Evaluator};
use crate::geometry::World;
use crate::noise::NoiseGenerator;
use crate::syntax::ast::{Block, BlockHead, Expr, Item};
use crate::texture::pattern::{
    default_colour_map, Altitude, BlackHole, Colouring, Crackle, DensityFile, Fractal, FractalKind,
    MagnetType, Mapping, MappingKind, NoiseChoice, Pattern, PatternKind, Pavement, PavementPolygon,
    Repeat, Slope, Warp, WaveShape,
};

/// Largest fractal iteration count accepted (POV-Ray allows up to 2^32 − 1; more than this
/// would only make a render hang).
const MAX_FRACTAL_ITERATIONS: f64 = 1e6;

impl Evaluator {
    /// When `word` names a pattern, parses the pattern's own operands (such as gradient's
    /// direction) and returns it; `None` when `word` is not a pattern keyword. Block lists
    /// (`checker pigment {..}, pigment {..}`) are left for the owner.
    pub(crate) fn pattern_keyword(
        &mut self,
        word: &str,
        span: Span,
        stream: &mut Stream,
    ) -> EvalResult<Option<Pattern>> {
        let kind = match word {
            "agate" => PatternKind::Agate { agate_turb: 1.0 },
            "aoi" => PatternKind::Aoi,
            "boxed" => PatternKind::Boxed,
            "bozo" | "spotted" => PatternKind::Bozo,
            "brick" => PatternKind::Brick {
                size: DVec3::new(8.0, 3.0, 4.5),
                mortar: 0.5,
            },
            "bumps" => PatternKind::Bumps,
            "cells" => PatternKind::Cells,
            "checker" => PatternKind::Checker,
            "crackle" => PatternKind::Crackle(Crackle::default()),
            "cubic" => PatternKind::Cubic,
            "cylindrical" => PatternKind::Cylindrical,
            "dents" => PatternKind::Dents,
            "density_file" => self.density_file_operands(span, stream)?,
            "facets" => PatternKind::Facets {
                coords: 0.0,
                size: 0.1,
            },
            "gradient" => PatternKind::Gradient(self.expect_vector(stream, "a direction")?),
            // POV-Ray 3.5's form, `slope DIRECTION` without braces (no range, no altitude),
            // which povray 3.7 still reads (advanced/balcony's terrain.inc).
            "slope" => PatternKind::Slope(Slope::new(self.slope_direction(span, stream)?)),
            "granite" => PatternKind::Granite,
            "hexagon" => PatternKind::Hexagon,
            "julia" => {
                let c = self.expect_complex(stream)?;
                let iterations = self.expect_iterations(stream)?;
                PatternKind::Fractal(Fractal::new(FractalKind::Julia(c), iterations))
            }
            "leopard" => PatternKind::Leopard,
            "magnet" => self.magnet_operands(span, stream)?,
            "mandel" => {
                let iterations = self.expect_iterations(stream)?;
                PatternKind::Fractal(Fractal::new(FractalKind::Mandelbrot, iterations))
            }
            "marble" => PatternKind::Marble,
            "onion" => PatternKind::Onion,
            "pavement" => PatternKind::Pavement(Pavement::default()),
            "planar" => PatternKind::Planar,
            "quilted" => PatternKind::Quilted {
                control0: 1.0,
                control1: 1.0,
            },
            "radial" => PatternKind::Radial,
            "ripples" => PatternKind::Ripples(self.scene.settings.wave_sources.clone()),
            "spherical" => PatternKind::Spherical,
            "spiral1" => PatternKind::Spiral1(self.expect_float(stream, "a number of arms")?),
            "spiral2" => PatternKind::Spiral2(self.expect_float(stream, "a number of arms")?),
            "square" => PatternKind::Square,
            "tiling" => {
                let (value, number_span) = self.expect_value(stream, "a tiling number")?;
                let number = self.to_float(value, number_span)?.trunc();
                if !(1.0..=27.0).contains(&number) {
                    return Err(self
                        .runtime
                        .error(number_span, "the tiling number must be between 1 and 27")
                        .with_label(format!("this is {number}"))
                        .into());
                }
                // In range, so the conversion is exact.
                PatternKind::Tiling(number as u8)
            }
            "triangular" => PatternKind::Triangular,
            "waves" => PatternKind::Waves(self.scene.settings.wave_sources.clone()),
            "wood" => PatternKind::Wood,
            "wrinkles" => PatternKind::Wrinkles,
            _ => return Ok(None),
        };
        let mut pattern = self.new_pattern(kind);
        pattern.default_colour_map = default_colour_map(word);
        Ok(Some(pattern))
    }

    /// POV-Ray reads a pigment's pattern only as its first item: a pattern keyword after
    /// anything else (a modifier, a colour, a map) is an error there.
    pub(crate) fn pattern_not_first(
        &self,
        word: &str,
        span: Span,
        earlier: Span,
    ) -> Box<crate::diag::Diagnostic> {
        self.runtime
            .error(
                span,
                format!("the pattern `{word}` must come first in its block"),
            )
            .with_label("a pattern after other items")
            .with_secondary(earlier, "this comes before it")
            .with_help("write the pattern keyword first, then its modifiers and maps")
            .into()
    }

    /// [`Self::pattern_keyword`] for the blocks other than `normal` (pigment, texture,
    /// density, pattern functions): `facets` is refused there, as POV-Ray does ("can only be
    /// used in a normal statement").
    pub(crate) fn pattern_keyword_outside_normal(
        &mut self,
        word: &str,
        span: Span,
        stream: &mut Stream,
        owner: &str,
    ) -> EvalResult<Option<Pattern>> {
        let spec = self.pattern_keyword(word, span, stream)?;
        if let Some(Pattern {
            kind: PatternKind::Facets { .. },
            ..
        }) = spec
        {
            return Err(self
                .runtime
                .error(span, "`facets` can only be used in a `normal`")
                .with_label(format!("not allowed in a `{owner}`"))
                .with_help("facets only tilts normals: write it as `normal { facets .. }`")
                .into());
        }
        Ok(spec)
    }

    /// When `item` is a pattern written as a block (`function { .. }`, `image_pattern { .. }`,
    /// `pigment_pattern { .. }`, `slope { .. }`, `object { .. }`), parses it. For `object`
    /// the block list (the items for outside and inside) is inside the block: the stream
    /// holding it comes back too, for the owner to read the list from.
    pub(crate) fn block_pattern(
        &mut self,
        item: &Item,
    ) -> EvalResult<Option<(Pattern, Option<Stream>)>> {
        if let Item::Expr(Expr::Function(literal)) = item {
            let function = self.compile_function(literal)?;
            return Ok(Some((
                self.new_pattern(PatternKind::Function(function)),
                None,
            )));
        }
        let Item::Block(block) = item else {
            return Ok(None);
        };
        let BlockHead::Word(head) = &block.head else {
            return Ok(None);
        };
        let mut body = Stream::new(block.body.clone());
        let kind = match &**head {
            "image_pattern" => return Ok(self.image_pattern(item)?.map(|spec| (spec, None))),
            "pigment_pattern" => {
                let pigment = self.eval_pigment(&mut body)?;
                PatternKind::PigmentPattern(Arc::new(pigment))
            }
            "slope" => PatternKind::Slope(self.slope_body(block.head_span, &mut body)?),
            "object" => {
                let (value, span) = self.expect_value(&mut body, "an object")?;
                let object = match value {
                    Value::Object(object) => object,
                    other => {
                        return Err(self
                            .runtime
                            .error(
                                span,
                                format!("expected an object, found {}", other.type_name()),
                            )
                            .with_label("the `object` pattern needs an object")
                            .into())
                    }
                };
                let world = World::build_from_objects(vec![Arc::unwrap_or_clone(object)]);
                let pattern = self.new_pattern(PatternKind::Object(Arc::new(world)));
                return Ok(Some((pattern, Some(body))));
            }
            _ => return Ok(None),
        };
        Ok(Some((self.new_pattern(kind), None)))
    }

    /// The body of `slope { .. }`: `DIRECTION [, LO, HI] [altitude DIRECTION [, LO, HI]]`
    /// or `point_at POINT [, LO, HI]`.
    fn slope_body(&mut self, span: Span, stream: &mut Stream) -> EvalResult<Slope> {
        let point_at = match self.peek_item(stream)? {
            Some(Item::Keyword(word, _)) if &*word == "point_at" => {
                let _ = self.next_item(stream)?;
                Some(self.expect_vector(stream, "a point")?)
            }
            _ => None,
        };
        let direction = match point_at {
            Some(_) => DVec3::Y,
            None => self.slope_direction(span, stream)?,
        };
        let mut slope = Slope::new(direction);
        slope.point_at = point_at;
        if let Some(range) = self.optional_range(stream)? {
            slope.slope_range = range;
        }
        match self.next_item(stream)? {
            None => {}
            Some(Item::Keyword(word, word_span)) if &*word == "altitude" => {
                if point_at.is_some() {
                    return Err(self
                        .runtime
                        .error(
                            word_span,
                            "`altitude` cannot follow `point_at` in a `slope`",
                        )
                        .into());
                }
                let direction = self.expect_vector(stream, "an altitude direction")?;
                let range = self.optional_range(stream)?.unwrap_or((0.0, 1.0));
                slope.altitude = Some(Altitude {
                    direction: direction.try_normalize().unwrap_or(DVec3::ZERO),
                    weight: direction.length(),
                    range,
                });
                if let Some(extra) = self.next_item(stream)? {
                    return Err(self.unexpected_in(&extra, "slope"));
                }
            }
            Some(other) => return Err(self.unexpected_in(&other, "slope")),
        }
        Ok(slope)
    }

    /// A slope's direction vector, which must not be zero.
    fn slope_direction(&mut self, span: Span, stream: &mut Stream) -> EvalResult<DVec3> {
        let direction = self.expect_vector(stream, "a slope direction")?;
        if direction == DVec3::ZERO {
            return Err(self
                .runtime
                .error(span, "the `slope` direction must not be zero")
                .into());
        }
        Ok(direction)
    }

    /// An optional `, LOW, HIGH` pair.
    fn optional_range(&mut self, stream: &mut Stream) -> EvalResult<Option<(f64, f64)>> {
        match self.next_item(stream)? {
            Some(Item::Comma(_)) => {
                let low = self.expect_float(stream, "the low end of the range")?;
                self.skip_comma(stream)?;
                let high = self.expect_float(stream, "the high end of the range")?;
                Ok(Some((low, high)))
            }
            Some(other) => {
                stream.push_back(other);
                Ok(None)
            }
            None => Ok(None),
        }
    }

    /// When `word` is a pattern modifier (`turbulence`, `octaves`, `frequency`, wave types,
    /// pattern-specific settings such as `brick_size`...), parses its operands into `pattern`
    /// and returns true; false when `word` is not a pattern modifier.
    pub(crate) fn pattern_modifier(
        &mut self,
        word: &str,
        span: Span,
        stream: &mut Stream,
        pattern: &mut Pattern,
    ) -> EvalResult<bool> {
        match word {
            "turbulence" => pattern.turbulence.amount = self.expect_amount(stream)?,
            "octaves" => pattern.turbulence.shape.octaves = self.expect_octaves(stream)?,
            "omega" => pattern.turbulence.shape.omega = self.expect_float(stream, "a float")?,
            "lambda" => pattern.turbulence.shape.lambda = self.expect_float(stream, "a float")?,
            "frequency" => pattern.wave.frequency = self.expect_float(stream, "a float")?,
            "phase" => pattern.wave.phase = self.expect_float(stream, "a float")?,
            "ramp_wave" => pattern.wave.shape = WaveShape::Ramp,
            "triangle_wave" => pattern.wave.shape = WaveShape::Triangle,
            "sine_wave" => pattern.wave.shape = WaveShape::Sine,
            "scallop_wave" => pattern.wave.shape = WaveShape::Scallop,
            "cubic_wave" => pattern.wave.shape = WaveShape::Cubic,
            "poly_wave" => {
                let exponent = match self.peek_item(stream)? {
                    Some(Item::Expr(_)) => self.expect_float(stream, "an exponent")?,
                    _ => 1.0,
                };
                pattern.wave.shape = WaveShape::Poly(exponent);
            }
            "noise_generator" => match self.expect_noise_generator(stream)? {
                Some(generator) => pattern.noise = NoiseChoice::Own(generator),
                None => {
                    pattern.noise =
                        NoiseChoice::Scene(self.scene.settings.scene_noise_generator.clone())
                }
            },
            _ => return self.pattern_setting(word, span, stream, pattern),
        }
        Ok(true)
    }

    /// The settings that belong to one pattern (`brick_size`, `form`, `exponent`...); an
    /// error when written for another pattern.
    fn pattern_setting(
        &mut self,
        word: &str,
        span: Span,
        stream: &mut Stream,
        pattern: &mut Pattern,
    ) -> EvalResult<bool> {
        let owner = match word {
            "agate_turb" => "agate",
            "brick_size" | "mortar" => "brick",
            "control0" | "control1" => "quilted",
            "metric" | "offset" | "solid" => "crackle",
            "form" => "crackle or pavement",
            "coords" | "size" => "facets",
            "exponent" => "mandel, julia or magnet",
            "interior" | "exterior" => "mandel, julia, magnet or pavement",
            "number_of_sides" | "number_of_tiles" | "pattern" => "pavement",
            "interpolate" => "density_file",
            _ => return Ok(false),
        };
        match (&mut pattern.kind, word) {
            (PatternKind::Agate { agate_turb }, "agate_turb") => {
                *agate_turb = self.expect_float(stream, "a float")?
            }
            (PatternKind::Brick { size, .. }, "brick_size") => {
                let given = self.expect_amount(stream)?;
                if given.min_element() <= 0.0 {
                    return Err(self
                        .runtime
                        .error(span, "`brick_size` must be positive in every direction")
                        .into());
                }
                *size = given;
            }
            (PatternKind::Brick { mortar, .. }, "mortar") => {
                *mortar = self.expect_float(stream, "a float")?
            }
            (PatternKind::Quilted { control0, .. }, "control0") => {
                *control0 = self.expect_float(stream, "a float")?
            }
            (PatternKind::Quilted { control1, .. }, "control1") => {
                *control1 = self.expect_float(stream, "a float")?
            }
            (PatternKind::Crackle(crackle), "form") => {
                crackle.form = self.expect_vector(stream, "a form vector")?
            }
            (PatternKind::Crackle(crackle), "metric") => {
                crackle.metric = self.expect_float(stream, "a metric")?;
                if crackle.metric.is_nan() || crackle.metric <= 0.0 {
                    return Err(self.runtime.error(span, "`metric` must be positive").into());
                }
            }
            (PatternKind::Crackle(crackle), "offset") => {
                crackle.offset = self.expect_float(stream, "a float")?
            }
            (PatternKind::Crackle(crackle), "solid") => crackle.solid = true,
            (PatternKind::DensityFile { interpolation, .. }, "interpolate") => {
                let number = self.expect_float(stream, "an interpolation (0, 1 or 2)")?;
                *interpolation = match number {
                    0.0 => 0,
                    1.0 => 1,
                    2.0 => 2,
                    _ => {
                        return Err(self
                            .runtime
                            .error(span, "the `density_file` interpolation must be 0, 1 or 2")
                            .into())
                    }
                };
            }
            (PatternKind::Facets { coords, .. }, "coords") => {
                *coords = self.expect_float(stream, "a float")?
            }
            (PatternKind::Facets { size, .. }, "size") => {
                *size = self.expect_float(stream, "a float")?
            }
            (PatternKind::Fractal(fractal), "exponent") => {
                let exponent = self.expect_float(stream, "an exponent")?;
                if !(2.0..=33.0).contains(&exponent) {
                    return Err(self
                        .runtime
                        .error(span, "the fractal `exponent` must be between 2 and 33")
                        .into());
                }
                fractal.exponent = exponent as u32;
            }
            (PatternKind::Fractal(fractal), which @ ("interior" | "exterior")) => {
                let kind = self.expect_float(stream, "a colouring type")?;
                let factor = self.expect_float(stream, "a factor")?;
                let limit = if which == "exterior" { 8.0 } else { 6.0 };
                if !(0.0..=limit).contains(&kind) {
                    return Err(self
                        .runtime
                        .error(span, format!("the `{which}` type must be 0 to {limit}"))
                        .into());
                }
                let colouring = Colouring {
                    kind: kind as u32,
                    factor,
                };
                if which == "exterior" {
                    fractal.exterior = colouring;
                } else {
                    fractal.interior = colouring;
                }
            }
            (
                PatternKind::Pavement(pavement),
                "number_of_sides" | "number_of_tiles" | "pattern" | "form" | "interior"
                | "exterior",
            ) => self.pavement_setting(word, stream, pavement)?,
            _ => {
                return Err(self
                    .runtime
                    .error(span, format!("`{word}` only applies to {owner}"))
                    .with_label("not a modifier of this pattern")
                    .into())
            }
        }
        Ok(true)
    }

    /// When `block` is a pattern modifier block (`warp { .. }`), applies it to `pattern` and
    /// returns true; false for other blocks.
    pub(crate) fn pattern_block(
        &mut self,
        block: &Block,
        pattern: &mut Pattern,
    ) -> EvalResult<bool> {
        if !matches!(&block.head, BlockHead::Word(w) if &**w == "warp") {
            return Ok(false);
        }
        let mut stream = Stream::new(block.body.clone());
        let mut warp = self.eval_warp(block.head_span, &mut stream)?;
        if let Warp::BlackHole(hole) = &mut warp {
            self.fit_repeated_black_hole(block.head_span, hole);
        }
        pattern.add_warp(warp);
        Ok(true)
    }

    /// POV-Ray keeps each copy of a repeated black hole inside its cell: on every repeated
    /// axis a centre closer to the cell's start than the radius moves out to the radius
    /// (measured), and a cell too small for centre, radius and jitter grows, with a warning.
    fn fit_repeated_black_hole(&mut self, span: Span, hole: &mut BlackHole) {
        let mut grew = false;
        for axis in 0..3 {
            if hole.repeat[axis] <= 0.0 {
                continue;
            }
            hole.centre[axis] = hole.centre[axis].max(hole.radius);
            let needed = hole.centre[axis] + hole.radius + hole.jitter[axis].abs();
            if hole.repeat[axis] < needed {
                hole.repeat[axis] = needed;
                grew = true;
            }
        }
        if grew {
            self.runtime.warn(
                span,
                "black hole `repeat` is too small for the centre, radius and turbulence; it was \
                 enlarged",
            );
        }
    }

    /// The body of `warp { .. }`: one warp kind followed by its settings.
    fn eval_warp(&mut self, head_span: Span, stream: &mut Stream) -> EvalResult<Warp> {
        let mut warp: Option<Warp> = None;
        while let Some(item) = self.next_item(stream)? {
            let (word, span) = match &item {
                Item::Keyword(word, span) => (*word, *span),
                Item::Comma(_) => continue,
                _ => return Err(self.unexpected_in(&item, "warp")),
            };
            match (&*word, &mut warp) {
                ("turbulence", None) => {
                    warp = Some(Warp::Turbulence {
                        amount: self.expect_amount(stream)?,
                        shape: Default::default(),
                    })
                }
                ("black_hole", None) => {
                    let centre = self.expect_vector(stream, "a centre")?;
                    let radius = self.expect_float(stream, "a radius")?;
                    warp = Some(Warp::BlackHole(BlackHole::new(centre, radius)));
                }
                ("repeat", None) => {
                    let direction = self.expect_vector(stream, "a direction")?;
                    let axes: Vec<usize> = (0..3).filter(|&a| direction[a] != 0.0).collect();
                    let [axis] = axes[..] else {
                        return Err(self
                            .runtime
                            .error(span, "the `repeat` direction must lie along one axis")
                            .into());
                    };
                    warp = Some(Warp::Repeat(Repeat {
                        axis,
                        width: direction[axis],
                        offset: DVec3::ZERO,
                        flip: [false; 3],
                    }));
                }
                ("cylindrical", None) => {
                    warp = Some(Warp::Mapping(Mapping::new(MappingKind::Cylindrical)))
                }
                ("spherical", None) => {
                    warp = Some(Warp::Mapping(Mapping::new(MappingKind::Spherical)))
                }
                ("toroidal", None) => {
                    warp = Some(Warp::Mapping(Mapping::new(MappingKind::Toroidal)))
                }
                ("planar", None) => {
                    let (normal, distance) = match self.peek_item(stream)? {
                        Some(Item::Expr(_)) => {
                            let normal = self.expect_vector(stream, "a plane normal")?;
                            let distance = self.expect_float(stream, "a distance")?;
                            (normal, distance)
                        }
                        _ => (DVec3::Z, 0.0),
                    };
                    let Some(normal) = normal.try_normalize() else {
                        return Err(self
                            .runtime
                            .error(span, "the `planar` warp needs a non-zero normal")
                            .into());
                    };
                    warp = Some(Warp::Planar { normal, distance });
                }
                ("octaves", Some(Warp::Turbulence { shape, .. })) => {
                    shape.octaves = self.expect_octaves(stream)?
                }
                ("omega", Some(Warp::Turbulence { shape, .. })) => {
                    shape.omega = self.expect_float(stream, "a float")?
                }
                ("lambda", Some(Warp::Turbulence { shape, .. })) => {
                    shape.lambda = self.expect_float(stream, "a float")?
                }
                ("strength", Some(Warp::BlackHole(hole))) => {
                    hole.strength = self.expect_float(stream, "a float")?
                }
                ("falloff", Some(Warp::BlackHole(hole))) => {
                    hole.falloff = self.expect_float(stream, "a float")?
                }
                ("inverse", Some(Warp::BlackHole(hole))) => hole.inverse = true,
                ("repeat", Some(Warp::BlackHole(hole))) => {
                    hole.repeat = self.expect_amount(stream)?.max(DVec3::ZERO)
                }
                ("turbulence", Some(Warp::BlackHole(hole))) => {
                    hole.jitter = self.expect_amount(stream)?
                }
                ("type", Some(Warp::BlackHole(_))) => {
                    let _ = self.expect_float(stream, "a type")?;
                }
                ("offset", Some(Warp::Repeat(repeat))) => {
                    repeat.offset = self.expect_vector(stream, "an offset")?
                }
                ("flip", Some(Warp::Repeat(repeat))) => {
                    let flip = self.expect_vector(stream, "a flip vector")?;
                    repeat.flip = [flip.x != 0.0, flip.y != 0.0, flip.z != 0.0];
                }
                ("orientation", Some(Warp::Mapping(mapping))) => {
                    let orientation = self.expect_vector(stream, "an orientation")?;
                    mapping.set_orientation(orientation);
                }
                ("dist_exp", Some(Warp::Mapping(mapping))) => {
                    mapping.dist_exp = self.expect_float(stream, "a float")?
                }
                ("major_radius", Some(Warp::Mapping(mapping))) => {
                    mapping.major_radius = self.expect_float(stream, "a float")?
                }
                _ => return Err(self.unexpected_in(&item, "warp")),
            }
        }
        match warp {
            Some(warp) => Ok(warp),
            None => Err(self
                .runtime
                .error(
                    head_span,
                    "a `warp` needs a kind: turbulence, black_hole, repeat, cylindrical, \
                     spherical, toroidal or planar",
                )
                .into()),
        }
    }

    /// `density_file df3 "FILE"`: reads the grid.
    /// One `pavement` setting. Each is checked against the settings written before it, so
    /// `number_of_sides`, `number_of_tiles` and `pattern` are best written in this order
    /// (POV-Ray checks them together at the end of the pattern).
    fn pavement_setting(
        &mut self,
        word: &str,
        stream: &mut Stream,
        pavement: &mut Pavement,
    ) -> EvalResult<()> {
        let (value, number_span) = self.expect_value(stream, "a number")?;
        let number = self.to_float(value, number_span)?;
        match word {
            "number_of_sides" => {
                let Some(polygon) = PavementPolygon::from_sides(number) else {
                    return Err(self
                        .runtime
                        .error(
                            number_span,
                            "`number_of_sides` of pavement must be 3, 4 or 6",
                        )
                        .into());
                };
                pavement.polygon = polygon;
            }
            "number_of_tiles" => pavement.tiles = number.trunc().clamp(0.0, 255.0) as u8,
            "pattern" => pavement.pattern = number.trunc().clamp(0.0, 255.0) as u8,
            "form" => pavement.form = crate::texture::pattern::pavement_corner_setting(number, 4),
            "exterior" => {
                pavement.exterior = crate::texture::pattern::pavement_corner_setting(number, 3)
            }
            _ => pavement.interior = crate::texture::pattern::pavement_corner_setting(number, 3),
        }
        let max_tiles = pavement.polygon.max_tiles();
        if !(1..=max_tiles).contains(&pavement.tiles) {
            return Err(self
                .runtime
                .error(
                    number_span,
                    format!("`number_of_tiles` of this pavement must be between 1 and {max_tiles}"),
                )
                .into());
        }
        let count = pavement.polygon.pattern_count(pavement.tiles);
        if !(1..=count).contains(&pavement.pattern) {
            return Err(self
                .runtime
                .error(
                    number_span,
                    format!(
                        "`pattern` of this pavement must be between 1 and {count} (tiles of {} \
                         polygons)",
                        pavement.tiles
                    ),
                )
                .into());
        }
        Ok(())
    }

    fn density_file_operands(
        &mut self,
        span: Span,
        stream: &mut Stream,
    ) -> EvalResult<PatternKind> {
        match self.next_item(stream)? {
            Some(Item::Keyword(word, _)) if &*word == "df3" => {}
            Some(other) => {
                return Err(self
                    .runtime
                    .error(
                        other.span(),
                        "expected `df3` (the only density file format)",
                    )
                    .with_label("expected `df3`")
                    .into())
            }
            None => {
                return Err(self
                    .runtime
                    .error(span, "expected `df3 \"FILE\"` after `density_file`")
                    .into())
            }
        }
        let (value, name_span) = self.expect_value(stream, "a file name")?;
        let Value::String(name) = value else {
            return Err(self
                .runtime
                .error(name_span, "expected the density file's name in quotes")
                .into());
        };
        let path = self
            .runtime
            .find_file(&name, name_span, "density file", "no such file")?;
        let grid = self
            .runtime
            .read_file_bytes(&path)
            .map_err(|error| error.to_string())
            .and_then(|bytes| DensityFile::parse(&bytes))
            .map(|mut grid| {
                grid.path = Some(path.clone());
                grid
            })
            .map_err(|message| {
                self.runtime
                    .error(
                        name_span,
                        format!("cannot read density file \"{name}\": {message}"),
                    )
                    .with_label("unreadable density file")
            })?;
        Ok(PatternKind::DensityFile {
            grid: Arc::new(grid),
            interpolation: 0,
        })
    }

    /// `magnet 1|2 mandel ITERATIONS` or `magnet 1|2 julia COMPLEX, ITERATIONS`.
    fn magnet_operands(&mut self, span: Span, stream: &mut Stream) -> EvalResult<PatternKind> {
        let number = self.expect_float(stream, "a magnet type (1 or 2)")?;
        let magnet = match number as i64 {
            1 if number == 1.0 => MagnetType::One,
            2 if number == 2.0 => MagnetType::Two,
            _ => {
                return Err(self
                    .runtime
                    .error(span, "the magnet type must be 1 or 2")
                    .into())
            }
        };
        let kind = match self.next_item(stream)? {
            Some(Item::Keyword(word, _)) if &*word == "mandel" => {
                FractalKind::MagnetMandelbrot(magnet)
            }
            Some(Item::Keyword(word, _)) if &*word == "julia" => {
                FractalKind::MagnetJulia(magnet, self.expect_complex(stream)?)
            }
            _ => {
                return Err(self
                    .runtime
                    .error(span, "expected `mandel` or `julia` after the magnet type")
                    .into())
            }
        };
        let iterations = self.expect_iterations(stream)?;
        Ok(PatternKind::Fractal(Fractal::new(kind, iterations)))
    }

    /// A complex number written as a 2-D vector.
    fn expect_complex(&mut self, stream: &mut Stream) -> EvalResult<DVec2> {
        let (value, span) = self.expect_value(stream, "a complex number (a 2-D vector)")?;
        let vector = self.to_vector3(value, span)?;
        Ok(DVec2::new(vector.x, vector.y))
    }

    /// A fractal's iteration count.
    fn expect_iterations(&mut self, stream: &mut Stream) -> EvalResult<u32> {
        let (value, span) = self.expect_value(stream, "an iteration count")?;
        let count = self.to_float(value, span)?;
        if !(1.0..=MAX_FRACTAL_ITERATIONS).contains(&count) {
            return Err(self
                .runtime
                .error(
                    span,
                    format!("the iteration count must be between 1 and {MAX_FRACTAL_ITERATIONS}"),
                )
                .into());
        }
        Ok(count as u32)
    }

    /// A float or vector amount (a float applies to all three axes).
    fn expect_amount(&mut self, stream: &mut Stream) -> EvalResult<DVec3> {
        let (value, span) = self.expect_value(stream, "a float or vector")?;
        match value {
            Value::Float(amount) => Ok(DVec3::splat(amount)),
            other => self.to_vector3(other, span),
        }
    }

    /// `octaves N`: 1 to 10 (POV-Ray clamps to that range).
    fn expect_octaves(&mut self, stream: &mut Stream) -> EvalResult<u32> {
        let octaves = self.expect_float(stream, "a number of octaves")?;
        Ok(if octaves.is_nan() {
            1
        } else {
            octaves.clamp(1.0, 10.0) as u32
        })
    }

    /// A new pattern of `kind` following the scene's global noise generator.
    pub(crate) fn new_pattern(&self, kind: PatternKind) -> Pattern {
        let mut pattern = Pattern::new(kind);
        pattern.use_scene_noise_generator(&self.scene.settings.scene_noise_generator);
        pattern
    }

    /// `noise_generator N` with N 0, 1, 2 or 3; `None` for 0, which means "the default"
    /// (for a pattern the global setting, globally generator 2).
    pub(crate) fn expect_noise_generator(
        &mut self,
        stream: &mut Stream,
    ) -> EvalResult<Option<NoiseGenerator>> {
        let (value, span) = self.expect_value(stream, "a noise generator (0, 1, 2 or 3)")?;
        let number = self.to_float(value, span)?;
        if number == 0.0 {
            return Ok(None);
        }
        let generator = if number.fract() == 0.0 {
            NoiseGenerator::from_number(number as i64)
        } else {
            None
        };
        match generator {
            Some(generator) => Ok(Some(generator)),
            None => Err(self
                .runtime
                .error(span, "the noise generator must be 0, 1, 2 or 3")
                .into()),
        }
    }
}

impl Evaluator {
    /// `global_settings { number_of_waves N }`: how many wave sources the scene's `ripples`
    /// and `waves` patterns use. As povray, N is truncated and a value
    /// below 1 becomes 1 with a warning; durer also limits it to
    /// [`crate::texture::pattern::MAX_WAVE_COUNT`] (with a warning).
    pub(crate) fn number_of_waves(&mut self, stream: &mut Stream) -> EvalResult<()> {
        let (value, span) = self.expect_value(stream, "a number of waves")?;
        let requested = self.to_float(value, span)?.trunc();
        let limit = crate::texture::pattern::MAX_WAVE_COUNT;
        let count = if requested.is_nan() || requested < 1.0 {
            self.runtime
                .warn(span, "number_of_waves must be greater than 0; 1 is used");
            1
        } else if requested > limit as f64 {
            self.runtime.warn(
                span,
                format!("number_of_waves above {limit} is limited to {limit}"),
            );
            limit
        } else {
            requested as usize
        };
        self.scene.settings.number_of_waves = count;
        Ok(())
    }
}
