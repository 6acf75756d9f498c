//! Leaf primitives: one shape placed in the world with its material.
//!
//! In: a [`Shape`] (not CSG), the object's world-from-local transform, a material index
//! and the inverse flag. Out: a compact [`Leaf`] answering ray intersections, inside tests and
//! hit details (world-space outward normal, uv coordinates, a mesh triangle's corner blend),
//! plus its world bounds.
//! Holds: transforms that a shape can absorb (any affine map for planes and triangles, a
//! similarity for spheres, an axis scaling plus translation for boxes) are baked into the shape
//! at build time; otherwise the leaf keeps only the world-to-local map. A degenerate shape or
//! a singular or non-finite transform gives an empty leaf that nothing hits.

use super::blob::Blob;
use super::cuboid::Cuboid;
use super::extrusion::ExtrudedOutline;
use super::flat::{Disc, Plane, Triangle};
use super::height_field::HeightField;
use super::isosurface::Isosurface;
use super::julia::JuliaFractal;
use super::lathe::Lathe;
use super::parametric::ParametricSurface;
use super::poly::PolySurface;
use super::polygon::{Polygon, SmoothTriangle};
use super::quadric::Quadric;
use super::quadric_bounds::InsideQuadric;
use super::roots::Roots;
use super::round::{Cone, Sphere};
use super::sor::Sor;
use super::sphere_sweep::SphereSweep;
use super::spindle::{Lemon, Ovus};
use super::superellipsoid::Superellipsoid;
use super::torus::{Torus, TorusShape};
use super::uv::{barycentric, box_uv, corner_weighted, sphere_uv, torus_uv};
use super::{HitDetails, Ray};
use crate::accel::Aabb;
use crate::{
    math::Transform,
    scene::{Blob as SceneBlob, Mesh, MeshTriangle, Shape},
};
use glam::{DAffine3, DVec2, DVec3};
use std::sync::Arc;

/// A shape in its own local space.
#[derive(Clone, Debug)]
pub enum LocalShape {
    /// Nothing: a degenerate shape.
    Empty,
    /// A sphere.
    Sphere(Sphere),
    /// An axis-aligned box.
    Cuboid(Cuboid),
    /// An infinite plane.
    Plane(Plane),
    /// A cylinder or cone frustum.
    Cone(Box<Cone>),
    /// A torus.
    Torus(Torus),
    /// A flat disc, possibly with a hole.
    Disc(Disc),
    /// A general quadric surface.
    Quadric(Box<Quadric>),
    /// A triangle.
    Triangle(Triangle),
    /// A triangle with interpolated normals.
    SmoothTriangle(Box<SmoothTriangle>),
    /// A mesh triangle with its corners' uv coordinates and materials.
    MeshFace(Box<MeshFace>),
    /// A polygon.
    Polygon(Box<Polygon>),
    /// A polynomial surface.
    Poly(Box<PolySurface>),
    /// An extruded outline (a text glyph or a prism).
    Extrusion(Box<ExtrudedOutline>),
    /// A surface of revolution.
    Lathe(Box<Lathe>),
    /// A blob.
    Blob(Box<Blob>),
    /// A superellipsoid.
    Superellipsoid(Superellipsoid),
    /// A surface of revolution.
    Sor(Box<Sor>),
    /// An isosurface.
    Isosurface(Box<Isosurface>),
    /// A height field.
    HeightField(Box<HeightField>),
    /// A sphere sweep.
    SphereSweep(Box<SphereSweep>),
    /// A julia fractal.
    JuliaFractal(Box<JuliaFractal>),
    /// An ovus.
    Ovus(Box<Ovus>),
    /// A lemon.
    Lemon(Box<Lemon>),
    /// A parametric surface.
    Parametric(Box<ParametricSurface>),
}

/// A triangle of a mesh (or bicubic patch) placed on its own, as in CSG: it keeps the uv
/// coordinates and materials of its corners, so uv mapping and corner texture blending work
/// as on a whole mesh.
#[derive(Clone, Debug)]
pub struct MeshFace {
    /// The triangle: [`LocalShape::Triangle`] or [`LocalShape::SmoothTriangle`].
    triangle: LocalShape,
    /// The uv coordinates of the corners.
    corner_uvs: [DVec2; 3],
    /// The material of each corner.
    corner_materials: [u32; 3],
}

impl MeshFace {
    /// The corners of the triangle.
    fn corners(&self) -> [DVec3; 3] {
        match &self.triangle {
            LocalShape::SmoothTriangle(triangle) => triangle.corners(),
            LocalShape::Triangle(triangle) => triangle.corners(),
            _ => [DVec3::ZERO; 3],
        }
    }

    /// The normal (any length) at the point with barycentric `weights`.
    fn normal_at_weights(&self, weights: [f64; 3]) -> DVec3 {
        match &self.triangle {
            LocalShape::SmoothTriangle(triangle) => triangle.normal_at_weights(weights),
            LocalShape::Triangle(triangle) => triangle.normal(),
            _ => DVec3::Z,
        }
    }
}

/// Which points count as inside a shape, beyond its surface bounds.
enum InsideReach {
    /// Inside points lie within the surface bounds.
    Bounded,
    /// Inside points may be anywhere (half-spaces, quadrics).
    Unbounded,
    /// No point is ever inside.
    Nowhere,
}

impl LocalShape {
    /// The local shape for a scene shape; CSG shapes give [`LocalShape::Empty`].
    pub fn from_scene(shape: &Shape) -> LocalShape {
        let shape = match *shape {
            Shape::Sphere { centre, radius } => Sphere::new(centre, radius).map(Self::Sphere),
            Shape::Box { corner1, corner2 } => Cuboid::new(corner1, corner2).map(Self::Cuboid),
            Shape::Plane { normal, distance } => Plane::new(normal, distance).map(Self::Plane),
            Shape::Cylinder {
                base,
                cap,
                radius,
                open,
            } => Cone::cylinder(base, cap, radius, open).map(|cone| Self::Cone(Box::new(cone))),
            Shape::Cone {
                base,
                base_radius,
                cap,
                cap_radius,
                open,
            } => Cone::new(base, base_radius, cap, cap_radius, open)
                .map(|cone| Self::Cone(Box::new(cone))),
            Shape::Torus { major, minor } => {
                Torus::from_radii(major, minor).map(|shape| match shape {
                    TorusShape::Torus(torus) => Self::Torus(torus),
                    TorusShape::Sphere(sphere) => Self::Sphere(sphere),
                })
            }
            Shape::Disc {
                centre,
                normal,
                radius,
                hole_radius,
            } => Disc::new(centre, normal, radius, hole_radius).map(Self::Disc),
            Shape::Quadric { ref coefficients } => {
                Quadric::new(**coefficients).map(|quadric| Self::Quadric(Box::new(quadric)))
            }
            Shape::Triangle { ref corners } => Triangle::new(**corners).map(Self::Triangle),
            Shape::SmoothTriangle {
                ref corners,
                ref normals,
            } => {
                SmoothTriangle::new(**corners, **normals).map(|t| Self::SmoothTriangle(Box::new(t)))
            }
            Shape::Polygon(ref polygon) => {
                Polygon::new(&polygon.outlines).map(|p| Self::Polygon(Box::new(p)))
            }
            Shape::Poly(ref poly) => {
                PolySurface::new(poly.order, &poly.coefficients).map(|p| Self::Poly(Box::new(p)))
            }
            Shape::Prism(ref prism) => {
                ExtrudedOutline::new(&prism.segments, prism.depth, prism.open, true, prism.conic)
                    .map(|p| Self::Extrusion(Box::new(p)))
            }
            Shape::Lathe { ref segments, .. } => {
                Lathe::new(segments).map(|l| Self::Lathe(Box::new(l)))
            }
            Shape::Blob(ref blob) => Blob::new(blob).map(|b| Self::Blob(Box::new(b))),
            Shape::Superellipsoid {
                east_west,
                north_south,
            } => Superellipsoid::new(east_west, north_south).map(Self::Superellipsoid),
            Shape::Sor { ref points, open } => {
                Sor::new(points, open).map(|s| Self::Sor(Box::new(s)))
            }
            Shape::Isosurface(ref spec) => {
                Isosurface::new(spec).map(|i| Self::Isosurface(Box::new(i)))
            }
            Shape::HeightField(ref spec) => {
                HeightField::new(spec).map(|h| Self::HeightField(Box::new(h)))
            }
            Shape::SphereSweep(ref spec) => {
                SphereSweep::new(spec).map(|s| Self::SphereSweep(Box::new(s)))
            }
            Shape::JuliaFractal(ref spec) => {
                JuliaFractal::new(spec).map(|j| Self::JuliaFractal(Box::new(j)))
            }
            Shape::Ovus {
                bottom_radius,
                top_radius,
            } => Ovus::new(bottom_radius, top_radius).map(|o| Self::Ovus(Box::new(o))),
            Shape::Lemon(ref spec) => Lemon::new(
                spec.base,
                spec.base_radius,
                spec.cap,
                spec.cap_radius,
                spec.inner_radius,
                spec.open,
            )
            .map(|l| Self::Lemon(Box::new(l))),
            Shape::Parametric(ref spec) => {
                ParametricSurface::new(spec).map(|p| Self::Parametric(Box::new(p)))
            }
            Shape::Mesh(_) | Shape::Text(_) | Shape::Csg { .. } => None,
        };
        shape.unwrap_or(LocalShape::Empty)
    }

    /// A blob whose components show their own textures: `materials[k]` is the material of
    /// component `k` (the blob's own for a component without a texture).
    pub fn textured_blob(blob: &SceneBlob, materials: &[u32]) -> LocalShape {
        Blob::new(blob)
            .map(|b| Self::Blob(Box::new(b.with_materials(materials))))
            .unwrap_or(LocalShape::Empty)
    }

    /// The shape of one mesh triangle.
    pub fn from_mesh_triangle(triangle: &MeshTriangle) -> LocalShape {
        let shape = match triangle.normals {
            None => Triangle::new(triangle.corners).map(Self::Triangle),
            Some(normals) => SmoothTriangle::new(triangle.corners, normals)
                .map(|t| Self::SmoothTriangle(Box::new(t))),
        };
        shape.unwrap_or(LocalShape::Empty)
    }

    /// The triangles of a mesh that are not degenerate, as [`LocalShape::MeshFace`]s, each
    /// with the material of its first corner. `slot_materials` holds the material of each
    /// texture slot (0: the mesh object's own; a missing slot falls back to it).
    pub fn mesh_pieces(mesh: &Mesh, slot_materials: &[u32]) -> Vec<(LocalShape, u32)> {
        let Some(&own) = slot_materials.first() else {
            return Vec::new();
        };
        let material = |slot: u32| slot_materials.get(slot as usize).copied().unwrap_or(own);
        (0..mesh.len())
            .filter_map(|face| {
                let triangle = Self::from_mesh_triangle(&mesh.triangle(face));
                if matches!(triangle, LocalShape::Empty) {
                    return None;
                }
                let corner_materials = mesh.corner_textures(face).map(material);
                let piece = LocalShape::MeshFace(Box::new(MeshFace {
                    triangle,
                    corner_uvs: mesh.corner_uvs(face),
                    corner_materials,
                }));
                Some((piece, corner_materials[0]))
            })
            .collect()
    }

    /// The leaf shapes a scene shape becomes: one per mesh triangle, else one.
    pub fn pieces(shape: &Shape) -> Vec<LocalShape> {
        match shape {
            Shape::Mesh(mesh) => mesh
                .triangles()
                .map(|triangle| Self::from_mesh_triangle(&triangle))
                .filter(|piece| !matches!(piece, LocalShape::Empty))
                .collect(),
            Shape::Text(glyphs) => glyphs
                .iter()
                .filter_map(|glyph| {
                    ExtrudedOutline::new(&glyph.segments, glyph.depth, glyph.open, false, false)
                })
                .map(|glyph| Self::Extrusion(Box::new(glyph)))
                .collect(),
            other => vec![Self::from_scene(other)],
        }
    }

    /// True for shapes without an inside, which `inverse` leaves unchanged (as in POV-Ray).
    pub fn has_no_inside(&self) -> bool {
        matches!(
            self,
            LocalShape::Triangle(_)
                | LocalShape::SmoothTriangle(_)
                | LocalShape::MeshFace(_)
                | LocalShape::Polygon(_)
                | LocalShape::Parametric(_)
        )
    }

    /// Pushes every crossing of the line `origin + t direction` (local space).
    #[inline]
    pub fn intersect(&self, origin: DVec3, direction: DVec3, roots: &mut Roots) {
        match self {
            LocalShape::Empty => {}
            LocalShape::Sphere(shape) => shape.intersect(origin, direction, roots),
            LocalShape::Cuboid(shape) => shape.intersect(origin, direction, roots),
            LocalShape::Plane(shape) => shape.intersect(origin, direction, roots),
            LocalShape::Cone(shape) => shape.intersect(origin, direction, roots),
            LocalShape::Torus(shape) => shape.intersect(origin, direction, roots),
            LocalShape::Disc(shape) => shape.intersect(origin, direction, roots),
            LocalShape::Quadric(shape) => shape.intersect(origin, direction, roots),
            LocalShape::Triangle(shape) => shape.intersect(origin, direction, roots),
            LocalShape::SmoothTriangle(shape) => shape.intersect(origin, direction, roots),
            LocalShape::MeshFace(face) => face.triangle.intersect(origin, direction, roots),
            LocalShape::Polygon(shape) => shape.intersect(origin, direction, roots),
            LocalShape::Poly(shape) => shape.intersect(origin, direction, roots),
            LocalShape::Extrusion(shape) => shape.intersect(origin, direction, roots),
            LocalShape::Lathe(shape) => shape.intersect(origin, direction, roots),
            LocalShape::Blob(shape) => shape.intersect(origin, direction, roots),
            LocalShape::Superellipsoid(shape) => shape.intersect(origin, direction, roots),
            LocalShape::Sor(shape) => shape.intersect(origin, direction, roots),
            LocalShape::Isosurface(shape) => shape.intersect(origin, direction, roots),
            LocalShape::HeightField(shape) => shape.intersect(origin, direction, roots),
            LocalShape::SphereSweep(shape) => shape.intersect(origin, direction, roots),
            LocalShape::JuliaFractal(shape) => shape.intersect(origin, direction, roots),
            LocalShape::Ovus(shape) => shape.intersect(origin, direction, roots),
            LocalShape::Lemon(shape) => shape.intersect(origin, direction, roots),
            LocalShape::Parametric(shape) => shape.intersect(origin, direction, roots),
        }
    }

    /// True when the local `point` is inside the shape.
    pub fn inside(&self, point: DVec3) -> bool {
        match self {
            LocalShape::Empty | LocalShape::MeshFace(_) => false,
            LocalShape::Sphere(shape) => shape.inside(point),
            LocalShape::Cuboid(shape) => shape.inside(point),
            LocalShape::Plane(shape) => shape.inside(point),
            LocalShape::Cone(shape) => shape.inside(point),
            LocalShape::Torus(shape) => shape.inside(point),
            LocalShape::Disc(shape) => shape.inside(point),
            LocalShape::Quadric(shape) => shape.inside(point),
            LocalShape::Triangle(shape) => shape.inside(point),
            LocalShape::SmoothTriangle(_) | LocalShape::Polygon(_) => false,
            LocalShape::Poly(shape) => shape.inside(point),
            LocalShape::Extrusion(shape) => shape.inside(point),
            LocalShape::Lathe(shape) => shape.inside(point),
            LocalShape::Blob(shape) => shape.inside(point),
            LocalShape::Superellipsoid(shape) => shape.inside(point),
            LocalShape::Sor(shape) => shape.inside(point),
            LocalShape::Isosurface(shape) => shape.inside(point),
            LocalShape::HeightField(shape) => shape.inside(point),
            LocalShape::SphereSweep(shape) => shape.inside(point),
            LocalShape::JuliaFractal(shape) => shape.inside(point),
            LocalShape::Ovus(shape) => shape.inside(point),
            LocalShape::Lemon(shape) => shape.inside(point),
            LocalShape::Parametric(_) => false,
        }
    }

    /// Outward normal (any length) at the local surface `point` of surface part `part`.
    pub fn normal(&self, point: DVec3, part: u8) -> DVec3 {
        match self {
            LocalShape::Empty => DVec3::Z,
            LocalShape::Sphere(shape) => shape.normal(point),
            LocalShape::Cuboid(shape) => shape.normal(part),
            LocalShape::Plane(shape) => shape.normal(),
            LocalShape::Cone(shape) => shape.normal(point, part),
            LocalShape::Torus(shape) => shape.normal(point),
            LocalShape::Disc(shape) => shape.normal(),
            LocalShape::Quadric(shape) => shape.normal(point),
            LocalShape::Triangle(shape) => shape.normal(),
            LocalShape::SmoothTriangle(shape) => shape.normal(point),
            LocalShape::MeshFace(face) => face.triangle.normal(point, part),
            LocalShape::Polygon(shape) => shape.normal(),
            LocalShape::Poly(shape) => shape.normal(point),
            LocalShape::Extrusion(shape) => shape.normal(point, part),
            LocalShape::Lathe(shape) => shape.normal(point, part),
            LocalShape::Blob(shape) => shape.normal(point),
            LocalShape::Superellipsoid(shape) => shape.normal(point),
            LocalShape::Sor(shape) => shape.normal(point, part),
            LocalShape::Isosurface(shape) => shape.normal(point, part),
            LocalShape::HeightField(shape) => shape.normal(point),
            LocalShape::SphereSweep(shape) => shape.normal(point),
            LocalShape::JuliaFractal(shape) => shape.normal(point),
            LocalShape::Ovus(shape) => shape.normal(point, part),
            LocalShape::Lemon(shape) => shape.normal(point, part),
            LocalShape::Parametric(shape) => shape.normal(point),
        }
    }

    /// The inside of an unbounded plane or quadric as a world-space inequality, for the boxes
    /// of the intersections it is part of; `None` for other shapes.
    pub fn inside_quadric(
        &self,
        local_from_world: &DAffine3,
        inverted: bool,
    ) -> Option<InsideQuadric> {
        match self {
            LocalShape::Plane(plane) => InsideQuadric::from_plane(
                plane.normal(),
                plane.distance(),
                local_from_world,
                inverted,
            ),
            LocalShape::Quadric(quadric) => {
                InsideQuadric::from_local(quadric.coefficients(), local_from_world, inverted)
            }
            _ => None,
        }
    }

    /// Local bounds of the surface; `None` when unbounded.
    pub fn bounds(&self) -> Option<Aabb> {
        match self {
            LocalShape::Empty => Some(Aabb::EMPTY),
            LocalShape::Sphere(shape) => Some(shape.bounds()),
            LocalShape::Cuboid(shape) => shape.is_finite().then(|| shape.bounds()),
            LocalShape::Plane(_) | LocalShape::Quadric(_) | LocalShape::Poly(_) => None,
            LocalShape::Cone(shape) => Some(shape.bounds()),
            LocalShape::Torus(shape) => Some(shape.bounds()),
            LocalShape::Disc(shape) => Some(shape.bounds()),
            LocalShape::Triangle(shape) => Some(shape.bounds()),
            LocalShape::SmoothTriangle(shape) => Some(shape.bounds()),
            LocalShape::MeshFace(face) => face.triangle.bounds(),
            LocalShape::Polygon(shape) => Some(shape.bounds()),
            LocalShape::Extrusion(shape) => Some(shape.bounds()),
            LocalShape::Lathe(shape) => Some(shape.bounds()),
            LocalShape::Blob(shape) => Some(shape.bounds()),
            LocalShape::Superellipsoid(shape) => Some(shape.bounds()),
            LocalShape::Sor(shape) => Some(shape.bounds()),
            LocalShape::Isosurface(shape) => Some(shape.bounds()),
            LocalShape::HeightField(shape) => Some(shape.bounds()),
            LocalShape::SphereSweep(shape) => Some(shape.bounds()),
            LocalShape::JuliaFractal(shape) => Some(shape.bounds()),
            LocalShape::Ovus(shape) => Some(shape.bounds()),
            LocalShape::Lemon(shape) => Some(shape.bounds()),
            LocalShape::Parametric(shape) => Some(shape.bounds()),
        }
    }

    /// POV-Ray's bounding box of the shape once mapped by `world_from_local`; `None` when
    /// unbounded. POV-Ray bounds discs, cylinders and cones with boxes oriented along their
    /// axis, and a triangle by its mapped corners; the difference shows where such a box cuts
    /// off an inverted CSG object or a disc's half-space.
    pub fn pov_bounds(&self, world_from_local: &DAffine3) -> Option<Aabb> {
        let map = |corner: DVec3| world_from_local.transform_point3(corner);
        match self {
            LocalShape::Disc(disc) => Some(Aabb::from_points(disc.pov_box_corners().map(map))),
            LocalShape::Cone(cone) => Some(Aabb::from_points(cone.pov_box_corners().map(map))),
            LocalShape::Triangle(triangle) => Some(Aabb::from_points(triangle.corners().map(map))),
            LocalShape::SmoothTriangle(triangle) => {
                Some(Aabb::from_points(triangle.corners().map(map)))
            }
            LocalShape::MeshFace(face) => face.triangle.pov_bounds(world_from_local),
            // POV-Ray leaves a height field out of the box of a CSG intersection (measured with
            // min_extent): its inside reaches down without limit.
            LocalShape::HeightField(_) => None,
            _ => self
                .bounds()
                .map(|bounds| bounds.transformed(world_from_local)),
        }
    }

    /// Where inside points can be, relative to the surface bounds.
    fn inside_reach(&self) -> InsideReach {
        match self {
            LocalShape::Empty
            | LocalShape::Triangle(_)
            | LocalShape::SmoothTriangle(_)
            | LocalShape::MeshFace(_)
            | LocalShape::Polygon(_)
            | LocalShape::Parametric(_) => InsideReach::Nowhere,
            LocalShape::Plane(_)
            | LocalShape::Quadric(_)
            | LocalShape::Poly(_)
            | LocalShape::Disc(_)
            | LocalShape::HeightField(_) => InsideReach::Unbounded,
            LocalShape::Blob(blob) if blob.inside_everywhere_far() => InsideReach::Unbounded,
            _ => InsideReach::Bounded,
        }
    }

    /// The shape with `world_from_local` folded in, when the shape can absorb that map.
    fn absorbing(&self, world_from_local: &DAffine3) -> Option<LocalShape> {
        let matrix = world_from_local.matrix3;
        match self {
            LocalShape::Empty => Some(LocalShape::Empty),
            LocalShape::Plane(plane) => Some(
                plane
                    .transformed(world_from_local)
                    .map_or(LocalShape::Empty, Self::Plane),
            ),
            LocalShape::Triangle(triangle) => Some(
                triangle
                    .transformed(world_from_local)
                    .map_or(LocalShape::Empty, Self::Triangle),
            ),
            LocalShape::SmoothTriangle(triangle) => Some(
                triangle
                    .transformed(world_from_local)
                    .map_or(LocalShape::Empty, |t| Self::SmoothTriangle(Box::new(t))),
            ),
            LocalShape::MeshFace(face) => {
                let triangle = face.triangle.absorbing(world_from_local)?;
                Some(if matches!(triangle, LocalShape::Empty) {
                    LocalShape::Empty
                } else {
                    LocalShape::MeshFace(Box::new(MeshFace { triangle, ..**face }))
                })
            }
            LocalShape::Sphere(sphere) => {
                let gram = matrix.transpose() * matrix;
                let scale_squared = gram.x_axis.x;
                let tolerance = scale_squared * 1e-12;
                let similar = (gram.y_axis.y - scale_squared).abs() <= tolerance
                    && (gram.z_axis.z - scale_squared).abs() <= tolerance
                    && gram.x_axis.y.abs() <= tolerance
                    && gram.x_axis.z.abs() <= tolerance
                    && gram.y_axis.z.abs() <= tolerance;
                similar.then(|| {
                    let centre = world_from_local.transform_point3(sphere.centre());
                    Sphere::new(centre, sphere.radius() * scale_squared.sqrt())
                        .map_or(LocalShape::Empty, Self::Sphere)
                })
            }
            LocalShape::Cuboid(cuboid) => {
                let diagonal = matrix.x_axis.y == 0.0
                    && matrix.x_axis.z == 0.0
                    && matrix.y_axis.x == 0.0
                    && matrix.y_axis.z == 0.0
                    && matrix.z_axis.x == 0.0
                    && matrix.z_axis.y == 0.0;
                diagonal.then(|| {
                    cuboid
                        .scaled_and_moved(world_from_local)
                        .map_or(LocalShape::Empty, Self::Cuboid)
                })
            }
            _ => None,
        }
    }
}

/// The uv coordinates at the local surface `point` of `shape` (surface part `part`); `None`
/// for shapes POV-Ray gives no uv coordinates (their uv-mapped pigments see the point).
fn shape_uv(shape: &LocalShape, point: DVec3, part: u8) -> Option<DVec2> {
    match shape {
        LocalShape::Sphere(sphere) => Some(sphere_uv(point - sphere.centre())),
        LocalShape::Cuboid(cuboid) => Some(box_uv(cuboid.bounds(), point, part)),
        LocalShape::Torus(torus) => Some(torus_uv(torus.major(), point)),
        LocalShape::Lathe(lathe) => Some(lathe.uv(point, part)),
        LocalShape::Sor(sor) => Some(sor.uv(point, part)),
        LocalShape::Ovus(ovus) => Some(ovus.uv(point)),
        LocalShape::Parametric(parametric) => Some(parametric.uv(point)),
        _ => None,
    }
}

/// One shape placed in the world, with its material and inverse flag.
#[derive(Clone, Debug)]
pub struct Leaf {
    shape: LocalShape,
    /// World-to-local map; `None` when the shape is already in world coordinates. Shared
    /// by the leaves placed alike (the children of one transformed union).
    local_from_world: Option<Arc<DAffine3>>,
    /// Index into the world's materials.
    material: u32,
    /// Inside and outside swapped, normals flipped.
    inverse: bool,
}

/// World-space bounds of a leaf.
#[derive(Clone, Copy, Debug)]
pub struct LeafBounds {
    /// Where the surface can be hit; `None` when unbounded.
    pub surface: Option<Aabb>,
    /// Where inside points can be; `None` when they can be anywhere.
    pub inside: Option<Aabb>,
    /// Where outside points can be; `None` when they can be anywhere (bounded only for
    /// inverted finite shapes).
    pub outside: Option<Aabb>,
}

/// Hands out one shared copy of a world-to-local map for runs of leaves placed with the same
/// map, so that the 160,000 children of a rotated union hold one matrix, not 160,000.
#[derive(Default)]
pub struct SharedFrames {
    last: Option<Arc<DAffine3>>,
}

impl SharedFrames {
    /// `map`, shared with the previous leaf when that leaf had the same one.
    fn share(&mut self, map: &DAffine3) -> Arc<DAffine3> {
        match &self.last {
            Some(last) if **last == *map => Arc::clone(last),
            _ => Arc::clone(self.last.insert(Arc::new(*map))),
        }
    }
}

/// True when both maps of `transform` are finite and its matrix is invertible.
fn usable(transform: &Transform) -> bool {
    let forward = &transform.outer_from_inner;
    let backward = &transform.inner_from_outer;
    let determinant = forward.matrix3.determinant();
    forward.is_finite()
        && backward.is_finite()
        && determinant.is_finite()
        && determinant != 0.0
        && backward.matrix3.determinant().is_finite()
}

impl Leaf {
    #[cfg(test)]
    /// Places `shape` (not CSG) in the world through `world_from_local`.
    pub fn new(
        shape: &Shape,
        world_from_local: &Transform,
        material: u32,
        inverse: bool,
    ) -> (Leaf, LeafBounds) {
        Leaf::from_local(
            LocalShape::from_scene(shape),
            world_from_local,
            material,
            inverse,
            &mut SharedFrames::default(),
        )
    }

    /// Places a prepared local shape in the world through `world_from_local`.
    pub fn from_local(
        local: LocalShape,
        world_from_local: &Transform,
        material: u32,
        inverse: bool,
        frames: &mut SharedFrames,
    ) -> (Leaf, LeafBounds) {
        Leaf::placed(local, world_from_local, material, inverse, true, frames)
    }

    /// Like [`Leaf::from_local`], but the shape keeps its own space (the transform is never
    /// folded into it), so that its uv coordinates follow the object's orientation.
    pub fn from_local_keeping_frame(
        local: LocalShape,
        world_from_local: &Transform,
        material: u32,
        inverse: bool,
        frames: &mut SharedFrames,
    ) -> (Leaf, LeafBounds) {
        Leaf::placed(local, world_from_local, material, inverse, false, frames)
    }

    /// [`Leaf::from_local`]; `may_absorb` allows folding the transform into the shape.
    fn placed(
        local: LocalShape,
        world_from_local: &Transform,
        material: u32,
        inverse: bool,
        may_absorb: bool,
        frames: &mut SharedFrames,
    ) -> (Leaf, LeafBounds) {
        // POV-Ray cannot invert a triangle: it has no inside either way.
        let inverse = inverse && !local.has_no_inside();
        let (shape, local_from_world, world_from_shape) = if !usable(world_from_local) {
            (LocalShape::Empty, None, DAffine3::IDENTITY)
        } else if world_from_local.outer_from_inner == DAffine3::IDENTITY {
            (local, None, DAffine3::IDENTITY)
        } else if let Some(absorbed) = may_absorb
            .then(|| local.absorbing(&world_from_local.outer_from_inner))
            .flatten()
        {
            (absorbed, None, DAffine3::IDENTITY)
        } else {
            let backward = frames.share(&world_from_local.inner_from_outer);
            (local, Some(backward), world_from_local.outer_from_inner)
        };
        let surface = shape
            .bounds()
            .map(|bounds| bounds.transformed(&world_from_shape));
        // Where the shape itself (before any inversion) can contain points.
        let own_inside = match shape.inside_reach() {
            InsideReach::Bounded => surface,
            InsideReach::Unbounded => None,
            InsideReach::Nowhere => Some(Aabb::EMPTY),
        };
        let (inside, outside) = if inverse {
            (None, own_inside)
        } else {
            (own_inside, None)
        };
        let leaf = Leaf {
            shape,
            local_from_world,
            material,
            inverse,
        };
        (
            leaf,
            LeafBounds {
                surface,
                inside,
                outside,
            },
        )
    }

    /// Index of the leaf's material.
    pub fn material(&self) -> u32 {
        self.material
    }

    /// True when a hit on the leaf may show materials besides [`Leaf::material`] (a mesh
    /// face's corner textures, a blob's component textures).
    pub fn shows_other_materials(&self) -> bool {
        match &self.shape {
            LocalShape::MeshFace(_) => true,
            LocalShape::Blob(blob) => blob.is_textured(),
            _ => false,
        }
    }

    /// Pushes every crossing of the world ray (as ray parameters) into `roots`.
    #[inline]
    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        let (origin, direction) = self.local_ray(ray);
        self.shape.intersect(origin, direction, roots);
    }

    /// The world ray's origin and direction in the shape's own space (the direction keeps
    /// the map's scale, so ray parameters stay world ones).
    #[inline]
    fn local_ray(&self, ray: &Ray) -> (DVec3, DVec3) {
        match &self.local_from_world {
            None => (ray.origin, ray.direction),
            Some(map) => (
                map.transform_point3(ray.origin),
                map.transform_vector3(ray.direction),
            ),
        }
    }

    /// The nearest crossing strictly between the limits, with its surface part.
    #[inline]
    pub fn nearest(&self, ray: &Ray, min_distance: f64, max_distance: f64) -> Option<(f64, u8)> {
        if let LocalShape::JuliaFractal(shape) = &self.shape {
            // Its walk along the ray stops at the first crossing in range.
            let (origin, direction) = self.local_ray(ray);
            return shape
                .nearest(origin, direction, min_distance, max_distance)
                .map(|distance| (distance, 0));
        }
        let mut roots = Roots::new();
        self.intersect(ray, &mut roots);
        roots.nearest_within(min_distance, max_distance)
    }

    /// True when the world `point` is inside the leaf (inverse applied).
    #[inline]
    pub fn inside(&self, point: DVec3) -> bool {
        self.shape.inside(self.local_point(point)) != self.inverse
    }

    /// The world `point` in the shape's own space.
    #[inline]
    fn local_point(&self, point: DVec3) -> DVec3 {
        match &self.local_from_world {
            None => point,
            Some(map) => map.transform_point3(point),
        }
    }

    /// The unit outward world normal at the local surface point `local` (flipped when
    /// inverse).
    fn world_normal(&self, local: DVec3, part: u8) -> DVec3 {
        let normal = match (&self.shape, &self.local_from_world) {
            (_, None) => self.shape.normal(local, part),
            // A smooth height field blends normals after transforming them.
            (LocalShape::HeightField(field), Some(map)) => {
                field.world_normal(local, map.matrix3.transpose())
            }
            (shape, Some(map)) => map.matrix3.transpose() * shape.normal(local, part),
        };
        self.oriented(normal)
    }

    /// The unit world `normal` (any length), flipped when inverse.
    fn oriented(&self, normal: DVec3) -> DVec3 {
        let normal = normal.try_normalize().unwrap_or(DVec3::Z);
        if self.inverse {
            -normal
        } else {
            normal
        }
    }

    #[cfg(test)]
    /// The unit outward world normal at the world surface `point` (flipped when inverse).
    pub fn normal(&self, point: DVec3, part: u8) -> DVec3 {
        self.world_normal(self.local_point(point), part)
    }

    /// The normal, material, uv coordinates and corner blend at the world surface `point`
    /// (surface part `part`); uv coordinates only when `uses_uv` says a material the point
    /// shows needs them, and only for shapes that have them.
    pub fn hit_details(&self, point: DVec3, part: u8, uses_uv: impl Fn(u32) -> bool) -> HitDetails {
        let local = self.local_point(point);
        match &self.shape {
            LocalShape::MeshFace(face) => {
                let weights = barycentric(face.corners(), local);
                let normal = match &self.local_from_world {
                    None => face.normal_at_weights(weights),
                    Some(map) => map.matrix3.transpose() * face.normal_at_weights(weights),
                };
                let normal = self.oriented(normal);
                let materials = face.corner_materials;
                let uv = materials
                    .iter()
                    .any(|&material| uses_uv(material))
                    .then(|| corner_weighted(face.corner_uvs, weights));
                HitDetails::blended(normal, materials, weights, uv)
            }
            // A blob's component textures blend by the components' fields at the point; the
            // hit keeps the blob's own material as its identity.
            LocalShape::Blob(blob) if blob.is_textured() => {
                let normal = self.world_normal(local, part);
                let mut details = HitDetails::plain(normal, self.material);
                details.blend = blob.texture_blend(local);
                let any_uv = match &details.blend {
                    Some(blend) => blend.iter().any(|(material, _)| uses_uv(material)),
                    None => uses_uv(self.material),
                };
                if any_uv {
                    details.uv = Some(DVec2::new(point.x, point.y));
                }
                details
            }
            // One nearest-uv search gives a parametric surface's normal and uv together.
            LocalShape::Parametric(surface) if uses_uv(self.material) => {
                let (normal, uv) = surface.normal_and_uv(local);
                let normal = match &self.local_from_world {
                    None => normal,
                    Some(map) => map.matrix3.transpose() * normal,
                };
                let mut details = HitDetails::plain(self.oriented(normal), self.material);
                details.uv = Some(uv);
                details
            }
            shape => {
                let normal = self.world_normal(local, part);
                let mut details = HitDetails::plain(normal, self.material);
                if uses_uv(self.material) {
                    // Shapes POV-Ray gives no uv coordinates show the world point's x and y
                    // as u and v (measured: `uv_mapping function { z }` is 0 on them).
                    let world_xy = || DVec2::new(point.x, point.y);
                    details.uv = Some(shape_uv(shape, local, part).unwrap_or_else(world_xy));
                }
                details
            }
        }
    }

    /// True for a leaf that nothing can hit.
    pub fn is_empty(&self) -> bool {
        matches!(self.shape, LocalShape::Empty)
    }
}
