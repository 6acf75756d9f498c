//! Patterns: functions from a point in pattern space to a value in [0, 1] or a block index,
//! with POV-Ray's modifiers (turbulence, warps, frequency, phase, wave shapes).
//!
//! In: a point already mapped into pattern space by the owning pigment/normal/texture's
//! transform. Out: the pattern value ([`Pattern::value`]) or, for block patterns such as
//! `checker`, the block index ([`Pattern::block`]). Holds: pure and allocation-free per
//! call; non-finite input gives 0.
//!
//! Order of evaluation, measured against POV-Ray 3.7: warps and the transformations written
//! after the pattern keyword act in the order written, so the point passes through them
//! from the last written to the first; the classic `turbulence` modifier acts innermost
//! (after every warp and transformation, "turbulence first"). Then the raw pattern value,
//! then frequency, phase and the wave shape ([`wave`]).
//!
//! Maps (colour, pigment, normal, texture maps) and what a value means live with the textures
//! (`render::pattern`); this module only knows patterns.

mod default_maps;
mod density_file;
mod facets;
mod fractal;
mod geometric;
mod noise_based;
mod normals;
mod pavement;
mod surface;
mod tiling;
mod warp;
mod wave;
mod waves;

use glam::DVec3;

use crate::math::Transform;
use crate::noise::{vector_turbulence, NoiseGenerator, SceneNoiseGenerator, TurbulenceShape};

pub use default_maps::{default_colour_map, DefaultColourMap};
pub use density_file::DensityFile;
pub use fractal::{Colouring, Fractal, FractalKind, MagnetType};
pub use geometric::checker_block;
pub use noise_based::{ClassicTurbulence, Crackle};
pub use pavement::{corner_setting as pavement_corner_setting, Pavement, PavementPolygon};
pub use surface::{Altitude, Slope, SurfaceContext};
pub use warp::{BlackHole, Mapping, MappingKind, Repeat, Warp};
pub use wave::{Wave, WaveShape};
pub use waves::{SceneWaveSources, WaveSources, MAX_WAVE_COUNT};

/// A solid the `object` pattern asks whether a point is inside.
///
/// The texture layer knows no geometry: the evaluator builds the object's render form
/// (the geometry layer's `World` implements this) and hands it over as a trait object.
pub trait Solid: Send + Sync + std::fmt::Debug {
    /// True when `point` (in pattern space) is inside the solid.
    fn contains(&self, point: DVec3) -> bool;
}

/// A pattern with its modifiers.
#[derive(Clone, Debug)]
pub struct Pattern {
    /// Which pattern.
    pub kind: PatternKind,
    /// Frequency, phase and wave shape.
    pub wave: Wave,
    /// The classic `turbulence` modifier (amount zero: none) with its octaves, omega and
    /// lambda.
    pub turbulence: ClassicTurbulence,
    /// Warps in the order written, each with the transformations written before it.
    pub warps: Vec<PlacedWarp>,
    /// The noise generator: the pattern's own, or the scene's global one.
    pub noise: NoiseChoice,
    /// The colour map a pigment uses when it gives none (empty: black to white).
    pub default_colour_map: DefaultColourMap,
    /// Every transformation noted so far, composed (outer from inner).
    noted: Transform,
}

/// Which noise generator a pattern uses.
#[derive(Clone, Debug)]
pub enum NoiseChoice {
    /// The pattern's own `noise_generator`.
    Own(NoiseGenerator),
    /// The scene's `global_settings { noise_generator }`, read when the pattern is
    /// evaluated (so a `global_settings` written after the pattern applies too).
    Scene(SceneNoiseGenerator),
}

/// A warp together with the frame it was written in.
#[derive(Clone, Debug)]
pub struct PlacedWarp {
    /// The warp.
    pub warp: Warp,
    /// The transformations written before the warp (after the pattern keyword), composed:
    /// maps the innermost pattern space to the warp's frame.
    pub frame: Transform,
}

/// The patterns.
#[derive(Clone, Debug)]
pub enum PatternKind {
    /// `function { .. }`: a user function of x, y, z, its value used as is (the wave shape
    /// then wraps it into [0, 1] as for every pattern).
    Function(std::sync::Arc<crate::texture::function::Function>),
    /// Banded like marble with its own turbulence (`agate_turb`, default 1).
    Agate {
        /// The built-in turbulence's amount.
        agate_turb: f64,
    },
    /// 1 at the origin falling to 0 at the faces of the cube [-1, 1]³.
    Boxed,
    /// Smooth noise (also `spotted`; `bumps` as a pigment).
    Bozo,
    /// Bricks and mortar; block 0 mortar, block 1 brick.
    Brick {
        /// Size of a brick with its mortar (default <8, 3, 4.5>).
        size: DVec3,
        /// Mortar thickness (default 0.5).
        mortar: f64,
    },
    /// Noise with a dedicated normal (the same as bozo as a pigment).
    Bumps,
    /// One random value per unit cube.
    Cells,
    /// 3-D checkerboard of unit cubes; block index 0 or 1.
    Checker,
    /// Voronoi cells.
    Crackle(Crackle),
    /// Six blocks, one per pyramid around each half axis.
    Cubic,
    /// 1 on the y axis falling to 0 at radius 1.
    Cylindrical,
    /// Dents (noise cubed as a pigment).
    Dents,
    /// `density_file df3 "file"`: a voxel grid over the unit cube.
    DensityFile {
        /// The grid, read when the scene is parsed.
        grid: std::sync::Arc<DensityFile>,
        /// `interpolate`: 0 nearest voxel, 1 trilinear, 2 cubic.
        interpolation: u8,
    },
    /// Facets: a normal-only pattern (`coords`, `size`); its value is 0.
    Facets {
        /// `coords` scale (0: not given).
        coords: f64,
        /// `size`: the cells' scale (default 0.1).
        size: f64,
    },
    /// Mandelbrot, Julia and magnet fractals.
    Fractal(Fractal),
    /// Ramp along a direction (the fractional part of `dot(p, direction)`).
    Gradient(DVec3),
    /// 1/f noise.
    Granite,
    /// Hexagons in the x-z plane; three blocks.
    Hexagon,
    /// `((sin x + sin y + sin z) / 3)²`.
    Leopard,
    /// The x coordinate with a triangle wave and turbulence built in.
    Marble,
    /// Concentric unit shells.
    Onion,
    /// `pavement`: a polyform tile paving the x-z plane (hexagon pavings are not supported
    /// yet and give 0, the map's first entry).
    Pavement(Pavement),
    /// 1 on the x-z plane falling to 0 at distance 1.
    Planar,
    /// Rounded cubes.
    Quilted {
        /// Curvature at the cube faces (default 1).
        control0: f64,
        /// Curvature at the seams (default 1).
        control1: f64,
    },
    /// Angle around the y axis.
    Radial,
    /// Ripples from the wave centres.
    Ripples(SceneWaveSources),
    /// `slope { .. }`: the surface normal against a direction (needs the surface).
    Slope(Slope),
    /// `aoi`: the angle between the ray and the surface (needs the surface).
    Aoi,
    /// `pigment_pattern { .. }`: the grey level 0.297 R + 0.589 G + 0.114 B of a pigment
    /// (measured; filter and transmit do not count).
    PigmentPattern(std::sync::Arc<crate::texture::Pigment>),
    /// `object { .. }`: block 1 inside the object, block 0 outside (the geometry is built
    /// once, when the pattern is parsed, by the layer that knows geometry).
    Object(std::sync::Arc<dyn Solid>),
    /// 1 at the origin falling to 0 at radius 1.
    Spherical,
    /// A screw around the z axis with a number of arms (the integer part is used).
    Spiral1(f64),
    /// Two spirals twisting in opposite directions (the integer part of the arms is used).
    Spiral2(f64),
    /// Squares in the x-z plane; four blocks.
    Square,
    /// `tiling N`: one of POV-Ray's periodic tilings of the x-z plane, tiles bevelled towards
    /// their edges (see [`tiling`]).
    Tiling(u8),
    /// Triangles in the x-z plane; six blocks.
    Triangular,
    /// Broad waves from the wave centres.
    Waves(SceneWaveSources),
    /// Rings around the z axis with a triangle wave.
    Wood,
    /// Sharp 1/f noise.
    Wrinkles,
    /// `image_pattern { .. }`: the grey level (or transparency) of an image's pixels.
    ImagePattern(std::sync::Arc<crate::texture::ImageMap>),
}

impl Pattern {
    /// The pattern with POV-Ray's default modifiers.
    pub fn new(kind: PatternKind) -> Pattern {
        let shape = match kind {
            PatternKind::Marble
            | PatternKind::Wood
            | PatternKind::Spiral1(_)
            | PatternKind::Spiral2(_) => WaveShape::Triangle,
            _ => WaveShape::Ramp,
        };
        Pattern {
            kind,
            wave: Wave::new(shape),
            turbulence: ClassicTurbulence {
                amount: DVec3::ZERO,
                shape: TurbulenceShape::default(),
            },
            warps: Vec::new(),
            noise: NoiseChoice::Scene(SceneNoiseGenerator::default()),
            default_colour_map: &[],
            noted: Transform::IDENTITY,
        }
    }

    /// Called for every transformation written inside the owning block after the pattern
    /// keyword (the owner also composes it into its own transform), so that warps can
    /// remember the frame they were written in.
    pub fn note_transform(&mut self, transform: &Transform) {
        self.noted = self.noted.then(transform);
    }

    /// Makes the pattern follow the scene's global noise generator `scene`, unless it
    /// names its own.
    pub fn use_scene_noise_generator(&mut self, scene: &SceneNoiseGenerator) {
        if let NoiseChoice::Scene(_) = self.noise {
            self.noise = NoiseChoice::Scene(scene.clone());
        }
    }

    /// The noise generator the pattern uses now.
    pub fn noise_generator(&self) -> NoiseGenerator {
        match &self.noise {
            NoiseChoice::Own(generator) => *generator,
            NoiseChoice::Scene(scene) => scene.get(),
        }
    }

    /// Adds a warp after everything written so far.
    pub fn add_warp(&mut self, warp: Warp) {
        self.warps.push(PlacedWarp {
            warp,
            frame: self.noted,
        });
    }

    /// True for the patterns whose value depends on the surface normal (`slope`, `aoi`).
    pub fn depends_on_surface(&self) -> bool {
        matches!(self.kind, PatternKind::Slope(_) | PatternKind::Aoi)
    }

    /// For block patterns (`checker`, `hexagon`, `brick`, ...): how many blocks there are.
    /// `None` for patterns with a continuous value.
    pub fn block_count(&self) -> Option<usize> {
        match self.kind {
            PatternKind::Checker | PatternKind::Brick { .. } | PatternKind::Object(_) => Some(2),
            PatternKind::Hexagon => Some(3),
            PatternKind::Square => Some(4),
            PatternKind::Triangular | PatternKind::Cubic => Some(6),
            _ => None,
        }
    }

    /// The colours (rgb) POV-Ray 3.7 gives the blocks of a block pattern written without
    /// any (measured): checker blue, green; hexagon blue, green, red; brick grey mortar and
    /// red brick; square red, green, blue, yellow; triangular and cubic red, green, blue,
    /// yellow, cyan, magenta. Empty for patterns with a continuous value.
    pub fn default_block_colours(&self) -> &'static [[f64; 3]] {
        const RED: [f64; 3] = [1.0, 0.0, 0.0];
        const GREEN: [f64; 3] = [0.0, 1.0, 0.0];
        const BLUE: [f64; 3] = [0.0, 0.0, 1.0];
        const YELLOW: [f64; 3] = [1.0, 1.0, 0.0];
        const CYAN: [f64; 3] = [0.0, 1.0, 1.0];
        const MAGENTA: [f64; 3] = [1.0, 0.0, 1.0];
        match self.kind {
            PatternKind::Checker => &[BLUE, GREEN],
            PatternKind::Hexagon => &[BLUE, GREEN, RED],
            PatternKind::Brick { .. } => &[[0.5, 0.5, 0.5], [0.6, 0.15, 0.15]],
            PatternKind::Square => &[RED, GREEN, BLUE, YELLOW],
            PatternKind::Triangular | PatternKind::Cubic => {
                &[RED, GREEN, BLUE, YELLOW, CYAN, MAGENTA]
            }
            _ => &[],
        }
    }

    /// The block index (below [`Self::block_count`]) at a pattern-space point.
    pub fn block(&self, point: DVec3) -> usize {
        if !point.is_finite() {
            return 0;
        }
        self.block_of_moved(self.moved_point(point))
    }

    /// [`Self::block`] at a point already through the warps and turbulence
    /// ([`Self::moved_point`]).
    fn block_of_moved(&self, p: DVec3) -> usize {
        match &self.kind {
            PatternKind::Checker => checker_block(p),
            PatternKind::Brick { size, mortar } => geometric::brick_block(p, *size, *mortar),
            PatternKind::Hexagon => geometric::hexagon_block(p),
            PatternKind::Square => geometric::square_block(p),
            PatternKind::Triangular => geometric::triangular_block(p),
            PatternKind::Cubic => geometric::cubic_block(p),
            PatternKind::Object(solid) => usize::from(solid.contains(p)),
            _ => 0,
        }
    }

    /// The pattern's value in [0, 1] at a pattern-space point (after turbulence, warps,
    /// frequency, phase and the wave shape). Block patterns give their block index.
    pub fn value(&self, point: DVec3) -> f64 {
        self.value_at(point, &SurfaceContext::default())
    }

    /// [`Self::value`] for a point on a surface: `surface` holds the hit point, normal and
    /// ray direction in world space, for the patterns that depend on it (`slope`, `aoi`).
    pub fn value_at(&self, point: DVec3, surface: &SurfaceContext) -> f64 {
        if !point.is_finite() {
            return 0.0;
        }
        self.value_of_moved(self.moved_point(point), surface)
    }

    /// [`Self::value_at`] at a point already through the warps and turbulence
    /// ([`Self::moved_point`]). A slope-derived normal samples the pattern this way around
    /// the centre's moved point: POV-Ray warps only the centre (measured: `normal { gradient
    /// x turbulence 1 }` tilts every point alike, bumping only where the value wraps).
    pub fn value_of_moved(&self, p: DVec3, surface: &SurfaceContext) -> f64 {
        if !p.is_finite() {
            return 0.0;
        }
        if self.block_count().is_some() {
            return self.block_of_moved(p) as f64;
        }
        let value = self.wave.apply(self.raw_value(p, surface));
        if value.is_finite() {
            value
        } else {
            0.0
        }
    }

    /// For patterns with a dedicated normal perturbation when used in `normal { }` (bumps,
    /// dents, ripples, waves, wrinkles, quilted, facets...): the perturbation vector to add to
    /// the surface normal at `point` for a bump size of 1. `None` means "derive the slope from
    /// [`Self::value`]".
    pub fn normal_perturbation(&self, point: DVec3) -> Option<DVec3> {
        if !point.is_finite() {
            return None;
        }
        let p = self.moved_point(point);
        let generator = self.noise_generator();
        let perturbation = match self.kind {
            PatternKind::Bumps => normals::bumps(p, generator),
            PatternKind::Dents => normals::dents(p, generator),
            PatternKind::Wrinkles => normals::wrinkles(p, generator),
            PatternKind::Ripples(ref sources) => {
                normals::ripples(p, &self.wave, sources.as_slice())
            }
            PatternKind::Waves(ref sources) => normals::waves(p, &self.wave, sources.as_slice()),
            PatternKind::Quilted { control0, control1 } => normals::quilted(p, control0, control1),
            _ => return None,
        };
        Some(if perturbation.is_finite() {
            perturbation
        } else {
            DVec3::ZERO
        })
    }

    /// For `facets`: the new (unnormalised) surface normal in pattern space at `point`, given
    /// the unit normal `facing` the viewer in pattern space. It replaces the usual
    /// perturbation: the bump amount does not scale it (measured). `None` for other patterns.
    pub fn facets_normal(&self, point: DVec3, facing: DVec3) -> Option<DVec3> {
        let PatternKind::Facets { coords, size } = self.kind else {
            return None;
        };
        if !point.is_finite() {
            return Some(facing);
        }
        let faceted = facets::facets_normal(self.moved_point(point), facing, coords, size);
        Some(if faceted.is_finite() { faceted } else { facing })
    }

    /// True for the patterns that use the classic turbulence inside their formula instead
    /// of moving the point with it. (The spirals do both, measured: the point is moved, then
    /// the scalar turbulence at the moved point is added. Agate too, measured: `agate
    /// turbulence t` equals `agate warp { turbulence t }`; its own `agate_turb` stirring takes
    /// only octaves, omega and lambda from the classic turbulence.)
    fn handles_own_turbulence(&self) -> bool {
        matches!(self.kind, PatternKind::Marble | PatternKind::Wood)
    }

    /// The point the raw pattern is evaluated at: through the warps and the
    /// transformations between them (last written first), then the classic turbulence.
    pub fn moved_point(&self, point: DVec3) -> DVec3 {
        // `point` is in the innermost pattern space. Each warp's frame is that space moved by
        // the transformations written before the warp, so the point is carried into the
        // last warp's frame, warped, carried back into the previous warp's frame, and so on.
        let mut p = point;
        for placed in self.warps.iter().rev() {
            let in_frame = placed.frame.point_to_outer(p);
            let warped = placed.warp.apply(in_frame, self.noise_generator());
            p = placed.frame.point_to_inner(warped);
        }
        if self.turbulence.amount != DVec3::ZERO && !self.handles_own_turbulence() {
            p += self.turbulence.amount
                * vector_turbulence(p, &self.turbulence.shape, self.noise_generator());
        }
        p
    }

    /// The classic turbulence as a scalar (its x amount times the scalar turbulence), for
    /// the spirals; 0 without turbulence.
    fn scalar_turbulence(&self, p: DVec3) -> f64 {
        let turbulence = &self.turbulence;
        if turbulence.amount == DVec3::ZERO {
            return 0.0;
        }
        turbulence.amount.x * crate::noise::turbulence(p, &turbulence.shape, self.noise_generator())
    }

    /// The pattern's value before frequency, phase and wave shape.
    fn raw_value(&self, p: DVec3, surface: &SurfaceContext) -> f64 {
        let generator = self.noise_generator();
        let turbulence = &self.turbulence;
        match &self.kind {
            PatternKind::Agate { agate_turb } => {
                noise_based::agate(p, *agate_turb, turbulence, generator)
            }
            PatternKind::Boxed => geometric::boxed(p),
            PatternKind::Bozo | PatternKind::Bumps => noise_based::bozo(p, generator),
            PatternKind::Cells => noise_based::cells(p),
            PatternKind::Crackle(settings) => noise_based::crackle(p, settings, generator),
            PatternKind::Cylindrical => geometric::cylindrical(p),
            PatternKind::Dents => noise_based::dents(p, generator),
            PatternKind::DensityFile {
                grid,
                interpolation,
            } => grid.value(p, *interpolation),
            PatternKind::Facets { .. } => 0.0,
            PatternKind::Pavement(pavement) => pavement.value(p.x, p.z),
            PatternKind::Fractal(fractal) => fractal.value(p.x, p.y),
            PatternKind::Gradient(direction) => geometric::gradient_raw(p, *direction),
            PatternKind::Granite => noise_based::granite(p, generator),
            PatternKind::Function(function) => function.eval_point(p),
            PatternKind::Leopard => geometric::leopard(p),
            PatternKind::Marble => noise_based::marble(p, turbulence, generator),
            PatternKind::Onion => geometric::onion(p),
            PatternKind::Planar => geometric::planar(p),
            PatternKind::Quilted { control0, control1 } => {
                normals::quilted_value(p, *control0, *control1)
            }
            PatternKind::Radial => geometric::radial(p),
            PatternKind::Ripples(sources) => {
                noise_based::ripples(p, &self.wave, sources.as_slice())
            }
            PatternKind::Slope(slope) => slope.value(p, surface),
            PatternKind::Aoi => surface::angle_of_incidence(surface.normal, surface.ray_direction),
            PatternKind::PigmentPattern(pigment) => {
                let [red, green, blue, _, _] =
                    crate::texture::pigment::pigment_colour_at(pigment, p, surface).to_array();
                0.297 * red + 0.589 * green + 0.114 * blue
            }
            PatternKind::Spherical => geometric::spherical(p),
            PatternKind::Tiling(number) => tiling::tiling_value(*number, p),
            PatternKind::Spiral1(arms) => {
                geometric::spiral1(p, arms.trunc(), self.scalar_turbulence(p))
            }
            PatternKind::Spiral2(arms) => {
                geometric::spiral2(p, arms.trunc(), self.scalar_turbulence(p))
            }
            PatternKind::Waves(sources) => noise_based::waves(p, &self.wave, sources.as_slice()),
            PatternKind::Wood => noise_based::wood(p, turbulence, generator),
            PatternKind::Wrinkles => noise_based::wrinkles(p, generator),
            PatternKind::ImagePattern(image) => crate::texture::image_map::image_value(image, p),
            PatternKind::Checker
            | PatternKind::Brick { .. }
            | PatternKind::Hexagon
            | PatternKind::Square
            | PatternKind::Triangular
            | PatternKind::Cubic
            | PatternKind::Object(_) => self.block(p) as f64,
        }
    }
}

/// The gradient pattern's value in [0, 1] at a pattern-space point.
pub fn gradient_value(point: DVec3, direction: DVec3) -> f64 {
    Wave::new(WaveShape::Ramp).apply(geometric::gradient_raw(point, direction))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gradient_x() -> Pattern {
        Pattern::new(PatternKind::Gradient(DVec3::X))
    }

    #[test]
    fn warps_and_transforms_apply_in_written_order() {
        // POV-Ray: `gradient x warp { repeat x*0.5 } translate x*0.2` at x = 0.05 is 0.35;
        // with the translation written before the warp it is 0.85.
        let shift = Transform::translation(DVec3::new(0.2, 0.0, 0.0));
        let repeat = Warp::Repeat(Repeat {
            axis: 0,
            width: 0.5,
            offset: DVec3::ZERO,
            flip: [false; 3],
        });
        let mut warp_first = gradient_x();
        warp_first.add_warp(repeat.clone());
        warp_first.note_transform(&shift);
        let inner = shift.point_to_inner(DVec3::new(0.05, 0.0, 0.0));
        assert!((warp_first.value(inner) - 0.35).abs() < 1e-9);

        let mut translate_first = gradient_x();
        translate_first.note_transform(&shift);
        translate_first.add_warp(repeat);
        assert!((translate_first.value(inner) - 0.85).abs() < 1e-9);
    }

    #[test]
    fn every_pattern_stays_finite_on_extreme_points() {
        let kinds = [
            PatternKind::Agate { agate_turb: 1.0 },
            PatternKind::Boxed,
            PatternKind::Bozo,
            PatternKind::Brick {
                size: DVec3::new(8.0, 3.0, 4.5),
                mortar: 0.5,
            },
            PatternKind::Bumps,
            PatternKind::Cells,
            PatternKind::Checker,
            PatternKind::Crackle(Crackle::default()),
            PatternKind::Cubic,
            PatternKind::Cylindrical,
            PatternKind::Dents,
            PatternKind::Fractal(Fractal::new(FractalKind::Mandelbrot, 50)),
            PatternKind::Fractal(Fractal::new(
                FractalKind::MagnetJulia(MagnetType::Two, glam::DVec2::new(0.5, 0.5)),
                50,
            )),
            PatternKind::Gradient(DVec3::new(1.0, 2.0, 3.0)),
            PatternKind::Granite,
            PatternKind::Hexagon,
            PatternKind::Leopard,
            PatternKind::Marble,
            PatternKind::Onion,
            PatternKind::Pavement(Pavement::default()),
            PatternKind::Pavement(Pavement {
                polygon: PavementPolygon::Square,
                tiles: 5,
                pattern: 12,
                form: 1,
                exterior: 2,
                interior: 1,
            }),
            PatternKind::Planar,
            PatternKind::Quilted {
                control0: 1.0,
                control1: 1.0,
            },
            PatternKind::Radial,
            PatternKind::Ripples(SceneWaveSources::default()),
            PatternKind::Spherical,
            PatternKind::Spiral1(3.0),
            PatternKind::Spiral2(1e300),
            PatternKind::Square,
            PatternKind::Tiling(1),
            PatternKind::Tiling(3),
            PatternKind::Triangular,
            PatternKind::Waves(SceneWaveSources::default()),
            PatternKind::Wood,
            PatternKind::Wrinkles,
            PatternKind::Facets {
                coords: 1e300,
                size: 0.0,
            },
        ];
        let points = [
            DVec3::ZERO,
            DVec3::splat(1e300),
            DVec3::new(-1e300, 1e-300, 3.0),
            DVec3::splat(f64::NAN),
            DVec3::new(f64::INFINITY, 0.0, 0.0),
        ];
        for kind in kinds {
            let mut pattern = Pattern::new(kind);
            pattern.wave.frequency = 1e300;
            pattern.turbulence.amount = DVec3::splat(1e300);
            pattern.add_warp(Warp::Mapping(Mapping {
                dist_exp: 1e300,
                ..Mapping::new(MappingKind::Toroidal)
            }));
            for point in points {
                let value = pattern.value(point);
                assert!(value.is_finite(), "{:?} at {point}", pattern.kind);
                if let Some(count) = pattern.block_count() {
                    assert!(pattern.block(point) < count);
                }
                if let Some(normal) = pattern.normal_perturbation(point) {
                    assert!(normal.is_finite());
                }
                if let Some(normal) = pattern.facets_normal(point, DVec3::Y) {
                    assert!(normal.is_finite());
                }
            }
        }
    }

    #[test]
    fn block_patterns_report_their_counts() {
        assert_eq!(Pattern::new(PatternKind::Hexagon).block_count(), Some(3));
        assert_eq!(Pattern::new(PatternKind::Onion).block_count(), None);
        assert_eq!(gradient_x().value(DVec3::splat(f64::NAN)), 0.0);
    }
}
