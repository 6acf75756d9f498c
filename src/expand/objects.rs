//! Objects: every shape, CSG, light groups, and the object modifiers.

use super::appearance::{write_interior, write_texture_items};
use super::functions::write_function_block;
use super::{address, matrix, number, on_off, rgb, vector, vector2, Unsupported, Writer, Written};
use crate::scene::{
    BlobKind, Container, CsgOperation, Extrusion, HeightFieldSource, JuliaAlgebra, JuliaFunction,
    LightSource, Mesh, Object, OutlineSpline, Shape, SweepSpline, FLAT_FACE,
};
use std::fmt::Write as _;
use std::sync::Arc;

/// Writes one object: its shape, then its modifiers, then its transformation (textures,
/// interiors and clipping objects are held in the object's own space, so they come first
/// and the transformation carries them along).
pub(super) fn write_object(writer: &mut Writer, out: &mut String, object: &Object) -> Written {
    if let Some(group) = &object.light_group {
        let Shape::Csg { children, .. } = &object.shape else {
            return Err(Unsupported("a light_group that is not a union".into()));
        };
        out.push_str("object { light_group {\n");
        for light in object.lights.iter().flat_map(|lights| lights.iter()) {
            write_light(writer, out, light)?;
        }
        for child in children {
            write_object(writer, out, child)?;
            out.push('\n');
        }
        let _ = write!(out, " global_lights {} }}", on_off(group.global_lights));
        write_modifiers(writer, out, object)?;
        out.push_str(" }");
        return Ok(());
    }
    write_shape(writer, out, &object.shape)?;
    write_modifiers(writer, out, object)?;
    out.push_str(" }");
    Ok(())
}

/// The object modifiers and the transformation, without the closing brace.
fn write_modifiers(writer: &mut Writer, out: &mut String, object: &Object) -> Written {
    if let Some(texture) = &object.texture {
        write_texture_items(writer, out, texture, "texture")?;
    }
    if let Some(texture) = &object.interior_texture {
        write_texture_items(writer, out, texture, "interior_texture")?;
    }
    if let Some(interior) = &object.interior {
        write_interior(writer, out, interior)?;
    }
    for (list, word) in [
        (&object.clipped_by, "clipped_by"),
        (&object.bounded_by, "bounded_by"),
    ] {
        if list.is_empty() {
            continue;
        }
        let _ = write!(out, " {word} {{ ");
        for part in list {
            write_object(writer, out, part)?;
            out.push(' ');
        }
        out.push('}');
    }
    for (on, word) in [
        (object.inverse, "inverse"),
        (object.no_shadow, "no_shadow"),
        (object.no_image, "no_image"),
        (object.no_reflection, "no_reflection"),
        (object.no_radiosity, "no_radiosity"),
        (object.double_illuminate, "double_illuminate"),
    ] {
        if on {
            let _ = write!(out, " {word}");
        }
    }
    if let Some(hollow) = object.hollow {
        let _ = write!(out, " hollow {}", on_off(hollow));
    }
    let photons = &object.photons;
    let given = photons.given();
    if given.any() {
        out.push_str(" photons {");
        if given.target {
            if let Some(multiplier) = photons.target() {
                let _ = write!(out, " target {}", number(multiplier));
            }
        }
        for (is_given, on, word) in [
            (given.refraction, photons.refraction(), "refraction"),
            (given.reflection, photons.reflection(), "reflection"),
            (given.collect, photons.collect(), "collect"),
        ] {
            if is_given {
                let _ = write!(out, " {word} {}", on_off(on));
            }
        }
        if given.pass_through && photons.pass_through() {
            out.push_str(" pass_through");
        }
        out.push_str(" }");
    }
    out.push_str(&matrix(object.transform()));
    Ok(())
}

/// The shape's keyword and items, leaving its block open.
fn write_shape(writer: &mut Writer, out: &mut String, shape: &Shape) -> Written {
    match shape {
        Shape::Sphere { centre, radius } => {
            let _ = write!(out, "sphere {{ {}, {}", vector(*centre), number(*radius));
        }
        Shape::Box { corner1, corner2 } => {
            let _ = write!(out, "box {{ {}, {}", vector(*corner1), vector(*corner2));
        }
        Shape::Plane { normal, distance } => {
            let _ = write!(out, "plane {{ {}, {}", vector(*normal), number(*distance));
        }
        Shape::Cylinder {
            base,
            cap,
            radius,
            open,
        } => {
            let _ = write!(
                out,
                "cylinder {{ {}, {}, {}{}",
                vector(*base),
                vector(*cap),
                number(*radius),
                if *open { " open" } else { "" }
            );
        }
        Shape::Cone {
            base,
            base_radius,
            cap,
            cap_radius,
            open,
        } => {
            let _ = write!(
                out,
                "cone {{ {}, {}, {}, {}{}",
                vector(*base),
                number(*base_radius),
                vector(*cap),
                number(*cap_radius),
                if *open { " open" } else { "" }
            );
        }
        Shape::Torus { major, minor } => {
            let _ = write!(out, "torus {{ {}, {}", number(*major), number(*minor));
        }
        Shape::Disc {
            centre,
            normal,
            radius,
            hole_radius,
        } => {
            let _ = write!(
                out,
                "disc {{ {}, {}, {}, {}",
                vector(*centre),
                vector(*normal),
                number(*radius),
                number(*hole_radius)
            );
        }
        Shape::Quadric { coefficients: c } => {
            let _ = write!(
                out,
                "quadric {{ <{}, {}, {}>, <{}, {}, {}>, <{}, {}, {}>, {}",
                number(c[0]),
                number(c[1]),
                number(c[2]),
                number(c[3]),
                number(c[4]),
                number(c[5]),
                number(c[6]),
                number(c[7]),
                number(c[8]),
                number(c[9])
            );
        }
        Shape::Triangle { corners: c } => {
            let _ = write!(
                out,
                "triangle {{ {}, {}, {}",
                vector(c[0]),
                vector(c[1]),
                vector(c[2])
            );
        }
        Shape::SmoothTriangle {
            corners: c,
            normals: n,
        } => {
            let _ = write!(
                out,
                "smooth_triangle {{ {}, {}, {}, {}, {}, {}",
                vector(c[0]),
                vector(n[0]),
                vector(c[1]),
                vector(n[1]),
                vector(c[2]),
                vector(n[2])
            );
        }
        Shape::Polygon(polygon) => {
            let count: usize = polygon.outlines.iter().map(|o| o.len() + 1).sum();
            let _ = write!(out, "polygon {{ {count}");
            for outline in &polygon.outlines {
                for point in outline.iter().chain(outline.first()) {
                    let _ = write!(out, ", {}", vector(*point));
                }
            }
        }
        Shape::Mesh(mesh) => {
            let name = if Arc::strong_count(mesh) > 1 {
                Some(writer.declared(address(mesh), "Mesh", |writer, text| {
                    write_mesh(writer, text, mesh)?;
                    text.push_str(" }");
                    Ok(())
                })?)
            } else {
                None
            };
            match name {
                Some(name) => {
                    let _ = write!(out, "object {{ {name}");
                }
                None => write_mesh(writer, out, mesh)?,
            }
        }
        Shape::Poly(poly) => {
            let list: Vec<String> = poly.coefficients.iter().map(|c| number(*c)).collect();
            let _ = write!(
                out,
                "poly {{ {}, <{}>{}",
                poly.order,
                list.join(", "),
                if poly.sturm { " sturm" } else { "" }
            );
        }
        Shape::Text(glyphs) => {
            // Each glyph is an outline in the XY plane extruded along Z: a prism (outline in
            // XZ, swept along Y) with its Y and Z axes swapped.
            out.push_str("union {");
            for glyph in glyphs.iter() {
                out.push(' ');
                write_prism(out, glyph);
                out.push_str(" matrix <1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0> }");
            }
        }
        Shape::Prism(extrusion) => write_prism(out, extrusion),
        Shape::Blob(blob) => {
            let _ = write!(out, "blob {{ threshold {}", number(blob.threshold));
            for component in &blob.components {
                match component.kind {
                    BlobKind::Sphere { centre } => {
                        let _ = write!(
                            out,
                            " sphere {{ {}, {}, strength {}",
                            vector(centre),
                            number(component.radius),
                            number(component.strength)
                        );
                    }
                    BlobKind::Cylinder { end1, end2 } => {
                        let _ = write!(
                            out,
                            " cylinder {{ {}, {}, {}, strength {}",
                            vector(end1),
                            vector(end2),
                            number(component.radius),
                            number(component.strength)
                        );
                    }
                }
                if let Some(texture) = &component.texture {
                    // Held in the blob's space: undo the component's own placement, which
                    // is written after it.
                    let mut local = crate::texture::Texture::clone(texture);
                    local.transform(&component.transform.inverse());
                    write_texture_items(writer, out, &Arc::new(local), "texture")?;
                }
                out.push_str(&matrix(&component.transform));
                out.push_str(" }");
            }
        }
        Shape::Superellipsoid {
            east_west,
            north_south,
        } => {
            let _ = write!(
                out,
                "superellipsoid {{ <{}, {}>",
                number(*east_west),
                number(*north_south)
            );
        }
        Shape::Sor { points, open } => {
            let _ = write!(out, "sor {{ {}", points.len());
            for point in points.iter() {
                let _ = write!(out, ", {}", vector2(*point));
            }
            if *open {
                out.push_str(" open");
            }
        }
        Shape::Lathe { segments, source } => match source {
            // The points as written: a cubic spline's Bézier controls may have negative
            // radii, which POV-Ray refuses in a lathe.
            Some(outline) => {
                let spline = match outline.spline {
                    OutlineSpline::Linear => "linear_spline",
                    OutlineSpline::Quadratic => "quadratic_spline",
                    OutlineSpline::Cubic => "cubic_spline",
                    OutlineSpline::Bezier => "bezier_spline",
                };
                let _ = write!(out, "lathe {{ {spline} {}", outline.points.len());
                for point in &outline.points {
                    let _ = write!(out, ", {}", vector2(*point));
                }
            }
            None => {
                let _ = write!(out, "lathe {{ bezier_spline {}", segments.len() * 4);
                for segment in segments.iter() {
                    for point in segment {
                        let _ = write!(out, ", {}", vector2(*point));
                    }
                }
            }
        },
        Shape::Isosurface(iso) => {
            out.push_str("isosurface { ");
            write_function_block(writer, out, &iso.function, &["x", "y", "z"])?;
            out.push_str(" contained_by { ");
            write_container(out, &iso.container);
            let _ = write!(
                out,
                " }} threshold {} accuracy {} max_gradient {}",
                number(iso.threshold),
                number(iso.accuracy),
                number(iso.max_gradient)
            );
            // `all_intersections` is durer's largest count: the same number reads back.
            let _ = write!(out, " max_trace {}", iso.max_trace);
            if iso.open {
                out.push_str(" open");
            }
        }
        Shape::HeightField(field) => {
            match &field.source {
                Some(HeightFieldSource::Image { path, format }) => {
                    let _ = write!(out, "height_field {{ {}", writer.image_file(*format, path));
                }
                Some(HeightFieldSource::Function {
                    function,
                    columns,
                    rows,
                }) => {
                    let _ = write!(out, "height_field {{ function {columns}, {rows} {{ ");
                    let mut block = String::new();
                    write_function_block(writer, &mut block, function, &["x", "y", "z"])?;
                    // `function { BODY }` without its keyword and braces: the resolution
                    // sits between them.
                    let body = block
                        .strip_prefix("function { ")
                        .and_then(|rest| rest.strip_suffix(" }"))
                        .unwrap_or(&block);
                    out.push_str(body);
                    out.push_str(" }");
                }
                None => return Err(Unsupported("a height_field of unknown origin".into())),
            }
            if field.smooth {
                out.push_str(" smooth");
            }
            let _ = write!(out, " water_level {}", number(field.water_level));
        }
        Shape::SphereSweep(sweep) => {
            let kind = match sweep.spline {
                SweepSpline::Linear => "linear_spline",
                SweepSpline::BSpline => "b_spline",
                SweepSpline::Cubic => "cubic_spline",
            };
            let _ = write!(out, "sphere_sweep {{ {kind} {}", sweep.spheres.len());
            for (centre, radius) in &sweep.spheres {
                let _ = write!(out, ", {}, {}", vector(*centre), number(*radius));
            }
            let _ = write!(out, " tolerance {}", number(sweep.tolerance));
        }
        Shape::JuliaFractal(julia) => {
            let p = julia.parameter;
            let _ = write!(
                out,
                "julia_fractal {{ <{}, {}, {}, {}> {} ",
                number(p.x),
                number(p.y),
                number(p.z),
                number(p.w),
                match julia.algebra {
                    JuliaAlgebra::Quaternion => "quaternion",
                    JuliaAlgebra::Hypercomplex => "hypercomplex",
                }
            );
            out.push_str(&julia_function(&julia.function));
            let n = julia.slice_normal;
            let _ = write!(
                out,
                " max_iteration {} precision {} slice <{}, {}, {}, {}>, {}",
                julia.max_iteration,
                number(julia.precision),
                number(n.x),
                number(n.y),
                number(n.z),
                number(n.w),
                number(julia.slice_distance)
            );
        }
        Shape::Ovus {
            bottom_radius,
            top_radius,
        } => {
            let _ = write!(
                out,
                "ovus {{ {}, {}",
                number(*bottom_radius),
                number(*top_radius)
            );
        }
        Shape::Lemon(lemon) => {
            let _ = write!(
                out,
                "lemon {{ {}, {}, {}, {}, {}{}",
                vector(lemon.base),
                number(lemon.base_radius),
                vector(lemon.cap),
                number(lemon.cap_radius),
                number(lemon.inner_radius),
                if lemon.open { " open" } else { "" }
            );
        }
        Shape::Parametric(parametric) => {
            out.push_str("parametric {");
            for function in &parametric.functions {
                out.push(' ');
                write_function_block(writer, out, function, &["u", "v"])?;
            }
            let _ = write!(
                out,
                " {}, {} contained_by {{ ",
                vector2(parametric.uv_corner1),
                vector2(parametric.uv_corner2)
            );
            write_container(out, &parametric.container);
            let _ = write!(
                out,
                " }} max_gradient {} accuracy {}",
                number(parametric.max_gradient),
                number(parametric.accuracy)
            );
        }
        Shape::Csg {
            operation,
            children,
        } => {
            let word = match operation {
                CsgOperation::Union => "union",
                CsgOperation::Intersection => "intersection",
                CsgOperation::Difference => "difference",
                CsgOperation::Merge => "merge",
            };
            let _ = writeln!(out, "{word} {{");
            for child in children {
                write_object(writer, out, child)?;
                out.push('\n');
            }
        }
    }
    Ok(())
}

fn write_container(out: &mut String, container: &Container) {
    match container {
        Container::Box { corner1, corner2 } => {
            let _ = write!(out, "box {{ {}, {} }}", vector(*corner1), vector(*corner2));
        }
        Container::Sphere { centre, radius } => {
            let _ = write!(out, "sphere {{ {}, {} }}", vector(*centre), number(*radius));
        }
    }
}

fn julia_function(function: &JuliaFunction) -> String {
    let word = match function {
        JuliaFunction::Sqr => "sqr",
        JuliaFunction::Cube => "cube",
        JuliaFunction::Exp => "exp",
        JuliaFunction::Reciprocal => "reciprocal",
        JuliaFunction::Sin => "sin",
        JuliaFunction::Asin => "asin",
        JuliaFunction::Sinh => "sinh",
        JuliaFunction::Asinh => "asinh",
        JuliaFunction::Cos => "cos",
        JuliaFunction::Acos => "acos",
        JuliaFunction::Cosh => "cosh",
        JuliaFunction::Acosh => "acosh",
        JuliaFunction::Tan => "tan",
        JuliaFunction::Atan => "atan",
        JuliaFunction::Tanh => "tanh",
        JuliaFunction::Atanh => "atanh",
        JuliaFunction::Ln => "ln",
        JuliaFunction::Power(p) => return format!("pwr({}, {})", number(p.x), number(p.y)),
    };
    word.to_string()
}

/// A prism of Bézier segments (the extrusion's X and Y are the prism's X and Z; its depth
/// is the prism's Y extent), leaving the block open.
fn write_prism(out: &mut String, extrusion: &Extrusion) {
    let _ = write!(
        out,
        "prism {{ {} bezier_spline {}, {}, {}",
        if extrusion.conic {
            "conic_sweep"
        } else {
            "linear_sweep"
        },
        number(extrusion.depth.0),
        number(extrusion.depth.1),
        extrusion.segments.len() * 4
    );
    for segment in &extrusion.segments {
        for point in segment {
            let _ = write!(out, ", {}", vector2(*point));
        }
    }
    if extrusion.open {
        out.push_str(" open");
    }
}

/// A mesh as `mesh2`, leaving the block open. Smooth meshes that also hold flat faces are
/// written as `mesh` of single triangles (mesh2 cannot mix them).
fn write_mesh(writer: &mut Writer, out: &mut String, mesh: &Mesh) -> Written {
    let mixed = !mesh.face_normals.is_empty()
        && mesh.face_normals.iter().any(|n| n[0] == FLAT_FACE)
        && mesh.face_normals.iter().any(|n| n[0] != FLAT_FACE);
    if mixed {
        return write_mesh_of_triangles(writer, out, mesh);
    }
    out.push_str("mesh2 {\n vertex_vectors { ");
    let _ = write!(out, "{}", mesh.vertices.len());
    for v in &mesh.vertices {
        let _ = write!(out, ", {}", vector(*v));
    }
    out.push_str(" }\n");
    let smooth = !mesh.face_normals.is_empty() && mesh.face_normals[0][0] != FLAT_FACE;
    if smooth {
        let _ = write!(out, " normal_vectors {{ {}", mesh.normals.len());
        for n in &mesh.normals {
            let _ = write!(out, ", {}", vector(*n));
        }
        out.push_str(" }\n");
    }
    if !mesh.face_uvs.is_empty() {
        let _ = write!(out, " uv_vectors {{ {}", mesh.uvs.len());
        for uv in &mesh.uvs {
            let _ = write!(out, ", {}", vector2(*uv));
        }
        out.push_str(" }\n");
    }
    if !mesh.textures.is_empty() {
        let _ = write!(out, " texture_list {{ {}", mesh.textures.len());
        for texture in &mesh.textures {
            write_texture_items(writer, out, texture, "texture")?;
        }
        out.push_str(" }\n");
    }
    let _ = write!(out, " face_indices {{ {}", mesh.faces.len());
    for (index, face) in mesh.faces.iter().enumerate() {
        let _ = write!(out, ", <{}, {}, {}>", face[0], face[1], face[2]);
        if let Some(slots) = mesh.face_textures.get(index) {
            match slots {
                [0, 0, 0] => {}
                [a, b, c] if a == b && b == c => {
                    let _ = write!(out, ", {}", a - 1);
                }
                [a, b, c] if *a > 0 && *b > 0 && *c > 0 => {
                    let _ = write!(out, ", {}, {}, {}", a - 1, b - 1, c - 1);
                }
                _ => {
                    return Err(Unsupported(
                        "a mesh face blending its own texture with the mesh's".into(),
                    ))
                }
            }
        }
    }
    out.push_str(" }\n");
    for (list, word, wanted) in [
        (&mesh.face_normals, "normal_indices", smooth),
        (&mesh.face_uvs, "uv_indices", true),
    ] {
        if !wanted || list.is_empty() {
            continue;
        }
        let _ = write!(out, " {word} {{ {}", list.len());
        for face in list.iter() {
            let _ = write!(out, ", <{}, {}, {}>", face[0], face[1], face[2]);
        }
        out.push_str(" }\n");
    }
    if let Some(inside) = mesh.inside_vector {
        let _ = write!(out, " inside_vector {}", vector(inside));
    }
    Ok(())
}

fn write_mesh_of_triangles(writer: &mut Writer, out: &mut String, mesh: &Mesh) -> Written {
    out.push_str("mesh {\n");
    for (index, face) in mesh.faces.iter().enumerate() {
        let corner = |k: usize| vector(mesh.vertices[face[k] as usize]);
        let normals = mesh.face_normals[index];
        if normals[0] == FLAT_FACE {
            let _ = write!(
                out,
                " triangle {{ {}, {}, {}",
                corner(0),
                corner(1),
                corner(2)
            );
        } else {
            let normal = |k: usize| vector(mesh.normals[normals[k] as usize]);
            let _ = write!(
                out,
                " smooth_triangle {{ {}, {}, {}, {}, {}, {}",
                corner(0),
                normal(0),
                corner(1),
                normal(1),
                corner(2),
                normal(2)
            );
        }
        if let Some(uvs) = mesh.face_uvs.get(index) {
            let _ = write!(
                out,
                " uv_vectors {}, {}, {}",
                vector2(mesh.uvs[uvs[0] as usize]),
                vector2(mesh.uvs[uvs[1] as usize]),
                vector2(mesh.uvs[uvs[2] as usize])
            );
        }
        if let Some(slots) = mesh.face_textures.get(index) {
            match slots {
                [0, 0, 0] => {}
                [a, b, c] if a == b && b == c => {
                    let texture = Arc::clone(&mesh.textures[*a as usize - 1]);
                    write_texture_items(writer, out, &texture, "texture")?;
                }
                _ => {
                    return Err(Unsupported(
                        "a mesh triangle with a texture per corner".into(),
                    ))
                }
            }
        }
        out.push_str(" }\n");
    }
    if let Some(inside) = mesh.inside_vector {
        let _ = write!(out, " inside_vector {}", vector(inside));
    }
    Ok(())
}

pub(super) fn write_light(writer: &mut Writer, out: &mut String, light: &LightSource) -> Written {
    let _ = write!(
        out,
        "light_source {{ {}, {}",
        vector(light.position),
        rgb(light.colour)
    );
    if let Some(spot) = &light.spotlight {
        let _ = write!(
            out,
            " {} point_at {} radius {} falloff {} tightness {}",
            if spot.cylinder {
                "cylinder"
            } else {
                "spotlight"
            },
            vector(spot.point_at),
            number(spot.radius),
            number(spot.falloff),
            number(spot.tightness)
        );
    }
    if let Some(target) = light.parallel {
        out.push_str(" parallel");
        if light.spotlight.is_none() {
            let _ = write!(out, " point_at {}", vector(target));
        }
    }
    if let Some(area) = &light.area {
        let _ = write!(
            out,
            " area_light {}, {}, {}, {}",
            vector(area.axis1),
            vector(area.axis2),
            area.size1,
            area.size2
        );
        if let Some(adaptive) = area.adaptive {
            let _ = write!(out, " adaptive {adaptive}");
        }
        for (on, word) in [
            (area.jitter, "jitter"),
            (area.circular, "circular"),
            (area.orient, "orient"),
        ] {
            if on {
                let _ = write!(out, " {word}");
            }
        }
        let _ = write!(out, " area_illumination {}", on_off(area.area_illumination));
    }
    if light.shadowless {
        out.push_str(" shadowless");
    }
    if light.fade_distance != 0.0 || light.fade_power != 0.0 {
        let _ = write!(
            out,
            " fade_distance {} fade_power {}",
            number(light.fade_distance),
            number(light.fade_power)
        );
    }
    let _ = write!(
        out,
        " media_interaction {} media_attenuation {}",
        on_off(light.media_interaction),
        on_off(light.media_attenuation)
    );
    let photons = &light.photons;
    if photons.refraction_given || photons.reflection_given {
        out.push_str(" photons {");
        if photons.refraction_given {
            let _ = write!(out, " refraction {}", on_off(photons.refraction));
        }
        if photons.reflection_given {
            let _ = write!(out, " reflection {}", on_off(photons.reflection));
        }
        out.push_str(" }");
    }
    if let Some(object) = &light.projected_through {
        out.push_str(" projected_through { ");
        write_object(writer, out, object)?;
        out.push_str(" }");
    }
    // `looks_like` is not written: evaluation already placed its object in the scene.
    out.push_str(" }\n");
    Ok(())
}
