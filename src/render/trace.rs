//! The recursive (Whitted) tracer: surface colour, transparency, refraction, reflection.
//!
//! In: a [`Scene`] (lights, background, global settings), its [`World`] and a ray. Out: the
//! linear colour seen along the ray. Holds: no allocation per ray; recursion depth is bounded
//! by `max_trace_level` (capped at 256, as POV-Ray does), and rays that merely continue
//! through a surface are followed in a loop, not by recursion.
//!
//! Rules measured against POV-Ray 3.7 renders:
//! - surface colour = `opacity · body + highlights
//!   + reflection · traced(reflected ray) + (filter · pigment + transmit) · traced(through)`,
//!   where body is ambient + emission + diffuse and highlights are phong + specular
//!   (highlights and reflection are not weakened by transparency; no clamping anywhere).
//!   opacity is `1 − filter − transmit`; in legacy scenes (no `#version`, or one below 3.7)
//!   it is `1 − filter · max(r, g, b) − transmit`, as POV-Ray 3.7 renders them.
//! - trace levels: the camera ray has level 1. At a surface hit by a ray of level L no
//!   further ray is traced when L ≥ `max_trace_level` (such rays contribute black, not the
//!   background). Reflected and refracted rays get level L + 1; a ray passing a surface
//!   without bending (equal indices of refraction on both sides) keeps level L.
//! - adaptive depth control: every ray carries a weight (1 for camera rays). A reflected
//!   ray's weight is the parent's times the largest component of `reflection`; a
//!   transmitted ray's weight is the parent's times the largest component of
//!   `|T|`, `T = filter · pigment + transmit` (a negative transmit is not clamped: it
//!   subtracts the light behind, measured at −1 and −0.5). A ray is traced only if its weight
//!   is at least `adc_bailout` (equality traces); a transmitted ray also needs the surface's
//!   own grey value of `|T|`, `0.297 r + 0.589 g + 0.114 b`, to be at least `adc_bailout`
//!   (this test does not include the parent's weight). Found by bisecting `adc_bailout` on stacks of
//!   discs with differently coloured filters, e.g. after a `transmit 0.5` disc, a disc with
//!   `rgbf <0,0,1,0.8>` is passed up to bailout 0.0912 (its grey), one with
//!   `rgbf <0.5,1,0.5,0.8>` up to 0.4 (0.5 · 0.8).
//! - refraction: Snell's law with ratio n₁/n₂. Entering (ray against the outward normal),
//!   n₁ is the index of the medium the ray is in (1 outside everything) and n₂ the object's;
//!   leaving, n₁ is the object's and n₂ the medium's outside it. Shadow rays never bend.
//! - total internal reflection: the surface then reflects with weight 1 (the finish's
//!   `reflection` is replaced, not added), whatever the filter or transmit amount, provided
//!   the transmitted ray passed the trace-level and bailout tests. The reflected ray's ADC
//!   weight is the transmitted ray's, parent · max(T): with it, random scenes with total
//!   internal reflection match POV-Ray exactly, and a `transmit 0.7` sphere seen by total
//!   internal reflection behind `rgbf <0.2,0.3,0.4,1>` is passed up to bailout 0.28 =
//!   0.4 · 0.7. (Not matched: in isolated tests a mirror seen that way reflects only up to
//!   bailout (parent · max(T))² · reflection.)

use super::atmosphere::AtmosphereShader;
use super::dispersion::Bands;
use super::encoding::is_legacy_scene;
use super::interiors::{interiors_around, InteriorStack};
use super::lights::{prepare_lights, SceneLight};
use super::media::{ActiveMedia, MediaShader, Stretch};
use super::optics::{
    apply_exponent, interior_fade, mirror, reflection_colour, refract, sanitise_ior, transmission,
    SURFACE_EPSILON,
};
use super::photons::PhotonMap;
use super::quality::Quality;
use super::radiosity::{Gathered, Radiosity};
use super::shading::{local_light, SurfaceSample};
use super::subsurface::{SubsurfacePoint, SubsurfaceShader};
use super::surface::{for_each_component, pigment_at_hit};
use crate::accel::counters::{self, Counter};
use crate::geometry::{Material, Ray, SurfaceHit, World};
use crate::texture::normal::perturbed_normal_at;
use crate::texture::pigment::hit_surface;
use crate::{
    scene::Scene,
    texture::{finish::Finish, Texture},
};
use glam::{DVec3, DVec4};
use std::cell::Cell;

/// POV-Ray's upper limit for `max_trace_level`.
const TRACE_LEVEL_LIMIT: u32 = 256;

/// At most this many surfaces are passed without bending along one ray.
const MAX_CONTINUATIONS: u32 = 100_000;

/// Weights of red, green and blue in POV-Ray's grey value of a colour.
const GREY_WEIGHTS: DVec3 = DVec3::new(0.297, 0.589, 0.114);

/// Traces rays through one scene; shared read-only by all threads.
pub struct Tracer<'a> {
    scene: &'a Scene,
    world: &'a World,
    max_trace_level: u32,
    adc_bailout: f64,
    atmosphere: AtmosphereShader<'a>,
    legacy_opacity: bool,
    lights: Vec<SceneLight>,
    /// Some object is `no_image` (camera rays must skip it).
    any_no_image: bool,
    /// Some object is `no_reflection` (reflected rays must skip it).
    any_no_reflection: bool,
    /// How far camera rays see (a mesh camera's `max_distance`; else infinite).
    camera_reach: f64,
    /// The scene has media (atmospheric or in some interior).
    any_media: bool,
    /// What camera rays start in: the objects around the camera (their media fill the
    /// rays from the start, their index of refraction bends them), flagged when one of
    /// them is not hollow (camera rays then see no fog or media).
    camera_interiors: InteriorStack,
    /// Radiosity's `media on`: gathering rays see media.
    gathering_sees_media: bool,
    /// Some object is `no_radiosity` (radiosity's gathering rays must skip it).
    any_no_radiosity: bool,
    /// Indirect diffuse light, when the scene has a radiosity block.
    radiosity: Option<Radiosity>,
    /// Caustics, when the scene has a photons block.
    photons: Option<PhotonMap>,
    /// Rays keep count of the background they see, for an alpha channel (`+UA`): the
    /// background then adds only its opaque part to the colour.
    alpha: bool,
    /// What is computed (`+Q`).
    quality: Quality,
}

/// What a ray is for, which decides the objects it can see.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum RayKind {
    /// A ray from the camera (and its unbent continuations): skips `no_image` objects.
    Camera,
    /// A mirror-reflected ray: skips `no_reflection` objects.
    Reflected,
    /// A refracted ray: sees everything.
    Refracted,
    /// A radiosity gathering ray: skips `no_radiosity` objects.
    Gathering,
}

impl<'a> Tracer<'a> {
    /// A tracer for `scene`, whose objects `world` holds.
    pub fn new(scene: &'a Scene, world: &'a World) -> Tracer<'a> {
        let settings = &scene.settings;
        let legacy = is_legacy_scene(settings);
        let adc_bailout = if settings.adc_bailout.is_nan() {
            0.0
        } else {
            settings.adc_bailout
        };
        Tracer {
            scene,
            world,
            max_trace_level: settings.max_trace_level.clamp(1, TRACE_LEVEL_LIMIT),
            adc_bailout,
            atmosphere: AtmosphereShader::new(&scene.atmosphere, scene.background.rgb_vec())
                .with_legacy_sky_layers(legacy)
                .with_noise_generator(settings.noise_generator),
            legacy_opacity: legacy,
            lights: prepare_lights(scene),
            any_no_image: world.materials.iter().any(|m| m.no_image),
            any_no_reflection: world.materials.iter().any(|m| m.no_reflection),
            camera_reach: scene
                .camera
                .mesh
                .as_ref()
                .map_or(f64::INFINITY, |m| m.reach()),
            any_media: !scene.atmosphere.media.is_empty()
                || world.materials.iter().any(|m| !m.interior.media.is_empty()),
            camera_interiors: interiors_around(world, scene.camera.location),
            gathering_sees_media: settings.radiosity.as_ref().is_some_and(|r| r.use_media),
            any_no_radiosity: world.materials.iter().any(|m| m.no_radiosity),
            radiosity: settings
                .radiosity
                .as_ref()
                .map(|radiosity| Radiosity::new(radiosity, scene.camera.location)),
            photons: PhotonMap::build(scene, world),
            alpha: false,
            quality: Quality::default(),
        }
    }

    /// This tracer at a quality level (the scene already reduced by [`Quality::reduced`]):
    /// leaves out media in objects, transparency and mirror reflection as the level says.
    pub fn with_quality(mut self, quality: Quality) -> Tracer<'a> {
        self.quality = quality;
        self.any_media &= quality.media_and_global_light();
        self
    }

    /// This tracer, computing how much background each camera ray sees (for `+UA`).
    pub fn with_alpha(mut self, alpha: bool) -> Tracer<'a> {
        self.alpha = alpha;
        self
    }

    /// How much of the background shows where a ray meets it, as POV-Ray's alpha output
    /// measures it: its transmit plus its filter times the grey of its colour (measured:
    /// `rgbf <0.2, 0.3, 0.4, 1>` leaves 0.282 of the pixel transparent).
    fn background_transparency(&self) -> f64 {
        let background = &self.scene.background;
        (background.filter * background.rgb_vec().dot(GREY_WEIGHTS) + background.transmit)
            .clamp(0.0, 1.0)
    }

    /// The scene's radiosity state, if it has radiosity.
    pub fn radiosity(&self) -> Option<&Radiosity> {
        self.radiosity.as_ref()
    }

    /// Indirect light arriving at a surface point from the hemisphere around `normal`,
    /// for a ray `inside` describes at trace `level` (zero without radiosity).
    fn indirect_light(
        &self,
        point: DVec3,
        normal: DVec3,
        level: u32,
        inside: &InteriorStack,
    ) -> DVec3 {
        let Some(radiosity) = &self.radiosity else {
            return DVec3::ZERO;
        };
        let depth = inside.radiosity_depth;
        if !radiosity.lights_depth(depth) || level >= self.max_trace_level {
            return DVec3::ZERO;
        }
        let gathering = InteriorStack::OUTSIDE.at_radiosity_depth(depth + 1);
        radiosity.irradiance(point, normal, depth, &|direction| {
            let ray = Ray {
                origin: point,
                direction,
            };
            let (colour, distance, _) = self.trace_measuring(
                ray,
                level + 1,
                RayWeight::CAMERA,
                &gathering,
                RayKind::Gathering,
            );
            Gathered { colour, distance }
        })
    }

    /// The colour seen along a camera ray.
    pub fn trace_camera_ray(&self, ray: &Ray) -> DVec3 {
        self.trace_camera_sample(ray).truncate()
    }

    /// The colour seen along a camera ray and (with alpha, [`Self::with_alpha`]) the share
    /// of background seen through transparent surfaces and refraction (not reflection),
    /// as the fourth component.
    pub fn trace_camera_sample(&self, ray: &Ray) -> DVec4 {
        let (colour, _, background) = self.trace_measuring(
            *ray,
            1,
            RayWeight::CAMERA,
            &self.camera_interiors,
            RayKind::Camera,
        );
        if colour.is_finite() && background.is_finite() {
            colour.extend(background)
        } else {
            DVec4::ZERO
        }
    }

    /// The colour seen along `ray`, a ray of trace `level` and ADC `weight` inside the
    /// objects of `inside`.
    fn trace(
        &self,
        ray: Ray,
        level: u32,
        weight: RayWeight,
        inside: &InteriorStack,
        kind: RayKind,
    ) -> DVec3 {
        self.trace_measuring(ray, level, weight, inside, kind).0
    }

    /// [`Self::trace`]'s colour, the distance to the first surface the ray meets (infinite
    /// when it meets none) and the share of background it sees (0 without alpha).
    fn trace_measuring(
        &self,
        ray: Ray,
        level: u32,
        weight: RayWeight,
        inside: &InteriorStack,
        kind: RayKind,
    ) -> (DVec3, f64, f64) {
        counters::add(
            match kind {
                RayKind::Camera => Counter::CameraRays,
                RayKind::Reflected => Counter::ReflectedRays,
                RayKind::Refracted => Counter::RefractedRays,
                RayKind::Gathering => Counter::RadiosityRays,
            },
            1,
        );
        // Distance to the first surface met, once one is met.
        let mut first_distance = f64::INFINITY;
        let mut inside = *inside;
        let mut weight = weight;
        let mut min_distance = SURFACE_EPSILON;
        // Product of the transmission of the surfaces passed so far without bending.
        let mut carried = DVec3::ONE;
        let mut colour = DVec3::ZERO;
        // With alpha: the share of background seen, and the product of the transparency
        // (grey of what each surface lets through) of the surfaces passed.
        let counts_background = self.alpha && !inside.reflected && inside.radiosity_depth == 0;
        let mut background = 0.0;
        let mut carried_transparency = 1.0;
        // Where the stretch of the ray not yet passed through the atmosphere starts.
        let mut segment_start = 0.0;
        let mut travelled = 0.0;
        for _ in 0..MAX_CONTINUATIONS {
            let hit = self.first_hit(&ray, min_distance, kind);
            if !self.atmosphere.is_clear() {
                let start = ray.origin + ray.direction * segment_start;
                let end = hit.as_ref().map_or(f64::INFINITY, |hit| hit.distance);
                // Fog does not fill non-hollow objects.
                if self.all_hollow(&inside) {
                    let (keep, add) =
                        self.atmosphere
                            .along(start, ray.direction, end - segment_start);
                    colour += carried * add;
                    carried *= keep;
                }
                segment_start = end;
            }
            // Radiosity's gathering rays see media only with its `media on` (POV-Ray's
            // default is off).
            if self.any_media && (inside.radiosity_depth == 0 || self.gathering_sees_media) {
                let end = hit.as_ref().map_or(f64::INFINITY, |hit| hit.distance);
                let (keep, add) = self.media_along(&ray, &inside, travelled, end);
                colour += carried * add;
                carried *= keep;
            }
            let Some(hit) = hit else {
                let sky = self.atmosphere.sky(ray.direction);
                if counts_background {
                    background += carried_transparency * self.background_transparency();
                    let opacity =
                        (1.0 - self.scene.background.filter - self.scene.background.transmit)
                            .clamp(0.0, 1.0);
                    return (colour + carried * sky * opacity, first_distance, background);
                }
                return (colour + carried * sky, first_distance, background);
            };
            first_distance = first_distance.min(hit.distance);
            let Some(material) = self.world.materials.get(hit.material as usize) else {
                return (colour, first_distance, background);
            };
            // Light from beyond this hit fades on its way through the object the ray is in,
            // when the hit is on that object (measured: povray fades nothing on the way to
            // another object inside it, nor out through a clipped-away part). Only the light
            // that came through the surface fades; the surface's own light and its finish
            // reflection do not (measured through thick glass slabs).
            let mut fade = DVec3::ONE;
            if inside
                .materials_innermost_first()
                .any(|id| id == hit.material)
            {
                if let Some(kept) = interior_fade(&material.interior, hit.distance - travelled) {
                    fade = kept;
                }
            }
            travelled = hit.distance;
            let indirect = Cell::new(None);
            let caustics = Cell::new(None);
            let surface = self.shade(
                &ray, &hit, material, level, weight, &inside, &indirect, &caustics,
            );
            colour += carried * (surface.colour + fade * surface.through);
            background += carried_transparency * fade.dot(GREY_WEIGHTS) * surface.background;
            let Some(continued) = surface.continued else {
                return (colour, first_distance, background);
            };
            carried *= fade * continued.filter;
            carried_transparency *= (fade * continued.filter).dot(GREY_WEIGHTS);
            weight = continued.weight;
            inside = continued.inside;
            // The same ray is searched again beyond this hit, which avoids drift along it.
            min_distance = hit.distance + SURFACE_EPSILON;
        }
        (colour, first_distance, background)
    }

    /// Whether every object of `inside` is hollow (so fog and media fill it).
    fn all_hollow(&self, inside: &InteriorStack) -> bool {
        !inside.in_solid
            && inside.materials_innermost_first().all(|id| {
                self.world
                    .materials
                    .get(id as usize)
                    .is_none_or(|material| material.hollow)
            })
    }

    /// What the media do along `ray` from `start` to `end` inside the objects of `inside`:
    /// their interiors' media and the atmospheric media, but nothing at all inside a
    /// non-hollow object (measured: a non-hollow box shows none of its own media, nor of a
    /// hollow box inside it, nor does a hollow media sphere inside a non-hollow plane that
    /// holds the camera).
    fn media_along(
        &self,
        ray: &Ray,
        inside: &InteriorStack,
        start: f64,
        end: f64,
    ) -> (DVec3, DVec3) {
        if !self.all_hollow(inside) {
            return (DVec3::ONE, DVec3::ZERO);
        }
        // The first media listed rules the sampling: the container entered first, then
        // the atmosphere (measured).
        let mut active = ActiveMedia::NONE;
        for id in inside.materials_outermost_first() {
            if let Some(material) = self.world.materials.get(id as usize) {
                active.extend(&material.interior.media, material.light_group);
            }
        }
        active.extend_atmosphere(&self.scene.atmosphere.media);
        let shader = MediaShader::new(self.world, &self.lights).with_photons(self.photons.as_ref());
        let stretch = Stretch {
            origin: ray.origin,
            direction: ray.direction,
            start,
            end,
        };
        shader.along(&active, stretch)
    }

    /// The nearest surface along `ray` beyond `min_distance` that a ray of this kind sees.
    fn first_hit(&self, ray: &Ray, min_distance: f64, kind: RayKind) -> Option<SurfaceHit> {
        let materials = &self.world.materials;
        let reach = match kind {
            RayKind::Camera => self.camera_reach,
            _ => f64::INFINITY,
        };
        match kind {
            RayKind::Camera if self.any_no_image => {
                self.world
                    .first_hit_skipping(ray, min_distance, reach, &|id: u32| {
                        materials.get(id as usize).is_some_and(|m| m.no_image)
                    })
            }
            RayKind::Reflected if self.any_no_reflection => {
                self.world
                    .first_hit_skipping(ray, min_distance, f64::INFINITY, &|id: u32| {
                        materials.get(id as usize).is_some_and(|m| m.no_reflection)
                    })
            }
            RayKind::Gathering if self.any_no_radiosity => {
                self.world
                    .first_hit_skipping(ray, min_distance, reach, &|id: u32| {
                        materials.get(id as usize).is_some_and(|m| m.no_radiosity)
                    })
            }
            _ => self.world.first_hit(ray, min_distance, reach),
        }
    }

    /// The light leaving a surface towards the ray, and how the ray continues through it
    /// when it passes without bending: the blend of the shaded plain textures the material's
    /// texture is made of (see [`for_each_component`]). `indirect` holds the hit's radiosity
    /// light once a component has gathered it: POV-Ray gathers once per hit, not per layer;
    /// `caustics` likewise holds the photon light arriving there.
    #[allow(clippy::too_many_arguments)]
    fn shade(
        &self,
        ray: &Ray,
        hit: &SurfaceHit,
        material: &Material,
        level: u32,
        weight: RayWeight,
        inside: &InteriorStack,
        indirect: &Cell<Option<DVec3>>,
        caustics: &Cell<Option<DVec3>>,
    ) -> Shaded {
        if let Some(blend) = &hit.blend {
            // Several textures (a mesh triangle's corners, a blob's components): each shaded,
            // blended by weight. The hit keeps its material as the object's identity, so
            // the ray enters and leaves the same interior whichever texture shows.
            let mut total = Shaded {
                colour: DVec3::ZERO,
                through: DVec3::ZERO,
                background: 0.0,
                continued: None,
            };
            for (part_material, share) in blend.iter() {
                let Some(part_material) = self.world.materials.get(part_material as usize) else {
                    continue;
                };
                let single = SurfaceHit {
                    blend: None,
                    ..*hit
                };
                let part = self.shade(
                    ray,
                    &single,
                    part_material,
                    level,
                    weight,
                    inside,
                    indirect,
                    caustics,
                );
                total.add(DVec3::splat(share.max(0.0)), part);
            }
            return total;
        }
        let texture = material.texture_facing(ray.direction, hit.normal);
        if texture.compound.is_none() {
            return self.shade_plain(
                ray, hit, material, texture, true, level, weight, inside, indirect, caustics,
            );
        }
        let mut total = Shaded {
            colour: DVec3::ZERO,
            through: DVec3::ZERO,
            background: 0.0,
            continued: None,
        };
        let surface = hit_surface(hit.point, ray.direction, hit.normal);
        for_each_component(texture, hit, &surface, &mut |plain, share, passes_light| {
            let part = self.shade_plain(
                ray,
                hit,
                material,
                plain,
                passes_light,
                level,
                weight,
                inside,
                indirect,
                caustics,
            );
            total.add(share, part);
        });
        total
    }

    /// [`Self::shade`] for one plain texture; `passes_light` false for an upper layer of a
    /// layered texture (the layers below stand for what is seen through it); `indirect` is
    /// the hit's radiosity light and `caustics` its photon light, each gathered by the first
    /// component that needs it (with that component's normal and brilliance).
    #[allow(clippy::too_many_arguments)]
    fn shade_plain(
        &self,
        ray: &Ray,
        hit: &SurfaceHit,
        material: &Material,
        texture: &Texture,
        passes_light: bool,
        level: u32,
        weight: RayWeight,
        inside: &InteriorStack,
        indirect: &Cell<Option<DVec3>>,
        caustics: &Cell<Option<DVec3>>,
    ) -> Shaded {
        let surface = hit_surface(hit.point, ray.direction, hit.normal);
        let pigment = pigment_at_hit(&texture.pigment, hit, &surface);
        if self.quality.colours_only() {
            return Shaded {
                colour: pigment.rgb_vec(),
                through: DVec3::ZERO,
                background: 0.0,
                continued: None,
            };
        }
        // Whether the ray goes into the hit object's own volume: by the objects it is known
        // to be in, not by the side of the surface, so that a subtracted child's surface
        // (an air bubble cut out of glass) is entered from the glass and left into it, as
        // povray refracts there (measured: the bubble shows the sky above it upright).
        let entering = !inside.contains(hit.material);
        let normal = match &texture.normal {
            Some(perturbation) => perturbed_normal_at(perturbation, hit.point, hit.uv, &surface),
            None => surface.normal,
        };
        let sample = SurfaceSample {
            point: hit.point,
            normal,
            ray_direction: ray.direction,
            pigment,
            finish: &texture.finish,
            double_illuminate: material.double_illuminate,
            light_group: material.light_group,
            area_lights_as_points: inside.radiosity_depth > 0,
        };
        let settings = &self.scene.settings;
        let subsurface = match (&settings.subsurface, &texture.finish.subsurface) {
            (Some(_), Some(block)) if texture.finish.diffuse != 0.0 => Some(block),
            _ => None,
        };
        let mut local = match subsurface {
            None => local_light(&sample, &self.lights, settings.ambient_light, self.world),
            Some(block) => {
                // The light sources' diffuse light is scattered under the surface instead.
                let classic = Finish {
                    diffuse: 0.0,
                    diffuse_back: 0.0,
                    ..Finish::clone(&texture.finish)
                };
                let without_diffuse = SurfaceSample {
                    finish: &classic,
                    ..sample
                };
                let mut local = local_light(
                    &without_diffuse,
                    &self.lights,
                    settings.ambient_light,
                    self.world,
                );
                let shader = SubsurfaceShader::new(
                    settings.subsurface,
                    settings.mm_per_unit,
                    self.world,
                    &self.lights,
                );
                if let Some(shader) = shader {
                    local.body += shader.scattered(&SubsurfacePoint {
                        point: hit.point,
                        normal,
                        facing: surface.normal,
                        view: ray.direction,
                        reflectance: pigment.rgb_vec() * texture.finish.diffuse,
                        ior: sanitise_ior(material.interior.ior),
                        material: hit.material,
                        light_group: material.light_group,
                        subsurface: block,
                    });
                }
                local
            }
        };
        if self.radiosity.is_some() && texture.finish.diffuse != 0.0 {
            let radiosity = self.scene.settings.radiosity.as_ref();
            let oriented = if radiosity.is_some_and(|r| r.use_normal) {
                normal
            } else {
                surface.normal
            };
            let light = indirect.get().unwrap_or_else(|| {
                let light = self.indirect_light(hit.point, oriented, level, inside);
                indirect.set(Some(light));
                light
            });
            local.body += pigment.rgb_vec() * texture.finish.diffuse * light;
        }
        if let Some(photons) = &self.photons {
            if material.photons.collect() && texture.finish.diffuse != 0.0 {
                let light = caustics.get().unwrap_or_else(|| {
                    let light = photons.irradiance(hit.point, normal, texture.finish.brilliance);
                    caustics.set(Some(light));
                    light
                });
                local.body += pigment.rgb_vec() * texture.finish.diffuse * light;
            }
        }
        let opacity = if self.legacy_opacity {
            1.0 - pigment.filter * pigment.rgb_vec().max_element() - pigment.transmit
        } else {
            1.0 - pigment.filter - pigment.transmit
        };
        let mut shaded = Shaded {
            colour: opacity * local.body + local.highlights,
            through: DVec3::ZERO,
            background: 0.0,
            continued: None,
        };
        if level >= self.max_trace_level {
            return shaded;
        }

        // The indices of refraction on both sides, for refraction and Fresnel reflection.
        let interior = &material.interior;
        let mut ior = sanitise_ior(interior.ior);
        if let Some(offset) = inside.band {
            ior = sanitise_ior(ior * interior.dispersion.powf(offset));
        }
        let (ratio, beyond) = if entering {
            (inside.ior() / ior, inside.entered(hit.material, ior))
        } else {
            let beyond = inside.left(hit.material);
            (ior / beyond.ior(), beyond)
        };
        let finish = &texture.finish;
        let cos_incidence = -ray.direction.dot(normal);
        let mut reflection = if self.quality.reflection() {
            reflection_colour(finish, cos_incidence, ratio, pigment.rgb_vec())
        } else {
            DVec3::ZERO
        };
        let mut reflection_weight = weight.reflected(reflection);

        // Light coming through the surface.
        let mut pass = if passes_light && self.quality.transparency() {
            transmission(pigment)
        } else {
            DVec3::ZERO
        };
        if finish.conserve_energy {
            pass *= DVec3::ONE - reflection;
        }
        let pass_weight = weight.transmitted(pass);
        // Whether the mirror reflection is a total internal reflection (also when the
        // finish reflection has taken all the light there, as `fresnel` does with
        // `conserve_energy`): it fades inside the object like light coming through (measured
        // through a glass prism).
        let bends = (ratio - 1.0).abs() >= 1e-12;
        let bent = if bends {
            refract(ray.direction, normal, ratio)
        } else {
            None
        };
        let mut totally_reflected = bends && bent.is_none();
        // Negative transmit subtracts what lies behind; it is weighed by its size.
        let surface_passes = pass.abs().dot(GREY_WEIGHTS) >= self.adc_bailout;
        if pass_weight.0 > 0.0 && pass_weight.0 >= self.adc_bailout && surface_passes {
            if !bends {
                shaded.continued = Some(Continued {
                    filter: pass,
                    weight: pass_weight,
                    inside: beyond,
                });
            } else if entering && inside.band.is_none() && disperses(interior) {
                match self.dispersed(ray, hit, normal, inside, ior, level, pass_weight) {
                    Some(seen) => shaded.through += pass * seen,
                    None => {
                        reflection = DVec3::ONE;
                        reflection_weight = pass_weight;
                        totally_reflected = true;
                    }
                }
            } else if let Some(bent) = bent {
                let through = Ray {
                    origin: hit.point,
                    direction: bent,
                };
                let (seen, _, background) = self.trace_measuring(
                    through,
                    level + 1,
                    pass_weight,
                    &beyond,
                    RayKind::Refracted,
                );
                shaded.through += pass * seen;
                shaded.background += pass.dot(GREY_WEIGHTS) * background;
            } else {
                // Total internal reflection: the surface becomes a perfect mirror.
                reflection = DVec3::ONE;
                reflection_weight = pass_weight;
            }
        }

        // Under total internal reflection the layer that lets light through (the bottom one)
        // makes the surface a perfect mirror: an upper layer's own reflection adds nothing
        // (measured: a reflective top layer over a clear one renders as one clear layer with
        // that reflection, where light is totally reflected inside a glass box).
        let mirrored_below = !passes_light && bends && bent.is_none();
        // Mirror reflection.
        if !mirrored_below && reflection_weight.0 > 0.0 && reflection_weight.0 >= self.adc_bailout {
            if let Some(direction) = reflected_direction(ray.direction, normal, surface.normal) {
                let reflected = Ray {
                    origin: hit.point,
                    direction,
                };
                let seen = self.trace(
                    reflected,
                    level + 1,
                    reflection_weight,
                    &inside.reflected(),
                    RayKind::Reflected,
                );
                let mirrored = reflection * apply_exponent(seen, finish.reflection_exponent);
                if totally_reflected {
                    shaded.through += mirrored;
                } else {
                    shaded.colour += mirrored;
                }
            }
        }
        shaded
    }
}

/// The mirror direction of `direction` about the (possibly perturbed) unit `normal`. When a
/// perturbed normal would send it into the surface (against the geometric `facing` normal):
/// if it also points against `normal` (the ray met the perturbed normal from behind), the
/// mirror direction about `facing`; otherwise that direction mirrored once more, about the
/// surface plane (measured: directions read off a coloured sky reflected by a bumped plane).
fn reflected_direction(direction: DVec3, normal: DVec3, facing: DVec3) -> Option<DVec3> {
    let reflected = mirror(direction, normal).try_normalize()?;
    let below = reflected.dot(facing);
    if below < 0.0 {
        if reflected.dot(normal) < 0.0 {
            return mirror(direction, facing).try_normalize();
        }
        return (reflected - 2.0 * below * facing).try_normalize();
    }
    Some(reflected)
}

impl Tracer<'_> {
    /// White light entering a dispersive object: one refracted ray per band, each with its
    /// own index of refraction, weighted by the band's colour. `None` on total internal
    /// reflection of the middle of the spectrum.
    #[allow(clippy::too_many_arguments)]
    fn dispersed(
        &self,
        ray: &Ray,
        hit: &SurfaceHit,
        normal: DVec3,
        inside: &InteriorStack,
        ior: f64,
        level: u32,
        weight: RayWeight,
    ) -> Option<DVec3> {
        let interior = &self.world.materials.get(hit.material as usize)?.interior;
        let count = interior.dispersion_samples.max(2);
        refract(ray.direction, normal, inside.ior() / ior)?;
        let bands = Bands::new(count);
        let mut total = DVec3::ZERO;
        for index in 0..count {
            let (offset, colour) = bands.band(index);
            let band_ior = sanitise_ior(ior * interior.dispersion.powf(offset));
            let mut beyond = inside.entered(hit.material, band_ior);
            beyond.band = Some(offset);
            let Some(bent) = refract(ray.direction, normal, inside.ior() / band_ior) else {
                continue;
            };
            let through = Ray {
                origin: hit.point,
                direction: bent,
            };
            total += colour * self.trace(through, level + 1, weight, &beyond, RayKind::Refracted);
        }
        Some(total)
    }
}

/// Whether an interior splits light into bands.
fn disperses(interior: &crate::scene::Interior) -> bool {
    interior.dispersion != 1.0 && interior.dispersion > 0.0 && interior.dispersion.is_finite()
}

/// A ray's importance for adaptive depth control: compared with `adc_bailout` before the
/// ray is traced.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
struct RayWeight(f64);

impl RayWeight {
    /// The weight of a camera ray.
    const CAMERA: RayWeight = RayWeight(1.0);

    /// The weight of the ray reflected with this reflection colour.
    fn reflected(self, reflection: DVec3) -> RayWeight {
        RayWeight(self.0 * reflection.max_element())
    }

    /// The weight of the ray passing (or totally reflected at) a surface that lets `pass`
    /// through: the size of its largest component, as a negative `transmit` subtracts the
    /// light behind the surface (POV-Ray does not clamp it).
    fn transmitted(self, pass: DVec3) -> RayWeight {
        RayWeight(self.0 * pass.abs().max_element())
    }
}

/// What shading one surface yields.
struct Shaded {
    /// Light from the surface itself and its finish reflection.
    colour: DVec3,
    /// Light that came through the surface from beyond: bent transmitted rays, and the
    /// total internal reflection standing in for them (what an interior's fading dims).
    through: DVec3,
    /// The share of background seen through the surface by bent rays (alpha only).
    background: f64,
    /// How the ray goes on when it passes the surface without bending.
    continued: Option<Continued>,
}

impl Shaded {
    /// Adds `part` weighted by `share` (one component of a blended texture).
    fn add(&mut self, share: DVec3, part: Shaded) {
        self.colour += share * part.colour;
        self.through += share * part.through;
        self.background += share.dot(GREY_WEIGHTS) * part.background;
        if let Some(part) = part.continued {
            let continued = self.continued.get_or_insert(Continued {
                filter: DVec3::ZERO,
                weight: RayWeight(0.0),
                inside: part.inside,
            });
            continued.filter += share * part.filter;
            continued.weight = RayWeight(continued.weight.0.max(part.weight.0));
        }
    }
}

/// A ray passing a surface without bending.
struct Continued {
    /// What the surface lets through.
    filter: DVec3,
    /// The weight of the continuing ray.
    weight: RayWeight,
    /// The objects the ray is inside beyond the surface.
    inside: InteriorStack,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interior_stack_tracks_entering_and_leaving() {
        let glass = InteriorStack::OUTSIDE.entered(3, 1.5);
        assert_eq!(glass.ior(), 1.5);
        let water_in_glass = glass.entered(7, 1.33);
        assert_eq!(water_in_glass.ior(), 1.33);
        assert_eq!(water_in_glass.left(7).ior(), 1.5);
        assert_eq!(water_in_glass.left(3).ior(), 1.33);
        // Leaving something never entered (camera inside) changes nothing.
        assert_eq!(InteriorStack::OUTSIDE.left(9).ior(), 1.0);
        let mut deep = InteriorStack::OUTSIDE;
        for index in 0..40 {
            deep = deep.entered(index, f64::from(index));
        }
        assert_eq!(deep.ior(), 39.0);
    }
}
