//! The evaluated scene: plain, immutable data handed from `eval` to the renderer.
//!
//! In: nothing (this is a data definition). Out: [`Scene`]. Holds: every value is final
//! (defaults filled in, camera vectors resolved); no macros, identifiers or spans remain.

mod atmosphere;
mod camera;
mod implicit;
mod interior;
mod julia;
mod light;
mod light_group;
mod media;
mod mesh;
mod parametric;
mod photons;
mod radiosity;
mod spindle;
mod uv_faces;

pub use atmosphere::{Atmosphere, Fog, FogKind, FogTurbulence, Rainbow, SkySphere};
pub use camera::{
    Camera, CameraFace, CylinderKind, FocalBlur, MeshCamera, MeshDistribution, Projection,
    DEFAULT_ANGLE,
};
pub use implicit::{
    Container, HeightField, HeightFieldSource, Isosurface, SphereSweep, SweepSpline,
};
pub use interior::Interior;
pub use julia::{JuliaAlgebra, JuliaFractal, JuliaFunction};
pub use light::{AreaLight, LightSource, Spotlight};
pub use light_group::{separate_light_groups, LightGroup};
pub use media::{Media, Scattering, ScatteringKind};
pub use mesh::{Mesh, MeshTriangle, DEFAULT_TRIANGLE_UVS, FLAT_FACE};
pub use parametric::Parametric;
pub use photons::{LightPhotons, ObjectPhotons, PhotonDensity, PhotonItemsGiven, PhotonSettings};
pub use radiosity::RadiositySettings;
pub use spindle::Lemon;
pub use uv_faces::{UvFace, UvFaces, UvHit};

use crate::math::{Colour, Transform};
use crate::texture::finish::SceneIridWavelengths;
use crate::texture::Texture;
use glam::DVec3;
use std::sync::Arc;

/// A whole scene ready to render.
#[derive(Clone, Debug)]
pub struct Scene {
    /// The camera (POV-Ray's default camera when the scene has none).
    pub camera: Camera,
    /// All light sources, in scene order.
    pub lights: Vec<LightSource>,
    /// Top-level objects, in scene order.
    pub objects: Vec<Object>,
    /// Colour seen by rays that hit nothing.
    pub background: Colour,
    /// Fog, sky sphere and rainbows.
    pub atmosphere: Atmosphere,
    /// `global_settings` and the language version that decides gamma handling.
    pub settings: GlobalSettings,
}

/// `global_settings` with POV-Ray's defaults filled in.
#[derive(Clone, Debug)]
pub struct GlobalSettings {
    /// `assumed_gamma` as written, or `None` when the scene gives none.
    pub assumed_gamma: Option<f64>,
    /// The `#version` in force when parsing ended (3.7 when the scene declares none).
    pub language_version: f64,
    /// Whether the scene declared a `#version` at all.
    pub version_declared: bool,
    /// Maximum recursion depth of reflected and refracted rays (default 5).
    pub max_trace_level: u32,
    /// Rays contributing less than this are not traced (default 1/255).
    pub adc_bailout: f64,
    /// Multiplies every finish's ambient term (default white).
    pub ambient_light: DVec3,
    /// The noise generator patterns use unless they name their own (default 2).
    pub noise_generator: crate::noise::NoiseGenerator,
    /// The same setting as the patterns (and irid) read it when evaluated: the handle every
    /// pattern without its own generator shares, so that the scene's last setting applies
    /// wherever it is written.
    pub scene_noise_generator: crate::noise::SceneNoiseGenerator,
    /// `irid_wavelength`: the wavelengths of red, green and blue light for `irid`.
    pub irid_wavelength: DVec3,
    /// The handle every `irid` of the scene reads its wavelengths from (fixed from
    /// `irid_wavelength` when parsing ends).
    pub scene_irid_wavelengths: SceneIridWavelengths,
    /// `number_of_waves` (default 10): how many wave sources `ripples` and `waves` use.
    pub number_of_waves: usize,
    /// The wave sources every `ripples` and `waves` pattern of the scene shares (fixed
    /// from `number_of_waves` when parsing ends).
    pub wave_sources: crate::texture::pattern::SceneWaveSources,
    /// The `radiosity { }` block, when given: indirect diffuse light is gathered, and in
    /// 3.7 scenes every finish's ambient term counts as zero.
    pub radiosity: Option<RadiositySettings>,
    /// The `photons { }` block, when given: caustics from photon mapping.
    pub photons: Option<PhotonSettings>,
    /// `mm_per_unit` (default 10): how many millimetres one scene unit stands for, which
    /// scales the `translucency` of subsurface finishes.
    pub mm_per_unit: f64,
    /// The `subsurface { }` block, when given: finishes with `subsurface` scatter light under
    /// their surface.
    pub subsurface: Option<SubsurfaceSettings>,
}

/// `global_settings { subsurface { samples D, S radiosity B } }`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SubsurfaceSettings {
    /// Samples of the diffuse (dipole) part per shaded point (default 50).
    pub diffuse_samples: u32,
    /// Samples of the single-scattering part per shaded point (default 50).
    pub single_samples: u32,
    /// `radiosity`: whether radiosity light is scattered too (read; not used).
    pub radiosity: bool,
}

impl Default for SubsurfaceSettings {
    fn default() -> Self {
        SubsurfaceSettings {
            diffuse_samples: 50,
            single_samples: 50,
            radiosity: false,
        }
    }
}

impl Default for GlobalSettings {
    fn default() -> Self {
        GlobalSettings {
            assumed_gamma: None,
            language_version: 3.7,
            version_declared: false,
            max_trace_level: 5,
            adc_bailout: 1.0 / 255.0,
            ambient_light: DVec3::ONE,
            noise_generator: crate::noise::NoiseGenerator::default(),
            scene_noise_generator: crate::noise::SceneNoiseGenerator::for_scene(),
            irid_wavelength: crate::texture::finish::DEFAULT_IRID_WAVELENGTHS,
            scene_irid_wavelengths: SceneIridWavelengths::for_scene(),
            number_of_waves: 10,
            wave_sources: crate::texture::pattern::SceneWaveSources::default(),
            radiosity: None,
            photons: None,
            mm_per_unit: 10.0,
            subsurface: None,
        }
    }
}

/// One object of the scene tree: a shape or a CSG node, with its appearance.
#[derive(Clone, Debug)]
pub struct Object {
    /// What the object is.
    pub shape: Shape,
    /// Maps this object's local space into its parent's space (world for top-level objects);
    /// `None` for the identity, which most objects of generated scenes have (boxed so that
    /// an `Object` stays small: a fractal holds hundreds of thousands of them).
    placement: Option<Box<Transform>>,
    /// Appearance; `None` inherits the parent's (or the default texture at top level).
    /// Pattern transformations inside are expressed in this object's local space.
    pub texture: Option<Arc<Texture>>,
    /// `interior_texture`: the appearance of the inside faces (hits where the ray leaves the
    /// object, or the back of a patch); `None` inherits the parent's, or uses `texture`.
    /// Pattern transformations inside are expressed in this object's local space.
    pub interior_texture: Option<Arc<Texture>>,
    /// Interior (index of refraction...); `None` inherits the parent's or the default.
    pub interior: Option<Box<Interior>>,
    /// Swaps inside and outside (`inverse`).
    pub inverse: bool,
    /// The object casts no shadow (`no_shadow`).
    pub no_shadow: bool,
    /// `hollow` as written: `Some(true)` hollow, `Some(false)` `hollow off`, `None` unspecified.
    pub hollow: Option<bool>,
    /// `clipped_by` objects, in this object's local space: only the parts of the object inside
    /// all of them remain.
    pub clipped_by: Vec<Object>,
    /// `bounded_by` objects, in this object's local space (the object takes their box: rays missing it miss the object, as in POV-Ray 3.7).
    pub bounded_by: Vec<Object>,
    /// `no_image`: invisible to camera rays (still casts shadows and shows in reflections).
    pub no_image: bool,
    /// `no_reflection`: invisible in reflections.
    pub no_reflection: bool,
    /// `no_radiosity`: invisible to radiosity's gathering rays.
    pub no_radiosity: bool,
    /// `double_illuminate`: lit from both sides.
    pub double_illuminate: bool,
    /// Light sources written inside this CSG object, in its local space: they move with
    /// it, and evaluation adds them to the scene's lights wherever the object is placed
    /// (boxed: almost no object has any).
    pub lights: Option<Box<Vec<LightSource>>>,
    /// The `light_group` this object is (the root of every object written in the group):
    /// only the group's lights, and with `global_lights on` the scene's, light it.
    pub light_group: Option<LightGroup>,
    /// The `photons { }` block: whether photons are shot at the object, bounce off it,
    /// pass into it or land on it.
    pub photons: ObjectPhotons,
}

impl Object {
    /// An object with the given shape and everything else at its default.
    pub fn new(shape: Shape) -> Object {
        Object {
            shape,
            placement: None,
            texture: None,
            interior_texture: None,
            interior: None,
            inverse: false,
            no_shadow: false,
            hollow: None,
            clipped_by: Vec::new(),
            bounded_by: Vec::new(),
            no_image: false,
            no_reflection: false,
            no_radiosity: false,
            double_illuminate: false,
            lights: None,
            light_group: None,
            photons: ObjectPhotons::default(),
        }
    }

    /// Maps this object's local space into its parent's space.
    pub fn transform(&self) -> &Transform {
        self.placement.as_deref().unwrap_or(&Transform::IDENTITY)
    }

    /// Replaces the object's transformation.
    pub fn set_transform(&mut self, transform: Transform) {
        self.placement = (transform != Transform::IDENTITY).then(|| Box::new(transform));
    }

    /// Applies `t` after the object's own transformation.
    pub fn transform_by(&mut self, t: &Transform) {
        self.set_transform(self.transform().then(t));
    }
}

/// The geometry of an object, in the object's local space, as written in the scene.
#[derive(Clone, Debug)]
pub enum Shape {
    /// `sphere { centre, radius }`.
    Sphere { centre: DVec3, radius: f64 },
    /// `box { corner1, corner2 }`.
    Box { corner1: DVec3, corner2: DVec3 },
    /// `plane { normal, distance }`, the normal as written (not yet normalised).
    Plane { normal: DVec3, distance: f64 },
    /// `cylinder { base, cap, radius [open] }`.
    Cylinder {
        base: DVec3,
        cap: DVec3,
        radius: f64,
        open: bool,
    },
    /// `cone { base, base_radius, cap, cap_radius [open] }`.
    Cone {
        base: DVec3,
        base_radius: f64,
        cap: DVec3,
        cap_radius: f64,
        open: bool,
    },
    /// `torus { major, minor }`, in the XZ plane around the Y axis.
    Torus { major: f64, minor: f64 },
    /// `disc { centre, normal, radius [, hole_radius] }`.
    Disc {
        centre: DVec3,
        normal: DVec3,
        radius: f64,
        hole_radius: f64,
    },
    /// `quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }`:
    /// A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J = 0.
    Quadric { coefficients: Box<[f64; 10]> },
    /// `triangle { a, b, c }`.
    Triangle { corners: Box<[DVec3; 3]> },
    /// `smooth_triangle { a, na, b, nb, c, nc }`: corners with the normals to interpolate.
    SmoothTriangle {
        corners: Box<[DVec3; 3]>,
        normals: Box<[DVec3; 3]>,
    },
    /// `polygon { n, p1, .. pn }`: closed outlines in one plane, filled by the even-odd rule.
    Polygon(Arc<Polygon>),
    /// `mesh { .. }` or `mesh2 { .. }`: a shared list of triangles.
    Mesh(Arc<Mesh>),
    /// `poly`, `cubic` or `quartic`: the zero set of a polynomial in x, y and z.
    Poly(Arc<Poly>),
    /// `text { ttf .. }`: one extruded outline per glyph, already laid out.
    Text(Arc<Vec<Extrusion>>),
    /// `prism { .. }`: an outline in the XZ plane swept along Y (the extrusion's depth is the
    /// Y extent; its X and Y are the prism's X and Z).
    Prism(Arc<Extrusion>),
    /// `blob { .. }`: a field of spherical and cylindrical components, surface at the
    /// threshold.
    Blob(Arc<Blob>),
    /// `superellipsoid { <e, n> }`: (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1.
    Superellipsoid { east_west: f64, north_south: f64 },
    /// `sor { n, <r, h>.. [open] }`: radius² as a cubic spline of the height, turned around Y.
    Sor {
        points: Arc<Vec<glam::DVec2>>,
        open: bool,
    },
    /// `lathe { .. }`: a curve in the (radius, height) plane, as cubic Béziers of `<r, y>`
    /// points, turned around the Y axis.
    Lathe {
        segments: Arc<Vec<[glam::DVec2; 4]>>,
        /// The spline and points as written (for writing the scene back), when known.
        source: Option<Arc<SplineOutline>>,
    },
    /// `isosurface { .. }`: where a function equals its threshold.
    Isosurface(Arc<Isosurface>),
    /// `height_field { .. }`: a grid of heights over the unit square.
    HeightField(Arc<HeightField>),
    /// `sphere_sweep { .. }`: a sphere moved along a spline.
    SphereSweep(Arc<SphereSweep>),
    /// `julia_fractal { .. }`: a 3D slice of a 4D Julia set.
    JuliaFractal(Arc<JuliaFractal>),
    /// `ovus { bottom_radius, top_radius }`: an egg standing on the origin.
    Ovus { bottom_radius: f64, top_radius: f64 },
    /// `lemon { .. }`: a circle arc turned around an axis, with flat ends.
    Lemon(Arc<Lemon>),
    /// `parametric { .. }`: the points three functions of u and v give.
    Parametric(Arc<Parametric>),
    /// A CSG combination of child objects.
    Csg {
        operation: CsgOperation,
        children: Vec<Object>,
    },
}

/// A `lathe`'s or `prism`'s points as written, with the spline that joins them.
#[derive(Clone, Debug)]
pub struct SplineOutline {
    pub spline: OutlineSpline,
    pub points: Vec<glam::DVec2>,
}

/// How the points of a lathe or prism are joined.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutlineSpline {
    Linear,
    Quadratic,
    Cubic,
    Bezier,
}

/// The outlines of a `polygon`, already closed.
#[derive(Clone, Debug)]
pub struct Polygon {
    /// Each closed outline (sub-polygon), without repeating its first point at the end.
    pub outlines: Vec<Vec<DVec3>>,
}

/// A polynomial surface `poly { order, <coefficients> }`.
#[derive(Clone, Debug)]
pub struct Poly {
    /// Total degree (2 to 7).
    pub order: u32,
    /// Coefficients of x^i y^j z^k in POV-Ray's order: i from `order` down to 0, then j from
    /// `order - i` down to 0, then k from `order - i - j` down to 0.
    pub coefficients: Vec<f64>,
    /// `sturm` was asked for (durer's root finder is always exact, so this changes nothing).
    pub sturm: bool,
}

/// A region of the XY plane bounded by closed outlines of cubic Bézier segments,
/// extruded along Z. A point is in the region when a line from it crosses the outlines an
/// odd number of times.
#[derive(Clone, Debug)]
pub struct Extrusion {
    /// Segments as (start, control, control, end) of cubic Béziers.
    pub segments: Vec<[glam::DVec2; 4]>,
    /// The Z extent: from `depth.0` to `depth.1`.
    pub depth: (f64, f64),
    /// Without caps (a prism's `open`).
    pub open: bool,
    /// `conic_sweep`: at depth z the outline is scaled by z (apex at the origin).
    pub conic: bool,
}

/// A `blob`: the surface where the summed component fields equal the threshold.
#[derive(Clone, Debug)]
pub struct Blob {
    /// The field value of the surface (default 1).
    pub threshold: f64,
    /// The components, each with its own transform into the blob's space.
    pub components: Vec<BlobComponent>,
}

impl Blob {
    /// True when some component has its own texture.
    pub fn has_component_textures(&self) -> bool {
        self.components.iter().any(|c| c.texture.is_some())
    }
}

/// One blob component: field `strength * (1 - (d / radius)²)²` within `radius`.
#[derive(Clone, Debug)]
pub struct BlobComponent {
    /// Sphere or cylinder (with hemispherical caps).
    pub kind: BlobKind,
    /// Radius of influence.
    pub radius: f64,
    /// Field value at the centre (or axis); may be negative.
    pub strength: f64,
    /// Maps the component's space into the blob's.
    pub transform: Transform,
    /// The component's own texture, in the blob's space (its transformations applied);
    /// `None` shows the blob's. Where components with textures meet, each texture is shaded
    /// and the results blended by the components' shares of the field.
    pub texture: Option<Arc<Texture>>,
}

/// The shape of a blob component's field.
#[derive(Clone, Copy, Debug)]
pub enum BlobKind {
    /// Distance to a point.
    Sphere { centre: DVec3 },
    /// Distance to a segment.
    Cylinder { end1: DVec3, end2: DVec3 },
}

/// The four CSG operations.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CsgOperation {
    /// All surfaces of all children.
    Union,
    /// Surfaces of each child that lie inside all the others.
    Intersection,
    /// The first child minus the rest (an intersection with the later children inverted).
    Difference,
    /// A union without the surfaces that lie inside other children.
    Merge,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Generated scenes hold hundreds of thousands of objects: their size is memory and
    /// evaluation time (160,000 boxes of 416 bytes each made up a third of the Menger
    /// benchmark's parse time in page faults).
    #[test]
    fn objects_stay_small() {
        assert!(
            std::mem::size_of::<Shape>() <= 72,
            "{}",
            std::mem::size_of::<Shape>()
        );
        // 168 bytes before `interior_texture` (one pointer; no field had room to share),
        // 184 since `photons` (eight bytes: a spacing multiplier and on/off bits).
        assert!(
            std::mem::size_of::<Object>() <= 184,
            "{}",
            std::mem::size_of::<Object>()
        );
    }
}
