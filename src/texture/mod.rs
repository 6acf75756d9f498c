//! The texture layer: the recursive appearance family of POV-Ray's language — textures,
//! pigments, normals, finishes, patterns, functions and image maps — and their evaluation.
//!
//! In: a point in pattern space (and, for surface patterns, a [`pattern::SurfaceContext`]).
//! Out: colours ([`pigment`]), perturbed normals ([`normal`]), pattern values
//! ([`pattern`]), function values ([`function`]), image lookups ([`image_map`]).
//! Holds: pure data and pure functions of a point; nothing here knows about rays, lights
//! or the world (the object pattern sees a solid only through [`pattern::Solid`]).
//!
//! This file holds the data: every nested map entry carries its complete pattern
//! transform, so a transformation applied to a whole pigment, normal or texture is composed
//! into all of them at once, which is how POV-Ray transforms the entries of maps together
//! with the map.

pub mod finish;
pub mod function;
pub mod image_map;
pub mod normal;
pub mod pattern;
pub mod pigment;

use crate::math::{Colour, Transform};
use finish::Finish;
use pattern::Pattern;
use std::sync::Arc;

/// Surface appearance: pigment, normal perturbation and finish, or a combination of whole
/// textures.
#[derive(Clone, Debug)]
pub struct Texture {
    /// Colour and transparency at each point.
    pub pigment: Pigment,
    /// Perturbation of the surface normal; `None` leaves the normal as the shape has it.
    /// (Boxed, like the pattern of a pigment, so that the millions of plain textures of a
    /// large generated scene stay small.)
    pub normal: Option<Box<Normal>>,
    /// How the surface reacts to light (shared: most textures of a large scene keep the
    /// finish they started from; change it with `Arc::make_mut`).
    pub finish: Arc<Finish>,
    /// When set, the texture is made of other textures (layers, a texture map, block
    /// textures, tiles, averages) and `pigment`, `normal` and `finish` are not used.
    pub compound: Option<Arc<CompoundTexture>>,
}

impl Default for Texture {
    fn default() -> Self {
        Texture {
            pigment: Pigment::Solid(Colour::BLACK),
            normal: None,
            finish: Arc::new(Finish::default()),
            compound: None,
        }
    }
}

/// A texture made of other textures.
// Held once behind an `Arc` per texture, so the size of the pattern variant does not matter.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug)]
pub enum CompoundTexture {
    /// Layers from the bottom up: each layer shows the ones below through its pigment's
    /// filter and transmit.
    Layered(Vec<Texture>),
    /// A pattern choosing or blending whole textures; each is shaded and the results blended.
    Pattern {
        pattern: Pattern,
        map: BlendMap<Texture>,
        transform: Transform,
    },
    /// `average`: the weighted mean of the shaded textures.
    Average(Vec<(f64, Texture)>),
    /// `material_map`: each image pixel's palette index (or 8-bit red value) picks a texture
    /// (see `render::image_map::material_choice`).
    MaterialMap {
        image: Arc<ImageMap>,
        textures: Vec<Texture>,
        transform: Transform,
    },
}

/// What a pattern's value selects: entries interpolated by key, or one item per block.
#[derive(Clone, Debug)]
pub enum BlendMap<T> {
    /// `(key, item)` entries sorted by key (a `pigment_map`, `normal_map`, `texture_map`).
    Entries(Vec<(f64, T)>),
    /// For block patterns (checker, hexagon, brick, tiles...): one item per block.
    Blocks(Vec<T>),
}

/// A pigment: a colour function of position.
// Pigments live inside shared textures, never in large arrays, so the size of the pattern
// variant does not matter.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug)]
pub enum Pigment {
    /// The same colour everywhere.
    Solid(Colour),
    /// A pattern looked up through a map; the point is first mapped by `transform`'s
    /// `inner_from_outer` (outer space to pattern space).
    Pattern {
        pattern: Box<Pattern>,
        map: PigmentMap,
        transform: Transform,
    },
    /// `average`: the weighted mean of the entries' colours.
    Average {
        /// `(weight, pigment)` entries of the `pigment_map`.
        entries: Vec<(f64, Pigment)>,
        /// Outer space to the average's own pattern space: the transformations written in
        /// the pigment (the entries carry them too, so they apply when there are no warps).
        transform: Transform,
        /// The `turbulence` and warps written in the pigment, carried by a pattern whose
        /// value is not used: the entries are evaluated at the warped point (POV-Ray treats
        /// `average` as a pattern); `None` without any.
        warps: Option<Box<Pattern>>,
    },
    /// `image_map { .. }`: an image projected onto the pattern space.
    Image {
        image: Arc<ImageMap>,
        transform: Transform,
        /// The `turbulence` and warps written in the pigment, carried by an image pattern
        /// of the same image (its value is not used); `None` without any.
        warps: Option<Box<Pattern>>,
    },
    /// `uv_mapping`: the pigment is evaluated at `<u, v, 0>` of the surface instead of the
    /// point. Only the transformations written in the block that says `uv_mapping` apply;
    /// none applied afterwards reach it (see [`Pigment::transform`]).
    UvMapped(Box<Pigment>),
}

/// What a pigment's pattern value is looked up in.
#[derive(Clone, Debug)]
pub enum PigmentMap {
    /// A colour map: sorted (value, colour) entries, interpolated.
    Colours(Vec<(f64, Colour)>),
    /// For block patterns (checker): one pigment per block.
    Blocks(Vec<Pigment>),
    /// A pigment map: sorted (value, pigment) entries, their colours interpolated.
    Pigments(Vec<(f64, Pigment)>),
}

/// A normal perturbation: how the shading normal is tilted at each point.
#[derive(Clone, Debug)]
pub struct Normal {
    /// Where the perturbation comes from.
    pub source: NormalSource,
    /// `bump_size` (POV-Ray's default for a pattern written without one is 0.5).
    pub amount: f64,
    /// Distance between the samples of the numeric slope (`accuracy`, default 0.02).
    pub accuracy: f64,
    /// `no_bump_scale`: the bumps keep their depth when the pattern is scaled.
    pub no_bump_scale: bool,
    /// Outer space to pattern space (for the samples of the numeric slope).
    pub transform: Transform,
    /// `uv_mapping` (in the normal or its texture): the pattern is evaluated around the
    /// hit's `<u, v, 0>` and its slope there tilts the world normal as it stands (measured);
    /// the object's transformations do not apply.
    pub uv_mapped: bool,
}

/// Where a normal's perturbation comes from.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug)]
pub enum NormalSource {
    /// A pattern used as a height field, optionally reshaped by a `slope_map`.
    Pattern {
        pattern: Pattern,
        slope_map: Option<Vec<SlopeEntry>>,
    },
    /// A pattern selecting normals: `normal_map` entries or block normals.
    Map {
        pattern: Pattern,
        map: BlendMap<Normal>,
    },
    /// `average`: the weighted mean of the entries' perturbations.
    Average(Vec<(f64, Normal)>),
    /// `bump_map { .. }`: heights read from an image.
    BumpMap(Arc<ImageMap>),
}

/// One `slope_map` entry `[key <height, slope>]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SlopeEntry {
    /// The pattern value the entry applies at.
    pub key: f64,
    /// The height at the key.
    pub height: f64,
    /// The slope at the key.
    pub slope: f64,
}

/// How an image's stored values become linear light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ImageGamma {
    /// Values are used as stored.
    Linear,
    /// The sRGB transfer function is undone.
    Srgb,
    /// Values are raised to this power.
    Power(f64),
}

/// The projection of an image onto pattern space (`map_type`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImageProjection {
    /// 0: the unit square of the XY plane, repeated (or once) along X and Y.
    Planar,
    /// 1: around the origin, longitude from the +X axis... latitude from the poles.
    Spherical,
    /// 2: around the Y axis, one unit high.
    Cylindrical,
    /// 5: around a torus of major radius 1 in the XZ plane.
    Torus,
}

/// An image used as a pigment (`image_map`), as heights (`bump_map`) or as a pattern
/// (`image_pattern`), already decoded into linear values (an `image_pattern` keeps the
/// stored values: POV-Ray applies no gamma there).
#[derive(Clone, Debug)]
pub struct ImageMap {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Linear red, green, blue and alpha of each pixel, rows from the top.
    pub pixels: Vec<[f32; 4]>,
    /// How the image is projected.
    pub projection: ImageProjection,
    /// `once`: no repetition; outside the unit square the pigment is clear.
    pub once: bool,
    /// `interpolate`: 0 none, 2 bilinear, 4 normalised distance.
    pub interpolation: u8,
    /// `filter all F`: added to every pixel's filter.
    pub filter_all: f64,
    /// `transmit all T`: added to every pixel's transmit.
    pub transmit_all: f64,
    /// `use_index` for bump maps (the palette index stands in for the grey value).
    pub use_index: bool,
    /// `use_alpha` of an `image_pattern`: the value is the pixel's transparency.
    pub use_alpha: bool,
    /// Each pixel's palette index, rows from the top (palette PNG files only).
    pub palette_indices: Option<Vec<u8>>,
    /// `filter N, F` of single palette entries (replacing `filter_all` for them).
    pub palette_filter: Vec<(u8, f64)>,
    /// `transmit N, T` of single palette entries (replacing `transmit_all` for them).
    pub palette_transmit: Vec<(u8, f64)>,
    /// The file the pixels came from, as the block named it (for writing the scene back).
    pub file: Option<Arc<ImageFile>>,
}

/// Where an image's pixels came from: the file found, its format and the `gamma` given.
#[derive(Clone, Debug, PartialEq)]
pub struct ImageFile {
    /// The file as found on the search path.
    pub path: std::path::PathBuf,
    /// The format keyword given (`sys` when none).
    pub format: crate::raster::RasterFormat,
    /// The `gamma` given in the block, if any.
    pub gamma: Option<ImageGamma>,
}

impl Texture {
    /// Composes `t` into every pattern transform of the texture (outer space moves by `t`);
    /// uv-mapped pigments and normals keep theirs (see [`Pigment::transform`]).
    pub fn transform(&mut self, t: &Transform) {
        self.pigment.transform(t);
        if let Some(normal) = &mut self.normal {
            normal.transform(t);
        }
        if let Some(compound) = &mut self.compound {
            Arc::make_mut(compound).transform(t);
        }
    }

    /// True when the texture varies with position (so its transforms matter).
    pub fn depends_on_position(&self) -> bool {
        self.compound.is_some() || self.normal.is_some() || !self.pigment.is_solid()
    }
}

impl CompoundTexture {
    /// Composes `t` into every texture and pattern transform held.
    pub fn transform(&mut self, t: &Transform) {
        match self {
            CompoundTexture::Layered(layers) => layers.iter_mut().for_each(|l| l.transform(t)),
            CompoundTexture::Pattern { map, transform, .. } => {
                *transform = transform.then(t);
                map.for_each_mut(|texture| texture.transform(t));
            }
            CompoundTexture::Average(entries) => entries
                .iter_mut()
                .for_each(|(_, texture)| texture.transform(t)),
            CompoundTexture::MaterialMap {
                textures,
                transform,
                ..
            } => {
                *transform = transform.then(t);
                textures.iter_mut().for_each(|texture| texture.transform(t));
            }
        }
    }
}

impl<T> BlendMap<T> {
    /// Calls `f` on every item of the map.
    pub fn for_each_mut(&mut self, mut f: impl FnMut(&mut T)) {
        match self {
            BlendMap::Entries(entries) => entries.iter_mut().for_each(|(_, item)| f(item)),
            BlendMap::Blocks(blocks) => blocks.iter_mut().for_each(f),
        }
    }
}

impl Texture {
    /// True when no point of the texture lets light through: a plain texture (not layered
    /// or patterned) whose pigment is [`Pigment::surely_opaque`]. Shadow rays stop at the
    /// first such surface they find, in any order (see `World::shadow_query`).
    pub fn surely_opaque(&self) -> bool {
        self.compound.is_none() && self.pigment.surely_opaque()
    }
}

impl Pigment {
    /// True when every colour the pigment can give has no filter and no transmit (image
    /// maps, whose pixels may be transparent, never count).
    pub fn surely_opaque(&self) -> bool {
        let opaque = |colour: &Colour| colour.filter == 0.0 && colour.transmit == 0.0;
        match self {
            Pigment::Solid(colour) => opaque(colour),
            Pigment::Pattern { map, .. } => match map {
                PigmentMap::Colours(entries) => entries.iter().all(|(_, colour)| opaque(colour)),
                PigmentMap::Blocks(blocks) => blocks.iter().all(Pigment::surely_opaque),
                PigmentMap::Pigments(entries) => {
                    entries.iter().all(|(_, pigment)| pigment.surely_opaque())
                }
            },
            Pigment::Average { entries, .. } => {
                entries.iter().all(|(_, pigment)| pigment.surely_opaque())
            }
            Pigment::Image { .. } => false,
            Pigment::UvMapped(inner) => inner.surely_opaque(),
        }
    }

    /// Composes `t` into the pigment's pattern transform and those of every nested pigment.
    /// Uv-mapped pigments are left as they are, wherever they sit (measured: once the block
    /// that says `uv_mapping` is closed, POV-Ray applies no transformation to the pigment:
    /// not an object's, a texture's, an enclosing pigment's, nor one written after the
    /// pigment's name in `pigment { Uv_pigment translate .. }`; the transformations inside
    /// that block apply before the pigment is wrapped).
    pub fn transform(&mut self, t: &Transform) {
        match self {
            Pigment::Solid(_) => {}
            Pigment::Pattern { map, transform, .. } => {
                *transform = transform.then(t);
                match map {
                    PigmentMap::Colours(_) => {}
                    PigmentMap::Blocks(blocks) => blocks.iter_mut().for_each(|b| b.transform(t)),
                    PigmentMap::Pigments(entries) => {
                        entries.iter_mut().for_each(|(_, p)| p.transform(t))
                    }
                }
            }
            Pigment::Average {
                entries, transform, ..
            } => {
                *transform = transform.then(t);
                entries.iter_mut().for_each(|(_, p)| p.transform(t))
            }
            Pigment::Image { transform, .. } => *transform = transform.then(t),
            Pigment::UvMapped(_) => {}
        }
    }

    /// The pigment evaluated at uv coordinates, when it is `uv_mapping`'s.
    pub fn uv_mapped(&self) -> Option<&Pigment> {
        match self {
            Pigment::UvMapped(inner) => Some(inner),
            _ => None,
        }
    }

    /// True for a plain colour.
    pub fn is_solid(&self) -> bool {
        matches!(self, Pigment::Solid(_))
    }
}

impl Normal {
    /// A normal from `source` with POV-Ray's defaults for everything else.
    pub fn new(source: NormalSource) -> Normal {
        Normal {
            source,
            amount: 0.5,
            accuracy: 0.02,
            no_bump_scale: false,
            transform: Transform::IDENTITY,
            uv_mapped: false,
        }
    }

    /// Composes `t` into the normal's transform and those of every nested normal. A
    /// uv-mapped normal keeps its transform (measured, as for pigments: only the
    /// transformations in the block that says `uv_mapping` apply; neither an object's, a
    /// texture's, an enclosing normal's nor one after its name in `normal { N scale .. }`).
    pub fn transform(&mut self, t: &Transform) {
        if self.uv_mapped {
            return;
        }
        self.transform = self.transform.then(t);
        match &mut self.source {
            NormalSource::Pattern { .. } | NormalSource::BumpMap(_) => {}
            NormalSource::Map { map, .. } => map.for_each_mut(|normal| normal.transform(t)),
            NormalSource::Average(entries) => entries
                .iter_mut()
                .for_each(|(_, normal)| normal.transform(t)),
        }
    }
}
