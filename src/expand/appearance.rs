//! Appearance: textures (plain, layered, patterned, averaged, material maps), pigments,
//! normals, finishes, interiors and media.
//!
//! Every pattern transformation the scene holds is complete (it maps the pattern's space
//! to the object's); a block nested in another (a map entry) is written with its parent's
//! transformation undone, because the parent's `matrix`, written after the map, is applied
//! to the entries again when the file is read.

use super::patterns::{write_pattern_kind, write_pattern_modifiers};
use super::{
    address, colour, matrix, number, on_off, relative, rgb, vector, Unsupported, Writer, Written,
};
use crate::math::Transform;
use crate::scene::{Interior, Media, ScatteringKind};
use crate::texture::finish::Finish;
use crate::texture::{
    BlendMap, CompoundTexture, ImageGamma, ImageMap, ImageProjection, Normal, NormalSource,
    Pigment, PigmentMap, Texture,
};
use std::fmt::Write as _;
use std::sync::Arc;

/// Whether a pigment is a pigment or a media density (whose maps are `density_map`s).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum PigmentRole {
    Pigment,
    Density,
}

impl PigmentRole {
    fn keyword(self) -> &'static str {
        match self {
            PigmentRole::Pigment => "pigment",
            PigmentRole::Density => "density",
        }
    }

    fn map_keyword(self) -> &'static str {
        match self {
            PigmentRole::Pigment => "pigment_map",
            PigmentRole::Density => "density_map",
        }
    }
}

/// What an image block is for (which items it may hold).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ImageRole {
    Pigment,
    Pattern,
    Bump,
    Material,
}

/// ` KEYWORD { .. }` for an object's texture (several for a layered one; a shared texture
/// is declared once and named).
pub(super) fn write_texture_items(
    writer: &mut Writer,
    out: &mut String,
    texture: &Arc<Texture>,
    keyword: &str,
) -> Written {
    if Arc::strong_count(texture) > 1 {
        let name = declared_texture(writer, texture)?;
        let _ = write!(out, " {keyword} {{ {name} }}");
        return Ok(());
    }
    let mut text = String::new();
    write_texture_layers(writer, &mut text, texture, keyword, &Transform::IDENTITY)?;
    out.push_str(&writer.shared_text(text, keyword));
    Ok(())
}

/// The texture as one or more ` KEYWORD { .. }` blocks.
fn write_texture_layers(
    writer: &mut Writer,
    out: &mut String,
    texture: &Texture,
    keyword: &str,
    parent: &Transform,
) -> Written {
    if let Some(compound) = &texture.compound {
        if let CompoundTexture::Layered(layers) = &**compound {
            for layer in layers {
                write_texture_layers(writer, out, layer, keyword, parent)?;
            }
            return Ok(());
        }
    }
    let _ = write!(out, " {keyword} {{");
    write_texture_body(writer, out, texture, parent)?;
    out.push_str(" }");
    Ok(())
}

fn declared_texture(writer: &mut Writer, texture: &Arc<Texture>) -> Result<String, Unsupported> {
    writer.declared(address(texture), "Texture", |writer, text| {
        write_texture_layers(writer, text, texture, "texture", &Transform::IDENTITY)
    })
}

/// The items of a texture that is not layered.
fn write_texture_body(
    writer: &mut Writer,
    out: &mut String,
    texture: &Texture,
    parent: &Transform,
) -> Written {
    let Some(compound) = &texture.compound else {
        out.push(' ');
        write_pigment(writer, out, &texture.pigment, parent, PigmentRole::Pigment)?;
        if let Some(normal) = &texture.normal {
            out.push(' ');
            write_normal(writer, out, normal, parent)?;
        }
        write_finish(out, &texture.finish);
        return Ok(());
    };
    match &**compound {
        CompoundTexture::Layered(_) => {
            // Only reached for a layered texture inside a map: name it.
            let name = declared_texture(writer, &Arc::new(texture.clone()))?;
            let _ = write!(out, " {name}");
        }
        CompoundTexture::Pattern {
            pattern,
            map,
            transform,
        } => {
            out.push(' ');
            write_pattern_kind(writer, out, pattern)?;
            match map {
                BlendMap::Entries(entries) => {
                    write_map(out, "texture_map", entries, |out, entry| {
                        write_texture_entry(writer, out, entry, transform)
                    })?;
                }
                BlendMap::Blocks(blocks) => {
                    for (i, block) in blocks.iter().enumerate() {
                        if i > 0 {
                            out.push(',');
                        }
                        out.push_str(" texture {");
                        write_texture_entry(writer, out, block, transform)?;
                        out.push_str(" }");
                    }
                }
            }
            write_pattern_modifiers(out, pattern, transform, parent);
        }
        CompoundTexture::Average(entries) => {
            out.push_str(" average");
            write_map(out, "texture_map", entries, |out, entry| {
                write_texture_entry(writer, out, entry, parent)
            })?;
        }
        CompoundTexture::MaterialMap {
            image,
            textures,
            transform,
        } => {
            out.push_str(" material_map ");
            write_image_block_open(writer, out, image, ImageRole::Material)?;
            for texture in textures {
                write_texture_layers(writer, out, texture, "texture", transform)?;
            }
            out.push_str(" }");
            out.push_str(&matrix(&relative(transform, parent)));
        }
    }
    Ok(())
}

/// A texture map entry's body (a layered entry is declared and named).
fn write_texture_entry(
    writer: &mut Writer,
    out: &mut String,
    texture: &Texture,
    parent: &Transform,
) -> Written {
    if let Some(compound) = &texture.compound {
        if let CompoundTexture::Layered(layers) = &**compound {
            // A map entry holds one texture: name the layers, with the parent undone.
            let mut text = String::new();
            for layer in layers {
                write_texture_layers(writer, &mut text, layer, "texture", parent)?;
            }
            let key = address(compound);
            let name = writer.declared(key, "Texture", |_, declaration| {
                declaration.push_str(&text);
                Ok(())
            })?;
            let _ = write!(out, " {name}");
            return Ok(());
        }
    }
    write_texture_body(writer, out, texture, parent)
}

/// ` KEYWORD { [KEY ENTRY] .. }`: a map (or an average's weights), each entry written by
/// `write`.
fn write_map<T>(
    out: &mut String,
    keyword: &str,
    entries: &[(f64, T)],
    mut write: impl FnMut(&mut String, &T) -> Written,
) -> Written {
    let _ = write!(out, " {keyword} {{");
    for (key, entry) in entries {
        let _ = write!(out, " [{}", number(*key));
        write(out, entry)?;
        out.push(']');
    }
    out.push_str(" }");
    Ok(())
}

/// `pigment { .. }` (or `density { .. }`) written relative to `parent`.
pub(crate) fn write_pigment(
    writer: &mut Writer,
    out: &mut String,
    pigment: &Pigment,
    parent: &Transform,
    role: PigmentRole,
) -> Written {
    let _ = write!(out, "{} {{", role.keyword());
    write_pigment_items(writer, out, pigment, parent, role)?;
    out.push_str(" }");
    Ok(())
}

fn write_pigment_items(
    writer: &mut Writer,
    out: &mut String,
    pigment: &Pigment,
    parent: &Transform,
    role: PigmentRole,
) -> Written {
    match pigment {
        Pigment::Solid(c) => {
            let _ = write!(out, " {}", colour(c));
        }
        Pigment::Pattern {
            pattern,
            map,
            transform,
        } => {
            out.push(' ');
            write_pattern_kind(writer, out, pattern)?;
            match map {
                PigmentMap::Colours(entries) => {
                    if !entries.is_empty() {
                        write_map(out, "color_map", entries, |out, c| {
                            let _ = write!(out, " {}", colour(c));
                            Ok(())
                        })?;
                    }
                }
                PigmentMap::Blocks(blocks) => {
                    for (i, block) in blocks.iter().enumerate() {
                        out.push_str(if i > 0 { ", " } else { " " });
                        write_pigment(writer, out, block, transform, role)?;
                    }
                }
                PigmentMap::Pigments(entries) => {
                    write_map(out, role.map_keyword(), entries, |out, entry| {
                        write_pigment_items(writer, out, entry, transform, role)
                    })?;
                }
            }
            write_pattern_modifiers(out, pattern, transform, parent);
        }
        Pigment::Average {
            entries,
            transform,
            warps,
        } => {
            out.push_str(" average");
            write_map(out, role.map_keyword(), entries, |out, entry| {
                write_pigment_items(writer, out, entry, transform, role)
            })?;
            write_warps_and_transform(out, warps.as_deref(), transform, parent);
        }
        Pigment::Image {
            image,
            transform,
            warps,
        } => {
            out.push_str(" image_map ");
            write_image_block(writer, out, image, ImageRole::Pigment)?;
            write_warps_and_transform(out, warps.as_deref(), transform, parent);
        }
        Pigment::UvMapped(inner) => {
            out.push_str(" uv_mapping");
            write_pigment_items(writer, out, inner, &Transform::IDENTITY, role)?;
        }
    }
    Ok(())
}

/// The warps an image or average pigment holds (in a pattern of its own), then its
/// transformation.
fn write_warps_and_transform(
    out: &mut String,
    warps: Option<&crate::texture::pattern::Pattern>,
    transform: &Transform,
    parent: &Transform,
) {
    match warps {
        Some(pattern) => write_pattern_modifiers(out, pattern, transform, parent),
        None => out.push_str(&matrix(&relative(transform, parent))),
    }
}

/// `{ FORMAT "file" .. }` of an image map, bump map, image pattern.
pub(crate) fn write_image_block(
    writer: &mut Writer,
    out: &mut String,
    image: &ImageMap,
    role: ImageRole,
) -> Written {
    write_image_block_open(writer, out, image, role)?;
    out.push_str(" }");
    Ok(())
}

/// The image block without its closing brace (a material map adds its textures).
fn write_image_block_open(
    writer: &mut Writer,
    out: &mut String,
    image: &ImageMap,
    role: ImageRole,
) -> Written {
    let Some(file) = &image.file else {
        return Err(Unsupported("an image made in memory".into()));
    };
    let _ = write!(out, "{{ {}", writer.image_file(file.format, &file.path));
    match file.gamma {
        None => {}
        Some(ImageGamma::Linear) => out.push_str(" gamma 1"),
        Some(ImageGamma::Srgb) => out.push_str(" gamma srgb"),
        Some(ImageGamma::Power(g)) => {
            let _ = write!(out, " gamma {}", number(g));
        }
    }
    let map_type = match image.projection {
        ImageProjection::Planar => 0,
        ImageProjection::Spherical => 1,
        ImageProjection::Cylindrical => 2,
        ImageProjection::Torus => 5,
    };
    if map_type != 0 {
        let _ = write!(out, " map_type {map_type}");
    }
    if image.once {
        out.push_str(" once");
    }
    if image.interpolation != 0 {
        let _ = write!(out, " interpolate {}", image.interpolation);
    }
    if role == ImageRole::Pigment {
        if image.filter_all != 0.0 {
            let _ = write!(out, " filter all {}", number(image.filter_all));
        }
        if image.transmit_all != 0.0 {
            let _ = write!(out, " transmit all {}", number(image.transmit_all));
        }
        for (index, amount) in &image.palette_filter {
            let _ = write!(out, " filter {index}, {}", number(*amount));
        }
        for (index, amount) in &image.palette_transmit {
            let _ = write!(out, " transmit {index}, {}", number(*amount));
        }
    }
    if image.use_alpha {
        out.push_str(" use_alpha");
    }
    if image.use_index {
        out.push_str(" use_index");
    }
    Ok(())
}

/// `normal { .. }` written relative to `parent`.
pub(crate) fn write_normal(
    writer: &mut Writer,
    out: &mut String,
    normal: &Normal,
    parent: &Transform,
) -> Written {
    out.push_str("normal {");
    write_normal_items(writer, out, normal, parent)?;
    out.push_str(" }");
    Ok(())
}

fn write_normal_items(
    writer: &mut Writer,
    out: &mut String,
    normal: &Normal,
    parent: &Transform,
) -> Written {
    let parent = if normal.uv_mapped {
        out.push_str(" uv_mapping");
        Transform::IDENTITY
    } else {
        *parent
    };
    let transform = &normal.transform;
    match &normal.source {
        NormalSource::Pattern { pattern, slope_map } => {
            out.push(' ');
            write_pattern_kind(writer, out, pattern)?;
            let _ = write!(out, " bump_size {}", number(normal.amount));
            if let Some(entries) = slope_map {
                out.push_str(" slope_map {");
                for entry in entries {
                    let _ = write!(
                        out,
                        " [{} <{}, {}>]",
                        number(entry.key),
                        number(entry.height),
                        number(entry.slope)
                    );
                }
                out.push_str(" }");
            }
            write_pattern_modifiers(out, pattern, transform, &parent);
        }
        NormalSource::Map { pattern, map } => {
            out.push(' ');
            write_pattern_kind(writer, out, pattern)?;
            match map {
                BlendMap::Entries(entries) => {
                    write_map(out, "normal_map", entries, |out, entry| {
                        write_normal_items(writer, out, entry, transform)
                    })?;
                }
                BlendMap::Blocks(blocks) => {
                    for (i, block) in blocks.iter().enumerate() {
                        out.push_str(if i > 0 { ", " } else { " " });
                        write_normal(writer, out, block, transform)?;
                    }
                }
            }
            write_pattern_modifiers(out, pattern, transform, &parent);
        }
        NormalSource::Average(entries) => {
            out.push_str(" average");
            write_map(out, "normal_map", entries, |out, entry| {
                write_normal_items(writer, out, entry, transform)
            })?;
            out.push_str(&matrix(&relative(transform, &parent)));
        }
        NormalSource::BumpMap(image) => {
            out.push_str(" bump_map ");
            write_image_block(writer, out, image, ImageRole::Bump)?;
            let _ = write!(out, " bump_size {}", number(normal.amount));
            out.push_str(&matrix(&relative(transform, &parent)));
        }
    }
    if normal.accuracy != 0.02 {
        let _ = write!(out, " accuracy {}", number(normal.accuracy));
    }
    if normal.no_bump_scale {
        out.push_str(" no_bump_scale");
    }
    Ok(())
}

/// ` finish { .. }` with the items that differ from POV-Ray's defaults (nothing when none
/// does).
fn write_finish(out: &mut String, finish: &Finish) {
    let d = Finish::default();
    let mut items = String::new();
    if finish.ambient != d.ambient {
        let _ = write!(items, " ambient {}", rgb(finish.ambient));
    }
    if finish.emission != d.emission {
        let _ = write!(items, " emission {}", rgb(finish.emission));
    }
    if finish.diffuse != d.diffuse || finish.diffuse_back != d.diffuse_back {
        let _ = write!(items, " diffuse {}", number(finish.diffuse));
        if finish.diffuse_back != d.diffuse_back {
            let _ = write!(items, ", {}", number(finish.diffuse_back));
        }
    }
    for (value, default, word) in [
        (finish.brilliance, d.brilliance, "brilliance"),
        (finish.crand, d.crand, "crand"),
        (finish.phong, d.phong, "phong"),
        (finish.phong_size, d.phong_size, "phong_size"),
        (finish.specular, d.specular, "specular"),
        (finish.roughness, d.roughness, "roughness"),
        (finish.metallic, d.metallic, "metallic"),
    ] {
        if value != default {
            let _ = write!(items, " {word} {}", number(value));
        }
    }
    let reflection_given = finish.reflection != d.reflection
        || finish.reflection_min.is_some()
        || finish.fresnel
        || finish.reflection_falloff != d.reflection_falloff
        || finish.reflection_exponent != d.reflection_exponent
        || finish.reflect_metallic != d.reflect_metallic;
    if reflection_given {
        items.push_str(" reflection {");
        if let Some(min) = finish.reflection_min {
            let _ = write!(items, " {},", rgb(min));
        }
        let _ = write!(
            items,
            " {} fresnel {} falloff {} exponent {} metallic {} }}",
            rgb(finish.reflection),
            on_off(finish.fresnel),
            number(finish.reflection_falloff),
            number(finish.reflection_exponent),
            number(finish.reflect_metallic)
        );
    }
    if finish.conserve_energy {
        items.push_str(" conserve_energy");
    }
    if let Some(irid) = &finish.irid {
        let _ = write!(
            items,
            " irid {{ {} thickness {} turbulence {} }}",
            number(irid.amount),
            number(irid.thickness),
            number(irid.turbulence)
        );
    }
    if let Some(sub) = &finish.subsurface {
        let _ = write!(
            items,
            " subsurface {{ translucency {}",
            rgb(sub.translucency)
        );
        if sub.anisotropy != glam::DVec3::ZERO {
            let _ = write!(items, " anisotropy {}", rgb(sub.anisotropy));
        }
        items.push_str(" }");
    }
    if !items.is_empty() {
        let _ = write!(out, " finish {{{items} }}");
    }
}

/// ` interior { .. }`.
pub(super) fn write_interior(
    writer: &mut Writer,
    out: &mut String,
    interior: &Interior,
) -> Written {
    let d = Interior::default();
    out.push_str(" interior {");
    let _ = write!(out, " ior {}", number(interior.ior));
    if interior.dispersion != d.dispersion {
        let _ = write!(out, " dispersion {}", number(interior.dispersion));
    }
    if interior.dispersion_samples != d.dispersion_samples {
        let _ = write!(out, " dispersion_samples {}", interior.dispersion_samples);
    }
    if interior.fade_distance != d.fade_distance || interior.fade_power != d.fade_power {
        let _ = write!(
            out,
            " fade_distance {} fade_power {}",
            number(interior.fade_distance),
            number(interior.fade_power)
        );
    }
    if interior.fade_colour != d.fade_colour {
        let _ = write!(out, " fade_colour {}", rgb(interior.fade_colour));
    }
    if interior.caustics != d.caustics {
        let _ = write!(out, " caustics {}", number(interior.caustics));
    }
    for media in &interior.media {
        out.push(' ');
        write_media(writer, out, media, &Transform::IDENTITY)?;
    }
    out.push_str(" }");
    Ok(())
}

/// `media { .. }`.
pub(crate) fn write_media(
    writer: &mut Writer,
    out: &mut String,
    media: &Media,
    parent: &Transform,
) -> Written {
    let d = Media::default();
    let _ = write!(
        out,
        "media {{ method {} intervals {} samples {}, {} confidence {} variance {} ratio {} \
         jitter {} aa_threshold {} aa_level {}",
        media.method,
        media.intervals,
        media.samples.0,
        media.samples.1,
        number(media.confidence),
        number(media.variance),
        number(media.ratio),
        number(media.jitter),
        number(media.aa_threshold),
        media.aa_level
    );
    if media.absorption != d.absorption {
        let _ = write!(out, " absorption {}", rgb(media.absorption));
    }
    if media.emission != d.emission {
        let _ = write!(out, " emission {}", rgb(media.emission));
    }
    if let Some(scattering) = &media.scattering {
        let _ = write!(
            out,
            " scattering {{ {}, {} extinction {}",
            scattering_number(&scattering.kind),
            rgb(scattering.colour),
            number(scattering.extinction)
        );
        if let ScatteringKind::HenyeyGreenstein(g) = scattering.kind {
            let _ = write!(out, " eccentricity {}", number(g));
        }
        out.push_str(" }");
    }
    for density in &media.densities {
        out.push(' ');
        write_pigment(writer, out, density, parent, PigmentRole::Density)?;
    }
    out.push_str(" }");
    let _ = vector;
    Ok(())
}

fn scattering_number(kind: &ScatteringKind) -> u32 {
    match kind {
        ScatteringKind::Isotropic => 1,
        ScatteringKind::MieHazy => 2,
        ScatteringKind::MieMurky => 3,
        ScatteringKind::Rayleigh => 4,
        ScatteringKind::HenyeyGreenstein(_) => 5,
    }
}
