//! `durer expand`: the evaluated [`Scene`] written back as flat POV-Ray SDL.
//!
//! In: a [`Scene`] (every macro, loop, conditional, include and identifier already gone).
//! Out: SDL text that `povray` and durer read back to the same scene: objects, textures,
//! lights, camera, settings and atmosphere written out in full. Holds: numbers are printed
//! in the shortest form that reads back to the same `f64`; a texture, mesh or function
//! held in more than one place (one `Arc`) is written once as `#declare Name_N` and named
//! wherever it is used, so a generated scene of 160,000 boxes sharing one texture stays
//! a file of 160,000 short lines. The only directives written are `#version` and
//! `#declare`.
//!
//! Layout: `objects.rs` (shapes, CSG, object modifiers), `appearance.rs` (textures,
//! pigments, normals, finishes, interiors, media), `patterns.rs` (pattern kinds, their
//! modifiers and warps), `functions.rs` (user functions back to expressions),
//! `settings.rs` (global settings, camera, lights, atmosphere).

mod appearance;
mod functions;
mod objects;
mod patterns;
mod settings;

use crate::math::{Colour, Transform};
use crate::scene::Scene;
use glam::{DVec2, DVec3};
use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// How to write the flat file.
#[derive(Clone, Debug, Default)]
pub struct ExpandOptions {
    /// File names (images, fonts' data, density files) are written relative to this
    /// folder when they lie under it, else absolute.
    pub base: Option<PathBuf>,
}

/// Something the scene holds that flat SDL cannot say (or durer cannot yet write back).
#[derive(Clone, Debug, PartialEq)]
pub struct Unsupported(pub String);

impl std::fmt::Display for Unsupported {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "cannot write {} as flat SDL", self.0)
    }
}

/// The result of each writer.
type Written = Result<(), Unsupported>;

/// Writes `scene` as flat SDL.
pub fn expand_scene(scene: &Scene, options: &ExpandOptions) -> Result<String, Unsupported> {
    let mut writer = Writer::new(options.clone());
    let mut body = String::new();
    settings::write_scene(&mut writer, &mut body, scene)?;
    let mut text = String::with_capacity(writer.declarations.len() + body.len() + 256);
    text.push_str("// Flat SDL written by `durer expand`: no macros, loops or includes.\n");
    if scene.settings.version_declared {
        let _ = writeln!(
            text,
            "#version {};",
            number(scene.settings.language_version)
        );
    }
    text.push_str(&writer.declarations);
    text.push_str(&body);
    Ok(text)
}

/// The state shared while writing: declarations made so far, by the address of what they
/// declare.
pub(crate) struct Writer {
    options: ExpandOptions,
    /// `#declare` lines, in the order they must be read.
    declarations: String,
    /// Names given to shared things, by address.
    names: HashMap<usize, String>,
    /// The next number of each name prefix.
    counts: HashMap<&'static str, usize>,
    /// Texture text seen so far: `None` once, the declared name from the second time on
    /// (evaluation gives each object its own copy of a declared texture, so sharing is
    /// found by content).
    texture_texts: HashMap<String, Option<String>>,
}

impl Writer {
    fn new(options: ExpandOptions) -> Writer {
        Writer {
            options,
            declarations: String::new(),
            names: HashMap::new(),
            counts: HashMap::new(),
            texture_texts: HashMap::new(),
        }
    }

    /// The name declared for the thing at `address`, writing its declaration with `write`
    /// the first time it is asked for.
    pub(crate) fn declared(
        &mut self,
        address: usize,
        prefix: &'static str,
        write: impl FnOnce(&mut Writer, &mut String) -> Written,
    ) -> Result<String, Unsupported> {
        if let Some(name) = self.names.get(&address) {
            return Ok(name.clone());
        }
        let mut text = String::new();
        write(self, &mut text)?;
        let count = self.counts.entry(prefix).or_insert(0);
        *count += 1;
        let name = format!("{prefix}_{count}");
        let _ = writeln!(self.declarations, "#declare {name} =\n{text}");
        self.names.insert(address, name.clone());
        Ok(name)
    }

    /// `text` (a texture's blocks) as written where it is used: itself the first time, a
    /// declared name once the same text comes again.
    pub(crate) fn shared_text(&mut self, text: String, keyword: &str) -> String {
        const WORTH_SHARING: usize = 48;
        if text.len() < WORTH_SHARING || keyword != "texture" {
            return text;
        }
        match self.texture_texts.get(&text) {
            None => {
                self.texture_texts.insert(text.clone(), None);
                text
            }
            Some(Some(name)) => format!(" {keyword} {{ {name} }}"),
            Some(None) => {
                let count = self.counts.entry("Texture").or_insert(0);
                *count += 1;
                let name = format!("Texture_{count}");
                let _ = writeln!(self.declarations, "#declare {name} ={text}");
                self.texture_texts.insert(text, Some(name.clone()));
                format!(" {keyword} {{ {name} }}")
            }
        }
    }

    /// The format keyword and file name of an image file: POV-Ray has no `sys` format, so a
    /// file given without one is named by its extension.
    pub(crate) fn image_file(&self, format: crate::raster::RasterFormat, path: &Path) -> String {
        use crate::raster::RasterFormat;
        let format = match format {
            RasterFormat::System => path
                .extension()
                .and_then(|e| e.to_str())
                .map(|e| e.to_ascii_lowercase())
                .and_then(|e| {
                    RasterFormat::from_keyword(match e.as_str() {
                        "jpg" => "jpeg",
                        other => other,
                    })
                })
                .unwrap_or(RasterFormat::Png),
            other => other,
        };
        format!("{} {}", format.keyword(), self.file_name(path))
    }

    /// A file name as the flat file should name it.
    pub(crate) fn file_name(&self, path: &Path) -> String {
        let shown = match &self.options.base {
            Some(base) => path.strip_prefix(base).unwrap_or(path),
            None => path,
        };
        string_literal(&shown.to_string_lossy())
    }
}

/// The address of a shared value (its `Arc`'s allocation).
pub(crate) fn address<T: ?Sized>(arc: &std::sync::Arc<T>) -> usize {
    std::sync::Arc::as_ptr(arc) as *const u8 as usize
}

/// A string as an SDL string literal.
pub(crate) fn string_literal(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\t' => out.push_str("\\t"),
            _ => out.push(c),
        }
    }
    out.push('"');
    out
}

/// A float in the shortest form that reads back to the same value. SDL has no infinity or
/// NaN: infinities are written as ±1e300 and NaN as 0.
pub fn number(value: f64) -> String {
    if value.is_nan() {
        return "0".into();
    }
    if value.is_infinite() {
        return if value > 0.0 { "1e300" } else { "-1e300" }.into();
    }
    let magnitude = value.abs();
    if value != 0.0 && !(1e-5..1e16).contains(&magnitude) {
        format!("{value:e}")
    } else {
        format!("{value}")
    }
}

/// POV-Ray's number of a noise generator.
pub(crate) fn noise_number(generator: crate::noise::NoiseGenerator) -> u32 {
    match generator {
        crate::noise::NoiseGenerator::Original => 1,
        crate::noise::NoiseGenerator::RangeCorrected => 2,
        crate::noise::NoiseGenerator::Perlin => 3,
    }
}

/// `<x, y, z>`.
pub(crate) fn vector(v: DVec3) -> String {
    format!("<{}, {}, {}>", number(v.x), number(v.y), number(v.z))
}

/// `<u, v>`.
pub(crate) fn vector2(v: DVec2) -> String {
    format!("<{}, {}>", number(v.x), number(v.y))
}

/// `rgb <r, g, b>`.
pub(crate) fn rgb(c: DVec3) -> String {
    format!("rgb {}", vector(c))
}

/// `rgbft <r, g, b, f, t>`.
pub(crate) fn colour(c: &Colour) -> String {
    format!(
        "rgbft <{}, {}, {}, {}, {}>",
        number(c.red),
        number(c.green),
        number(c.blue),
        number(c.filter),
        number(c.transmit)
    )
}

/// `on` or `off`.
pub(crate) fn on_off(on: bool) -> &'static str {
    if on {
        "on"
    } else {
        "off"
    }
}

/// ` matrix < .. >` for a transformation other than the identity (empty for it). POV-Ray's
/// matrix lists the images of the x, y and z axes, then the translation.
pub(crate) fn matrix(t: &Transform) -> String {
    if *t == Transform::IDENTITY {
        return String::new();
    }
    let m = t.outer_from_inner;
    let (x, y, z, w) = (
        m.matrix3.x_axis,
        m.matrix3.y_axis,
        m.matrix3.z_axis,
        m.translation,
    );
    // A scale and a move (most placements) are written as such: reading them back composes
    // the same exact inverses as the scene did, where a `matrix` would be inverted anew
    // and differ in the last bits.
    let diagonal = x.y == 0.0 && x.z == 0.0 && y.x == 0.0 && y.z == 0.0 && z.x == 0.0 && z.y == 0.0;
    if diagonal && x.x != 0.0 && y.y != 0.0 && z.z != 0.0 {
        let scale = DVec3::new(x.x, y.y, z.z);
        let mut text = String::new();
        if scale != DVec3::ONE {
            let _ = write!(text, " scale {}", vector(scale));
        }
        if w != DVec3::ZERO {
            let _ = write!(text, " translate {}", vector(w));
        }
        let written = Transform::scaling(scale)
            .unwrap_or(Transform::IDENTITY)
            .then(&Transform::translation(w));
        if written == *t {
            return text;
        }
    }
    let values = [x.x, x.y, x.z, y.x, y.y, y.z, z.x, z.y, z.z, w.x, w.y, w.z];
    let list: Vec<String> = values.iter().map(|v| number(*v)).collect();
    format!(" matrix <{}>", list.join(", "))
}

/// The transformation that, applied after `parent`, gives `total`: what must be written
/// inside a block whose enclosing block applies `parent` afterwards.
pub(crate) fn relative(total: &Transform, parent: &Transform) -> Transform {
    if *parent == Transform::IDENTITY {
        return *total;
    }
    total.then(&parent.inverse())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_read_back_exactly() {
        for value in [
            0.0,
            -0.0,
            1.0,
            -2.5,
            0.1,
            1.0 / 3.0,
            std::f64::consts::PI,
            1e-7,
            -3.25e-12,
            1e20,
            123456.789,
            f64::MAX,
            f64::MIN_POSITIVE,
        ] {
            let text = number(value);
            assert_eq!(text.parse::<f64>().unwrap(), value, "{text}");
            assert!(!text.contains("inf") && !text.contains("NaN"), "{text}");
        }
        assert_eq!(number(0.5), "0.5");
        assert_eq!(number(2.0), "2");
        assert_eq!(number(1e-7), "1e-7");
        assert_eq!(number(f64::INFINITY), "1e300");
        assert_eq!(number(f64::NAN), "0");
    }

    #[test]
    fn matrix_lists_axes_then_translation() {
        let t = Transform::translation(DVec3::new(1.0, 2.0, 3.0))
            .then(&Transform::scaling(DVec3::new(2.0, 2.0, 2.0)).unwrap());
        assert_eq!(matrix(&t), " scale <2, 2, 2> translate <2, 4, 6>");
        let turned = t.then(&Transform::rotation_degrees(DVec3::new(0.0, 0.0, 90.0)));
        let m = turned.outer_from_inner;
        let text = matrix(&turned);
        assert!(text.starts_with(" matrix <"), "{text}");
        let listed: Vec<f64> = text[9..text.len() - 1]
            .split(", ")
            .map(|v| v.parse().unwrap())
            .collect();
        assert_eq!(listed[0..3], m.matrix3.x_axis.to_array());
        assert_eq!(listed[9..12], m.translation.to_array());
        assert_eq!(matrix(&Transform::IDENTITY), "");
    }

    #[test]
    fn strings_are_escaped() {
        assert_eq!(string_literal("a\"b\\c"), "\"a\\\"b\\\\c\"");
    }
}
