//! Surface finishes and iridescence as POV-Ray defines them.
//!
//! In: nothing (data definitions). Out: [`Finish`], [`Irid`]. Holds: defaults are
//! POV-Ray 3.7's; `albedo` forms are already converted to the peak values used in shading.

use glam::DVec3;
use std::sync::{Arc, OnceLock};

/// POV-Ray's `finish` with its defaults.
#[derive(Clone, Debug)]
pub struct Finish {
    /// Ambient light reflected (colour; default 0.1 grey).
    pub ambient: DVec3,
    /// Light emitted independently of `ambient_light` (default black).
    pub emission: DVec3,
    /// Diffuse reflection (default 0.6).
    pub diffuse: f64,
    /// Diffuse reflection of light arriving from behind the surface (`diffuse D, B`;
    /// default 0).
    pub diffuse_back: f64,
    /// Diffuse falloff exponent (default 1).
    pub brilliance: f64,
    /// Random darkening of the diffuse light, 0 to 1 (default 0).
    pub crand: f64,
    /// Phong highlight amount (default 0).
    pub phong: f64,
    /// Phong exponent (default 40).
    pub phong_size: f64,
    /// Blinn specular highlight amount (default 0).
    pub specular: f64,
    /// Specular roughness (default 0.05).
    pub roughness: f64,
    /// Tints highlights with the surface colour, 0 to 1 (default 0).
    pub metallic: f64,
    /// Mirror reflection colour, the maximum (glancing) one for variable reflection
    /// (default black).
    pub reflection: DVec3,
    /// Reflection seen along the normal (`reflection { min, max }`); without it the
    /// reflection is constant, or (with `fresnel`) the minimum is black.
    pub reflection_min: Option<DVec3>,
    /// `fresnel`: the reflection varies with the angle by the Fresnel equations.
    pub fresnel: bool,
    /// `falloff`: exponent of the variation from minimum to maximum reflection (default 1).
    pub reflection_falloff: f64,
    /// `exponent` (or `reflection_exponent`): reflected light is raised to this power
    /// (default 1).
    pub reflection_exponent: f64,
    /// `metallic` inside `reflection` (or `reflect_metallic`): tints the reflection with the
    /// pigment (default 0).
    pub reflect_metallic: f64,
    /// `conserve_energy`: transparency is reduced by what the surface reflects.
    pub conserve_energy: bool,
    /// `irid { .. }`: thin-film interference colours.
    pub irid: Option<Irid>,
    /// `subsurface { translucency .. }`: light scattered under the surface (used only when
    /// `global_settings` has a `subsurface` block).
    pub subsurface: Option<Subsurface>,
}

/// `subsurface { translucency C anisotropy G }` in a finish.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Subsurface {
    /// The reduced mean free path `1 / σ't` per colour channel, in millimetres (scaled to
    /// scene units by `mm_per_unit`); POV-Ray's example gives marble Jensen et al.'s
    /// `1 / (σ's + σa)`.
    pub translucency: DVec3,
    /// `anisotropy` (default 0): read, and like POV-Ray 3.7 (measured) not used.
    pub anisotropy: DVec3,
}

impl Default for Finish {
    fn default() -> Self {
        Finish {
            ambient: DVec3::splat(0.1),
            emission: DVec3::ZERO,
            diffuse: 0.6,
            diffuse_back: 0.0,
            brilliance: 1.0,
            crand: 0.0,
            phong: 0.0,
            phong_size: 40.0,
            specular: 0.0,
            roughness: 0.05,
            metallic: 0.0,
            reflection: DVec3::ZERO,
            reflection_min: None,
            fresnel: false,
            reflection_falloff: 1.0,
            reflection_exponent: 1.0,
            reflect_metallic: 0.0,
            conserve_energy: false,
            irid: None,
            subsurface: None,
        }
    }
}

/// `irid { amount thickness T turbulence U }`.
#[derive(Clone, Debug)]
pub struct Irid {
    /// Contribution of the effect to the surface colour.
    pub amount: f64,
    /// Film thickness (default 0).
    pub thickness: f64,
    /// Variation of the thickness (default 0).
    pub turbulence: f64,
    /// The wavelengths of red, green and blue light: the scene's last
    /// `global_settings { irid_wavelength }`, wherever it is written (measured).
    pub wavelengths: SceneIridWavelengths,
    /// The noise generator of the thickness turbulence: the scene's global one (measured:
    /// POV-Ray's irid follows the last `global_settings { noise_generator }`).
    pub noise_generator: crate::noise::SceneNoiseGenerator,
}

/// A scene's `irid_wavelength` as irid reads it when shading: a handle shared by every
/// `irid` of the scene, fixed from the last `global_settings { irid_wavelength }` when
/// parsing ends; until then, and without a scene, [`DEFAULT_IRID_WAVELENGTHS`].
#[derive(Clone, Debug, Default)]
pub struct SceneIridWavelengths(Option<Arc<OnceLock<DVec3>>>);

impl SceneIridWavelengths {
    /// A fresh handle for a scene being parsed.
    pub fn for_scene() -> SceneIridWavelengths {
        SceneIridWavelengths(Some(Arc::new(OnceLock::new())))
    }

    /// Fixes the scene's wavelengths; later calls change nothing.
    pub fn fix(&self, wavelengths: DVec3) {
        if let Some(shared) = &self.0 {
            let _ = shared.set(wavelengths);
        }
    }

    /// The wavelengths of red, green and blue light.
    pub fn get(&self) -> DVec3 {
        self.0
            .as_ref()
            .and_then(|shared| shared.get().copied())
            .unwrap_or(DEFAULT_IRID_WAVELENGTHS)
    }
}

/// The irid wavelengths without `irid_wavelength` (measured from the interference phases;
/// an explicit `irid_wavelength` is used as it is written).
pub const DEFAULT_IRID_WAVELENGTHS: DVec3 = DVec3::new(0.70, 0.52, 0.48);
