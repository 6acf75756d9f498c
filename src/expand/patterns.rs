//! Patterns: the kind with its parameters, then the modifiers (wave, turbulence, noise
//! generator), the warps each in the frame it was written in, and the transformation.

use super::appearance::{write_image_block, write_pigment, ImageRole, PigmentRole};
use super::functions::write_function_block;
use super::{matrix, noise_number, number, relative, vector, Unsupported, Writer, Written};
use crate::math::Transform;
use crate::noise::TurbulenceShape;
use crate::texture::pattern::{
    FractalKind, MagnetType, MappingKind, NoiseChoice, Pattern, PatternKind, PavementPolygon, Warp,
    WaveShape,
};
use std::fmt::Write as _;

/// The pattern, its modifiers and `transform` (written relative to `parent`).
pub(super) fn write_pattern_block(
    writer: &mut Writer,
    out: &mut String,
    pattern: &Pattern,
    transform: &Transform,
    parent: &Transform,
) -> Written {
    write_pattern_kind(writer, out, pattern)?;
    write_pattern_modifiers(out, pattern, transform, parent);
    Ok(())
}

/// ` octaves O omega W lambda L`.
pub(super) fn write_turbulence_shape(out: &mut String, shape: &TurbulenceShape) {
    let _ = write!(
        out,
        " octaves {} omega {} lambda {}",
        shape.octaves,
        number(shape.omega),
        number(shape.lambda)
    );
}

/// The modifiers and the transformation: each warp is written after the transformations
/// that came before it, so that it is placed in the same frame.
pub(super) fn write_pattern_modifiers(
    out: &mut String,
    pattern: &Pattern,
    transform: &Transform,
    parent: &Transform,
) {
    let default_shape = match pattern.kind {
        PatternKind::Marble
        | PatternKind::Wood
        | PatternKind::Spiral1(_)
        | PatternKind::Spiral2(_) => WaveShape::Triangle,
        _ => WaveShape::Ramp,
    };
    if let PatternKind::Brick { size, mortar } = &pattern.kind {
        let _ = write!(
            out,
            " brick_size {} mortar {}",
            vector(*size),
            number(*mortar)
        );
    }
    let wave = &pattern.wave;
    if wave.shape != default_shape {
        match wave.shape {
            WaveShape::Ramp => out.push_str(" ramp_wave"),
            WaveShape::Triangle => out.push_str(" triangle_wave"),
            WaveShape::Sine => out.push_str(" sine_wave"),
            WaveShape::Scallop => out.push_str(" scallop_wave"),
            WaveShape::Cubic => out.push_str(" cubic_wave"),
            WaveShape::Poly(exponent) => {
                let _ = write!(out, " poly_wave {}", number(exponent));
            }
        }
    }
    if wave.frequency != 1.0 {
        let _ = write!(out, " frequency {}", number(wave.frequency));
    }
    if wave.phase != 0.0 {
        let _ = write!(out, " phase {}", number(wave.phase));
    }
    if let NoiseChoice::Own(generator) = &pattern.noise {
        let _ = write!(out, " noise_generator {}", noise_number(*generator));
    }
    let turbulence = &pattern.turbulence;
    if turbulence.amount != glam::DVec3::ZERO {
        let _ = write!(out, " turbulence {}", vector(turbulence.amount));
        write_turbulence_shape(out, &turbulence.shape);
    }
    let mut frame = Transform::IDENTITY;
    for placed in &pattern.warps {
        out.push_str(&matrix(&relative(&placed.frame, &frame)));
        frame = placed.frame;
        out.push_str(" warp { ");
        write_warp(out, &placed.warp);
        out.push_str(" }");
    }
    // What remains: the transformations after the last warp, then the enclosing ones that
    // the enclosing block does not apply itself.
    let own = relative(transform, parent);
    out.push_str(&matrix(&relative(&own, &frame)));
}

fn write_warp(out: &mut String, warp: &Warp) {
    match warp {
        Warp::Turbulence { amount, shape } => {
            let _ = write!(out, "turbulence {}", vector(*amount));
            write_turbulence_shape(out, shape);
        }
        Warp::BlackHole(hole) => {
            let _ = write!(
                out,
                "black_hole {}, {} falloff {} strength {} repeat {} turbulence {}",
                vector(hole.centre),
                number(hole.radius),
                number(hole.falloff),
                number(hole.strength),
                vector(hole.repeat),
                vector(hole.jitter)
            );
            if hole.inverse {
                out.push_str(" inverse");
            }
        }
        Warp::Repeat(repeat) => {
            let mut direction = glam::DVec3::ZERO;
            direction[repeat.axis] = repeat.width;
            let flip = glam::DVec3::new(
                f64::from(u8::from(repeat.flip[0])),
                f64::from(u8::from(repeat.flip[1])),
                f64::from(u8::from(repeat.flip[2])),
            );
            let _ = write!(
                out,
                "repeat {} offset {} flip {}",
                vector(direction),
                vector(repeat.offset),
                vector(flip)
            );
        }
        Warp::Mapping(mapping) => {
            let word = match mapping.kind {
                MappingKind::Cylindrical => "cylindrical",
                MappingKind::Spherical => "spherical",
                MappingKind::Toroidal => "toroidal",
            };
            let _ = write!(
                out,
                "{word} orientation {} dist_exp {}",
                vector(mapping.orientation),
                number(mapping.dist_exp)
            );
            if mapping.kind == MappingKind::Toroidal {
                let _ = write!(out, " major_radius {}", number(mapping.major_radius));
            }
        }
        Warp::Planar { normal, distance } => {
            let _ = write!(out, "planar {}, {}", vector(*normal), number(*distance));
        }
    }
}

/// The pattern's keyword and its own parameters.
pub(super) fn write_pattern_kind(
    writer: &mut Writer,
    out: &mut String,
    pattern: &Pattern,
) -> Written {
    let word = match &pattern.kind {
        PatternKind::Function(function) => {
            return write_function_block(writer, out, function, &["x", "y", "z"]);
        }
        PatternKind::Agate { agate_turb } => {
            let _ = write!(out, "agate agate_turb {}", number(*agate_turb));
            return Ok(());
        }
        PatternKind::Boxed => "boxed",
        PatternKind::Bozo => "bozo",
        // Its size and mortar are written with the modifiers: a brick's two colours or
        // pigments must follow the keyword directly.
        PatternKind::Brick { .. } => "brick",
        PatternKind::Bumps => "bumps",
        PatternKind::Cells => "cells",
        PatternKind::Checker => "checker",
        PatternKind::Crackle(crackle) => {
            let _ = write!(
                out,
                "crackle form {} metric {} offset {}{}",
                vector(crackle.form),
                number(crackle.metric),
                number(crackle.offset),
                if crackle.solid { " solid" } else { "" }
            );
            return Ok(());
        }
        PatternKind::Cubic => "cubic",
        PatternKind::Cylindrical => "cylindrical",
        PatternKind::Dents => "dents",
        PatternKind::DensityFile {
            grid,
            interpolation,
        } => {
            let Some(path) = &grid.path else {
                return Err(Unsupported("a density_file of unknown origin".into()));
            };
            let _ = write!(
                out,
                "density_file df3 {} interpolate {interpolation}",
                writer.file_name(path)
            );
            return Ok(());
        }
        PatternKind::Facets { coords, size } => {
            if *coords != 0.0 {
                let _ = write!(out, "facets coords {}", number(*coords));
            } else {
                let _ = write!(out, "facets size {}", number(*size));
            }
            return Ok(());
        }
        PatternKind::Fractal(fractal) => {
            let magnet = |t: &MagnetType| match t {
                MagnetType::One => 1,
                MagnetType::Two => 2,
            };
            match &fractal.kind {
                FractalKind::Mandelbrot => {
                    let _ = write!(out, "mandel {}", fractal.iterations);
                }
                FractalKind::Julia(c) => {
                    let _ = write!(
                        out,
                        "julia <{}, {}>, {}",
                        number(c.x),
                        number(c.y),
                        fractal.iterations
                    );
                }
                FractalKind::MagnetMandelbrot(t) => {
                    let _ = write!(out, "magnet {} mandel {}", magnet(t), fractal.iterations);
                }
                FractalKind::MagnetJulia(t, c) => {
                    let _ = write!(
                        out,
                        "magnet {} julia <{}, {}>, {}",
                        magnet(t),
                        number(c.x),
                        number(c.y),
                        fractal.iterations
                    );
                }
            }
            if !matches!(
                fractal.kind,
                FractalKind::MagnetMandelbrot(_) | FractalKind::MagnetJulia(..)
            ) {
                let _ = write!(out, " exponent {}", fractal.exponent);
            }
            let _ = write!(
                out,
                " interior {}, {} exterior {}, {}",
                fractal.interior.kind,
                number(fractal.interior.factor),
                fractal.exterior.kind,
                number(fractal.exterior.factor)
            );
            return Ok(());
        }
        PatternKind::Gradient(direction) => {
            let _ = write!(out, "gradient {}", vector(*direction));
            return Ok(());
        }
        PatternKind::Granite => "granite",
        PatternKind::Hexagon => "hexagon",
        PatternKind::Leopard => "leopard",
        PatternKind::Marble => "marble",
        PatternKind::Onion => "onion",
        PatternKind::Pavement(p) => {
            let sides = match p.polygon {
                PavementPolygon::Triangle => 3,
                PavementPolygon::Square => 4,
                PavementPolygon::Hexagon => 6,
            };
            let _ = write!(
                out,
                "pavement number_of_sides {sides} number_of_tiles {} pattern {} form {} \
                 exterior {} interior {}",
                p.tiles, p.pattern, p.form, p.exterior, p.interior
            );
            return Ok(());
        }
        PatternKind::Planar => "planar",
        PatternKind::Quilted { control0, control1 } => {
            let _ = write!(
                out,
                "quilted control0 {} control1 {}",
                number(*control0),
                number(*control1)
            );
            return Ok(());
        }
        PatternKind::Radial => "radial",
        PatternKind::Ripples(_) => "ripples",
        PatternKind::Slope(slope) => {
            out.push_str("slope { ");
            match slope.point_at {
                Some(point) => {
                    let _ = write!(out, "point_at {}", vector(point));
                }
                None => out.push_str(&vector(slope.direction * slope.slope_weight)),
            }
            let _ = write!(
                out,
                ", {}, {}",
                number(slope.slope_range.0),
                number(slope.slope_range.1)
            );
            if let Some(altitude) = &slope.altitude {
                let _ = write!(
                    out,
                    " altitude {}, {}, {}",
                    vector(altitude.direction * altitude.weight),
                    number(altitude.range.0),
                    number(altitude.range.1)
                );
            }
            out.push_str(" }");
            return Ok(());
        }
        PatternKind::Aoi => "aoi",
        PatternKind::PigmentPattern(pigment) => {
            out.push_str("pigment_pattern { ");
            let mut inner = String::new();
            write_pigment(
                writer,
                &mut inner,
                pigment,
                &Transform::IDENTITY,
                PigmentRole::Pigment,
            )?;
            // `pigment { .. }` without its keyword: the pattern's block holds the items.
            let items = inner
                .strip_prefix("pigment {")
                .and_then(|rest| rest.strip_suffix('}'))
                .unwrap_or(&inner);
            out.push_str(items);
            out.push_str(" }");
            return Ok(());
        }
        PatternKind::Object(_) => {
            return Err(Unsupported("an object pattern".into()));
        }
        PatternKind::Spherical => "spherical",
        PatternKind::Spiral1(arms) => {
            let _ = write!(out, "spiral1 {}", number(*arms));
            return Ok(());
        }
        PatternKind::Spiral2(arms) => {
            let _ = write!(out, "spiral2 {}", number(*arms));
            return Ok(());
        }
        PatternKind::Square => "square",
        PatternKind::Tiling(n) => {
            let _ = write!(out, "tiling {n}");
            return Ok(());
        }
        PatternKind::Triangular => "triangular",
        PatternKind::Waves(_) => "waves",
        PatternKind::Wood => "wood",
        PatternKind::Wrinkles => "wrinkles",
        PatternKind::ImagePattern(image) => {
            out.push_str("image_pattern ");
            return write_image_block(writer, out, image, ImageRole::Pattern);
        }
    };
    out.push_str(word);
    Ok(())
}
