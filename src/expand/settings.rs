//! The scene's frame: `global_settings`, camera, light sources, background and atmosphere,
//! then the objects.

use super::appearance::{write_media, write_normal, write_pigment, PigmentRole};
use super::objects::{write_light, write_object};
use super::{
    colour, matrix, noise_number, number, on_off, rgb, vector, Unsupported, Writer, Written,
};
use crate::math::Transform;
use crate::noise::NoiseGenerator;
use crate::scene::{
    Camera, FogKind, GlobalSettings, PhotonDensity, PhotonSettings, Projection, RadiositySettings,
    Scene, DEFAULT_ANGLE,
};
use std::fmt::Write as _;

pub(super) fn write_scene(writer: &mut Writer, out: &mut String, scene: &Scene) -> Written {
    write_global_settings(writer, out, &scene.settings)?;
    write_camera(writer, out, &scene.camera)?;
    let background = &scene.background;
    if *background != crate::math::Colour::BLACK {
        let _ = writeln!(out, "background {{ {} }}", colour(background));
    }
    for light in scene.lights.iter().filter(|light| light.group.is_none()) {
        write_light(writer, out, light)?;
    }
    let atmosphere = &scene.atmosphere;
    for fog in &atmosphere.fogs {
        out.push_str("fog {");
        match fog.kind {
            FogKind::Constant => out.push_str(" fog_type 1"),
            FogKind::Ground { offset, altitude } => {
                let _ = write!(
                    out,
                    " fog_type 2 fog_offset {} fog_alt {}",
                    number(offset),
                    number(altitude)
                );
            }
        }
        let _ = write!(
            out,
            " distance {} color {} up {}",
            number(fog.distance),
            colour(&fog.colour),
            vector(fog.up)
        );
        if let Some(turbulence) = &fog.turbulence {
            let _ = write!(
                out,
                " turbulence {} turb_depth {}",
                vector(turbulence.amount),
                number(turbulence.depth)
            );
            super::patterns::write_turbulence_shape(out, &turbulence.shape);
        }
        out.push_str(" }\n");
    }
    if let Some(sky) = &atmosphere.sky_sphere {
        out.push_str("sky_sphere {\n");
        for pigment in &sky.pigments {
            write_pigment(writer, out, pigment, &sky.transform, PigmentRole::Pigment)?;
        }
        if sky.emission != glam::DVec3::ONE {
            let _ = write!(out, " emission {}", rgb(sky.emission));
        }
        out.push_str(&matrix(&sky.transform));
        out.push_str("\n}\n");
    }
    for rainbow in &atmosphere.rainbows {
        let _ = write!(
            out,
            "rainbow {{ direction {} angle {} width {} distance {} jitter {} up {} \
             arc_angle {} falloff_angle {} color_map {{",
            vector(rainbow.direction),
            number(rainbow.angle),
            number(rainbow.width),
            number(rainbow.distance),
            number(rainbow.jitter),
            vector(rainbow.up),
            number(rainbow.arc_angle),
            number(rainbow.falloff_angle)
        );
        for (key, c) in &rainbow.colour_map {
            let _ = write!(out, " [{} {}]", number(*key), colour(c));
        }
        out.push_str(" } }\n");
    }
    for media in &atmosphere.media {
        write_media(writer, out, media, &Transform::IDENTITY)?;
        out.push('\n');
    }
    for object in &scene.objects {
        write_object(writer, out, object)?;
        out.push('\n');
    }
    Ok(())
}

fn write_global_settings(writer: &mut Writer, out: &mut String, s: &GlobalSettings) -> Written {
    let _ = writer;
    let defaults = GlobalSettings::default();
    out.push_str("global_settings {");
    if let Some(gamma) = s.assumed_gamma {
        let _ = write!(out, " assumed_gamma {}", number(gamma));
    }
    if s.max_trace_level != defaults.max_trace_level {
        let _ = write!(out, " max_trace_level {}", s.max_trace_level);
    }
    if s.adc_bailout != defaults.adc_bailout {
        let _ = write!(out, " adc_bailout {}", number(s.adc_bailout));
    }
    if s.ambient_light != defaults.ambient_light {
        let _ = write!(out, " ambient_light {}", rgb(s.ambient_light));
    }
    if s.noise_generator != NoiseGenerator::default() {
        let _ = write!(out, " noise_generator {}", noise_number(s.noise_generator));
    }
    if s.irid_wavelength != defaults.irid_wavelength {
        let _ = write!(out, " irid_wavelength {}", rgb(s.irid_wavelength));
    }
    if s.number_of_waves != defaults.number_of_waves {
        let _ = write!(out, " number_of_waves {}", s.number_of_waves);
    }
    if s.mm_per_unit != defaults.mm_per_unit {
        let _ = write!(out, " mm_per_unit {}", number(s.mm_per_unit));
    }
    if let Some(sub) = &s.subsurface {
        let _ = write!(
            out,
            " subsurface {{ samples {}, {} radiosity {} }}",
            sub.diffuse_samples,
            sub.single_samples,
            on_off(sub.radiosity)
        );
    }
    if let Some(radiosity) = &s.radiosity {
        write_radiosity(out, radiosity);
    }
    if let Some(photons) = &s.photons {
        write_photon_settings(out, photons);
    }
    out.push_str(" }\n");
    Ok(())
}

fn write_radiosity(out: &mut String, r: &RadiositySettings) {
    let _ = write!(
        out,
        "\n radiosity {{ count {}, {} error_bound {} recursion_limit {} brightness {} \
         gray_threshold {} low_error_factor {} minimum_reuse {} maximum_reuse {} \
         nearest_count {} pretrace_start {} pretrace_end {} adc_bailout {} \
         always_sample {} normal {} media {}",
        r.count,
        r.direction_pool,
        number(r.error_bound),
        r.recursion_limit,
        number(r.brightness),
        number(r.gray_threshold),
        number(r.low_error_factor),
        number(r.minimum_reuse),
        number(r.maximum_reuse),
        r.nearest_count,
        number(r.pretrace_start),
        number(r.pretrace_end),
        number(r.adc_bailout),
        on_off(r.always_sample),
        on_off(r.use_normal),
        on_off(r.use_media)
    );
    if r.max_sample > 0.0 {
        let _ = write!(out, " max_sample {}", number(r.max_sample));
    }
    out.push_str(" }");
}

fn write_photon_settings(out: &mut String, p: &PhotonSettings) {
    out.push_str("\n photons {");
    match p.density {
        PhotonDensity::Spacing(spacing) => {
            let _ = write!(out, " spacing {}", number(spacing));
        }
        PhotonDensity::Count(count) => {
            let _ = write!(out, " count {count}");
        }
    }
    let _ = write!(
        out,
        " gather {}, {} jitter {} autostop {} expand_thresholds {}, {}",
        p.gather_min,
        p.gather_max,
        number(p.jitter),
        number(p.autostop),
        number(p.expand_increase),
        p.expand_min
    );
    if p.media_steps > 0 {
        let _ = write!(out, " media {}, {}", p.media_steps, number(p.media_factor));
    }
    if let Some(level) = p.max_trace_level {
        let _ = write!(out, " max_trace_level {level}");
    }
    if let Some(bailout) = p.adc_bailout {
        let _ = write!(out, " adc_bailout {}", number(bailout));
    }
    if p.radius > 0.0 {
        let _ = write!(
            out,
            " radius {}, {}, {}, {}",
            number(p.radius),
            number(p.radius_multiplier),
            number(p.media_radius),
            number(p.media_radius_multiplier)
        );
    }
    out.push_str(" }");
}

fn write_camera(writer: &mut Writer, out: &mut String, camera: &Camera) -> Written {
    let projection = match camera.projection {
        Projection::Perspective => "perspective".to_string(),
        Projection::Orthographic => "orthographic".into(),
        Projection::Fisheye => "fisheye".into(),
        Projection::UltraWideAngle => "ultra_wide_angle".into(),
        Projection::Omnimax => "omnimax".into(),
        Projection::Panoramic => "panoramic".into(),
        Projection::Cylinder(kind) => format!("cylinder {}", kind as u32 + 1),
        Projection::Spherical => "spherical".into(),
        Projection::Mesh => return Err(Unsupported("a mesh_camera".into())),
    };
    let _ = write!(
        out,
        "camera {{ {projection} location {} direction {} right {} up {}",
        vector(camera.location),
        vector(camera.direction),
        vector(camera.right),
        vector(camera.up)
    );
    // The perspective and orthographic cameras take their field from the vectors (an
    // `angle` would rescale them); the others read the angle itself.
    match camera.projection {
        Projection::Perspective | Projection::Orthographic => {}
        Projection::Spherical => {
            let _ = write!(
                out,
                " angle {}, {}",
                number(camera.angle),
                number(camera.vertical_angle)
            );
        }
        _ if camera.angle != DEFAULT_ANGLE => {
            let _ = write!(out, " angle {}", number(camera.angle));
        }
        _ => {}
    }
    if let Some(blur) = &camera.focal_blur {
        let _ = write!(
            out,
            " aperture {} focal_point {} blur_samples {}, {} confidence {} variance {}",
            number(blur.aperture),
            vector(blur.focal_point),
            blur.min_samples,
            blur.max_samples,
            number(blur.confidence),
            number(blur.variance)
        );
    }
    if let Some(normal) = &camera.normal {
        out.push(' ');
        write_normal(writer, out, normal, &Transform::IDENTITY)?;
    }
    out.push_str(" }\n");
    Ok(())
}
