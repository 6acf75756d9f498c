//! Scene assembly: the blocks that become scene data — objects and shapes, textures and
//! their maps, patterns, finishes, interiors, media, lights, the camera, atmosphere and
//! global settings — and the scene being built from them.
//!
//! In: item streams read through the language runtime. Out: [`crate::scene`] values and,
//! at the end, the [`crate::scene::Scene`]. Holds: every block keyword is dispatched in
//! [`blocks`]; each reader checks what its block accepts and reports the rest with a span.

pub(crate) mod appearance;
pub(crate) mod atmosphere;
pub(crate) mod blocks;
pub(crate) mod camera;
pub(crate) mod finish;
pub(crate) mod image_map;
pub(crate) mod light;
pub(crate) mod media;
pub(crate) mod objects;
pub(crate) mod pattern;
pub(crate) mod photons;
pub(crate) mod radiosity;
pub(crate) mod settings;
pub(crate) mod shapes;
pub(crate) mod texture_maps;

use super::language::value::AtmosphericEffect;
use crate::math::{Colour, Transform};
use crate::scene::{Atmosphere, Camera, GlobalSettings, LightSource, Object, Scene, Shape};
use crate::texture::Texture;
use std::sync::Arc;

/// The scene being built: what the scene file's top-level items and settings have added.
pub(crate) struct SceneAssembly {
    /// `#default { texture { .. } }`, given to objects written without a texture.
    default_texture: Texture,
    default_texture_set: bool,
    camera: Option<Camera>,
    lights: Vec<LightSource>,
    /// How many `light_group`s have been evaluated (the next group's id).
    light_groups: u32,
    /// Set once a light is placed inside an object: until then no object needs searching for
    /// the lights it carries.
    objects_carry_lights: bool,
    objects: Vec<Object>,
    /// `background { }`: the colour of rays that hit nothing.
    background: Colour,
    /// Fog, sky sphere, rainbows and scene media.
    atmosphere: Atmosphere,
    /// `global_settings` so far.
    settings: GlobalSettings,
}

impl SceneAssembly {
    /// An empty scene with POV-Ray's defaults.
    pub(crate) fn new() -> SceneAssembly {
        SceneAssembly {
            default_texture: Texture::default(),
            default_texture_set: false,
            camera: None,
            lights: Vec::new(),
            light_groups: 0,
            objects_carry_lights: false,
            objects: Vec::new(),
            background: Colour::BLACK,
            atmosphere: Atmosphere::default(),
            settings: GlobalSettings::default(),
        }
    }

    /// Adds a top-level object: the default texture when it has none (fixed in the world,
    /// not moved by the object's transformations: measured with a `#default` gradient on
    /// translated and scaled objects), its light groups separated, the lights it carries
    /// placed in the scene.
    pub(crate) fn add_object(&mut self, object: Arc<Object>) {
        let mut object = Arc::unwrap_or_clone(object);
        if object.texture.is_none() && self.default_texture_set {
            let mut texture = self.default_texture.clone();
            if *object.transform() != Transform::IDENTITY && texture.depends_on_position() {
                texture.transform(&object.transform().inverse());
            }
            object.texture = Some(Arc::new(texture));
        }
        // Both walk the whole object tree: skip them while there is nothing to find.
        if self.light_groups > 0 {
            crate::scene::separate_light_groups(&mut object, &mut self.light_groups);
        }
        if self.objects_carry_lights {
            self.add_carried_lights(&object, &Transform::IDENTITY);
        }
        self.objects.push(object);
    }

    /// Adds a `media { }` written at the top level (scene media).
    pub(crate) fn add_media(&mut self, media: crate::scene::Media) {
        self.atmosphere.media.push(media);
    }

    /// Sets the `background` colour (the last one wins).
    pub(crate) fn set_background(&mut self, colour: Colour) {
        self.background = colour;
    }

    /// The handle through which functions read the scene's `noise_generator` when they
    /// run, so the last `global_settings` applies wherever it stands.
    pub(crate) fn scene_noise_generator(&self) -> crate::noise::SceneNoiseGenerator {
        self.settings.scene_noise_generator.clone()
    }

    /// Sets the camera (the last one wins).
    pub(crate) fn set_camera(&mut self, camera: Camera) {
        self.camera = Some(camera);
    }

    pub(crate) fn finish(&mut self, version: f64, version_declared: bool) -> Scene {
        let waves = crate::texture::pattern::WaveSources::new(self.settings.number_of_waves);
        self.settings.wave_sources.fix(waves);
        let wavelengths = self.settings.irid_wavelength;
        self.settings.scene_irid_wavelengths.fix(wavelengths);
        let mut settings = self.settings.clone();
        settings.language_version = version;
        settings.version_declared = version_declared;
        if settings.radiosity.is_some() && version >= 3.7 {
            // POV-Ray 3.7 replaces the ambient term by radiosity (legacy scenes keep it).
            settings.ambient_light = glam::DVec3::ZERO;
        }
        Scene {
            camera: self.camera.clone().unwrap_or_default(),
            lights: std::mem::take(&mut self.lights),
            objects: std::mem::take(&mut self.objects),
            background: self.background,
            atmosphere: std::mem::take(&mut self.atmosphere),
            settings,
        }
    }

    /// Adds a fog or rainbow layer, or sets the sky sphere (the last one wins).
    pub(crate) fn add_atmospheric_effect(&mut self, effect: &AtmosphericEffect) {
        match effect {
            AtmosphericEffect::Fog(fog) => self.atmosphere.fogs.push(fog.clone()),
            AtmosphericEffect::SkySphere(sky) => self.atmosphere.sky_sphere = Some(sky.clone()),
            AtmosphericEffect::Rainbow(rainbow) => self.atmosphere.rainbows.push(rainbow.clone()),
        }
    }

    /// Adds a light to the scene, and its `looks_like` object to the objects.
    /// Adds the lights written inside `object` and its CSG children, moved into world
    /// space (`outer` maps the object's parent space to world space).
    pub(crate) fn add_carried_lights(&mut self, object: &Object, outer: &Transform) {
        let to_world = object.transform().then(outer);
        for light in object.lights.iter().flat_map(|lights| lights.iter()) {
            self.add_light(light.transformed(&to_world));
        }
        if let Shape::Csg { children, .. } = &object.shape {
            for child in children {
                self.add_carried_lights(child, &to_world);
            }
        }
    }

    pub(crate) fn add_light(&mut self, light: LightSource) {
        if let Some(shape) = &light.looks_like {
            self.objects.push((**shape).clone());
        }
        self.lights.push(light);
    }

    pub(crate) fn set_default_texture(&mut self, texture: Texture) {
        self.default_texture = texture;
        self.default_texture_set = true;
    }
}
