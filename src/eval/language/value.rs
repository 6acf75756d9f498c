//! Runtime values of the scene language.

use crate::scene::{Fog, Rainbow, SkySphere};
use crate::syntax::ast::{FunctionLiteral, MacroDefinition};
use crate::texture::SlopeEntry;
use crate::{
    math::{Colour, Transform},
    scene::{Camera, Interior, LightSource, Object},
    texture::{finish::Finish, Normal, Pigment, Texture},
};
use std::rc::Rc;
use std::sync::Arc;

/// A value produced by evaluating an expression or a block.
#[derive(Clone, Debug)]
pub enum Value {
    /// A float (also booleans: 0 false, anything else true).
    Float(f64),
    /// A vector of 2 to 5 components.
    Vector(Vector),
    /// A colour (red, green, blue, filter, transmit).
    Colour(Colour),
    /// A string.
    String(Rc<str>),
    /// An array (copied on write).
    Array(Rc<Array>),
    /// An object (shape or CSG), shared so instances need not copy it.
    Object(Arc<Object>),
    /// A texture.
    Texture(Arc<Texture>),
    /// A pigment.
    Pigment(Rc<Pigment>),
    /// A finish.
    Finish(Rc<Finish>),
    /// An interior.
    Interior(Rc<Interior>),
    /// A `media { }` block.
    Media(Rc<crate::scene::Media>),
    /// A `density { }` block (a pigment whose colour is the density).
    Density(Rc<Pigment>),
    /// A `material`: a texture and, when it gives them, an interior texture and an interior.
    Material(Rc<MaterialValue>),
    /// A colour map.
    ColourMap(Rc<Vec<(f64, Colour)>>),
    /// A normal.
    Normal(Rc<Normal>),
    /// A pigment, normal, texture or slope map.
    Map(Rc<crate::eval::language::value::AppearanceMap>),
    /// A transformation (boxed: it is large and rare).
    Transform(Rc<Transform>),
    /// A camera.
    Camera(Rc<Camera>),
    /// A light source.
    Light(Rc<LightSource>),
    /// A fog, sky sphere or rainbow.
    Atmospheric(Rc<crate::eval::language::value::AtmosphericEffect>),
    /// A macro.
    Macro(Rc<MacroDefinition>),
    /// A user-defined function.
    Function(Rc<UserFunction>),
    /// A spline, called like a function.
    Spline(Rc<crate::texture::function::spline::Spline>),
    /// An open data file (index into the evaluator's file table).
    File(usize),
    /// What a block durer does not support yet evaluates to: it is left out of the scene.
    Nothing,
    /// A parameter passed by reference: the caller's variable `name` in scope `scope`.
    Reference {
        scope: usize,
        name: crate::syntax::symbol::Symbol,
    },
}

/// A user-defined function: its source and the form compiled where it was written.
#[derive(Debug)]
pub struct UserFunction {
    /// The literal (its span, and a height field's resolution).
    pub literal: Rc<FunctionLiteral>,
    /// Compiled when the literal was evaluated, so its identifiers mean what they meant there
    /// (as in POV-Ray); the diagnostic when it could not be compiled, reported where the
    /// function is used.
    pub compiled: Result<Arc<crate::texture::function::Function>, Box<crate::diag::Diagnostic>>,
}

/// A vector with 2 to 5 components.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vector {
    /// Components; those past `len` are zero.
    pub components: [f64; 5],
    /// Number of components in use.
    pub len: u8,
}

impl Vector {
    /// A vector from a slice of 1 to 5 components.
    pub fn from_slice(values: &[f64]) -> Vector {
        let mut components = [0.0; 5];
        for (c, v) in components.iter_mut().zip(values) {
            *c = *v;
        }
        Vector {
            components,
            len: values.len().clamp(1, 5) as u8,
        }
    }

    /// A 3-vector.
    pub fn from_dvec3(v: glam::DVec3) -> Vector {
        Vector::from_slice(&[v.x, v.y, v.z])
    }

    /// The first three components.
    pub fn to_dvec3(self) -> glam::DVec3 {
        glam::DVec3::new(self.components[0], self.components[1], self.components[2])
    }
}

/// An array value: dimension sizes and elements in row-major order.
#[derive(Clone, Debug)]
pub struct Array {
    /// Size of each dimension, outermost first.
    pub sizes: Vec<usize>,
    /// Elements; `None` until assigned.
    pub elements: Vec<Option<Value>>,
}

impl Value {
    /// The name of the value's type for messages ("a float", "an object"...).
    pub fn type_name(&self) -> &'static str {
        match self {
            Value::Float(_) => "a float",
            Value::Vector(_) => "a vector",
            Value::Colour(_) => "a colour",
            Value::String(_) => "a string",
            Value::Array(_) => "an array",
            Value::Object(_) => "an object",
            Value::Texture(_) => "a texture",
            Value::Pigment(_) => "a pigment",
            Value::Finish(_) => "a finish",
            Value::Interior(_) => "an interior",
            Value::Media(_) => "a media",
            Value::Density(_) => "a density",
            Value::Material(_) => "a material",
            Value::ColourMap(_) => "a colour map",
            Value::Normal(_) => "a normal",
            Value::Map(_) => "a map",
            Value::Transform(_) => "a transform",
            Value::Camera(_) => "a camera",
            Value::Light(_) => "a light source",
            Value::Atmospheric(_) => "an atmospheric effect",
            Value::Macro(_) => "a macro",
            Value::Function(_) => "a function",
            Value::Reference { .. } => "a reference",
            Value::Nothing => "a left-out feature",
            Value::File(_) => "a file handle",
            Value::Spline(_) => "a spline",
        }
    }
}

/// What a `material { .. }` holds.
#[derive(Clone, Debug)]
pub struct MaterialValue {
    /// The texture, if given (without one the object keeps its own, as in POV-Ray).
    pub texture: Option<Texture>,
    /// The `interior_texture`, if given.
    pub interior_texture: Option<Texture>,
    /// The interior, if given.
    pub interior: Option<Interior>,
}

impl MaterialValue {
    /// Moves what the material holds: its textures and its interior's media.
    pub fn transform(&mut self, t: &Transform) {
        for texture in self.texture.iter_mut().chain(&mut self.interior_texture) {
            texture.transform(t);
        }
        for media in self
            .interior
            .iter_mut()
            .flat_map(|interior| &mut interior.media)
        {
            media.transform(t);
        }
    }
}

/// One evaluated atmospheric block, as a value (it may be declared and reused).
#[derive(Clone, Debug)]
pub enum AtmosphericEffect {
    /// A `fog { }` layer.
    Fog(Fog),
    /// A `sky_sphere { }`.
    SkySphere(SkySphere),
    /// A `rainbow { }`.
    Rainbow(Rainbow),
}

/// A declared map: what `#declare M = pigment_map { .. }` (and friends) holds.
#[derive(Clone, Debug)]
pub enum AppearanceMap {
    /// `pigment_map`.
    Pigments(Vec<(f64, Pigment)>),
    /// `normal_map`.
    Normals(Vec<(f64, Normal)>),
    /// `texture_map`.
    Textures(Vec<(f64, Texture)>),
    /// `slope_map`.
    Slopes(Vec<SlopeEntry>),
    /// `density_map`: densities are pigments whose colour is the density.
    Densities(Vec<(f64, Pigment)>),
}
