//! Turning the scene's object tree into flat primitives and shared materials.
//!
//! In: the top-level [`Object`]s of a scene. Out: [`Primitive`]s (leaves and CSG trees) with
//! their world bounds, the [`Material`] table, and the number of leaf shapes.
//! Holds: transforms compose down the tree (a child's transform maps into its parent's local
//! space); texture, interior texture, interior and `no_shadow` are each inherited from the
//! nearest ancestor that sets them (a material's light group: the innermost group's lights, the outermost group's
//! `global_lights`); each owning object's texture is converted to world space once and shared by every leaf
//! that inherits it; top-level unions that are not inverted are flattened into their children,
//! other CSG objects become trees. Inversion (by `inverse`, an inverted ancestor or being
//! subtracted) is pushed down to the leaves and changes the kind of each CSG node on the way, as
//! POV-Ray does: union becomes intersection, intersection becomes merge, merge becomes
//! intersection; triangles ignore inversion.

use super::csg::{Combination, CsgNode, CsgTree, NodeBounds};
use super::instance::{MeshGeometry, MeshInstance};
use super::leaf::{Leaf, LocalShape, SharedFrames};
use super::uv::texture_uses_uv;
use super::Material;
use crate::accel::Aabb;
use crate::hash::FastHash;
use crate::{
    math::Transform,
    scene::{Blob as SceneBlob, CsgOperation, Interior, Mesh, Object, Shape},
    texture::Texture,
};
use glam::DAffine3;
use std::borrow::Cow;
use std::collections::HashMap;
use std::sync::Arc;

/// Places a local shape in the world: [`Leaf::from_local`] or its frame-keeping twin.
type PlaceLeaf =
    fn(LocalShape, &Transform, u32, bool, &mut SharedFrames) -> (Leaf, super::leaf::LeafBounds);

/// Relative padding added to every primitive's bounds, so that rounding in the box tests can
/// never reject a hit the exact shape test finds.
const BOUNDS_RELATIVE_PADDING: f64 = 1e-9;

/// Absolute padding added to every primitive's bounds.
const BOUNDS_ABSOLUTE_PADDING: f64 = 1e-12;

/// A top-level renderable: one shape or a whole CSG object.
#[derive(Clone, Debug)]
pub enum Primitive {
    /// A single shape.
    Leaf(Leaf),
    /// A CSG object evaluated as a whole.
    Csg(Box<CsgTree>),
    /// One placement of a shared mesh.
    Mesh(Box<MeshInstance>),
}

/// Primitives in the order they were built, split by whether their surface has finite bounds.
#[derive(Default)]
pub struct Primitives {
    /// Primitives with finite surface bounds.
    pub bounded: Vec<Primitive>,
    /// The surface bounds of each of `bounded`, in the same order.
    pub bounds: Vec<Aabb>,
    /// Primitives without finite bounds (planes, unbounded quadrics, ...).
    pub unbounded: Vec<Primitive>,
}

impl Primitives {
    /// Adds `primitive`, whose surface lies inside `surface` (`None` when unbounded).
    fn push(&mut self, primitive: Primitive, surface: Option<Aabb>) {
        match surface {
            Some(surface) if surface.is_finite() => {
                self.bounded.push(primitive);
                self.bounds.push(surface);
            }
            _ => self.unbounded.push(primitive),
        }
    }
}

/// What the builder produces.
pub struct BuiltScene {
    /// Every primitive, with the bounds of the bounded ones.
    pub primitives: Primitives,
    /// The material table.
    pub materials: Vec<Material>,
    /// Number of leaf shapes, CSG children included.
    pub leaf_count: usize,
}

/// Identifies a texture for sharing materials.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum TextureKey {
    /// No object set a texture: the default one.
    Default,
    /// A texture used as is (no pattern or no transform to apply), by its address.
    Shared(usize),
    /// A texture converted for one owning object, by the owner's number.
    Owned(usize),
}

/// Identifies an interior for sharing materials.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum InteriorKey {
    /// No object set an interior.
    Default,
    /// The interior set by one object, by the owner's number.
    Owned(usize),
}

/// The inversions applied to a CSG subtree from above.
#[derive(Clone, Copy, Debug)]
struct Inversion {
    /// An odd number of inversions: the subtree's inside and outside are swapped.
    odd: bool,
    /// Inverted at least once (a union inverted twice becomes a merge, not a union again).
    any: bool,
}

/// The appearance an object passes down to its children.
#[derive(Clone, Debug)]
struct Appearance {
    texture: Arc<Texture>,
    texture_key: TextureKey,
    /// The `interior_texture` (inherited on its own, apart from `texture`) and its key.
    interior_texture: Option<(Arc<Texture>, TextureKey)>,
    interior: Arc<Interior>,
    interior_key: InteriorKey,
    flags: Flags,
}

impl Appearance {
    /// What materials are shared by: equal keys give equal materials.
    fn material_key(&self) -> MaterialKey {
        (
            self.texture_key,
            self.interior_texture.as_ref().map(|(_, key)| *key),
            self.interior_key,
            self.flags,
        )
    }

    /// True when a texture or interior of this appearance was made for an owner numbered
    /// `first_owner` or later.
    fn owned_since(&self, first_owner: usize) -> bool {
        let texture_owner =
            |key: TextureKey| matches!(key, TextureKey::Owned(n) if n >= first_owner);
        texture_owner(self.texture_key)
            || self
                .interior_texture
                .as_ref()
                .is_some_and(|(_, key)| texture_owner(*key))
            || matches!(self.interior_key, InteriorKey::Owned(n) if n >= first_owner)
    }
}

/// The object flags a material carries, inherited from ancestors.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
struct Flags {
    no_shadow: bool,
    no_image: bool,
    no_reflection: bool,
    no_radiosity: bool,
    double_illuminate: bool,
    hollow: bool,
    light_group: Option<crate::scene::LightGroup>,
    photons: crate::scene::ObjectPhotons,
}

/// What materials are shared by: texture, interior texture, interior and flags.
type MaterialKey = (TextureKey, Option<TextureKey>, InteriorKey, Flags);

/// Working state of one build.
struct Builder {
    materials: Vec<Material>,
    material_of: HashMap<MaterialKey, u32, FastHash>,
    /// The material found last, checked before the table.
    last_material: Option<(MaterialKey, u32)>,
    next_owner: usize,
    leaf_count: usize,
    /// Prepared geometry of each scene mesh placed at top level, by the mesh's address.
    meshes: HashMap<usize, Arc<MeshGeometry>>,
    /// World-to-local maps shared between leaves.
    frames: SharedFrames,
}

/// Builds primitives and materials from the scene's top-level objects.
pub fn build_scene(objects: &[Object]) -> BuiltScene {
    let mut builder = Builder {
        materials: Vec::new(),
        material_of: HashMap::default(),
        last_material: None,
        next_owner: 0,
        leaf_count: 0,
        meshes: HashMap::new(),
        frames: SharedFrames::default(),
    };
    let appearance = Appearance {
        texture: Arc::new(Texture::default()),
        texture_key: TextureKey::Default,
        interior_texture: None,
        interior: Arc::new(Interior::default()),
        interior_key: InteriorKey::Default,
        flags: Flags::default(),
    };
    let mut primitives = Primitives::default();
    for object in objects {
        builder.add_top_level(
            object,
            &Transform::IDENTITY,
            &appearance,
            &mut Vec::new(),
            &mut primitives,
        );
    }
    BuiltScene {
        primitives,
        materials: builder.materials,
        leaf_count: builder.leaf_count,
    }
}

/// The texture with every pattern transform re-expressed from owner-local to world space.
fn texture_to_world(texture: &Texture, world_from_owner: &Transform) -> Texture {
    let mut converted = texture.clone();
    converted.transform(world_from_owner);
    converted
}

/// POV-Ray's bounding box of `object` in its parent's space; `None` when infinite.
///
/// The rules, inferred from POV-Ray's output: a shape's box is its own box mapped through the
/// shape's transform ([`LocalShape::pov_bounds`]), infinite once the shape is inverted
/// (triangles cannot be inverted and keep theirs); a union or merge has the union of its
/// children's boxes; an intersection or difference has the overlap of the boxes of its children
/// that are not inverted (so a difference is bounded by its first child); a CSG object's box is
/// then mapped through its own transform as a box (all eight corners). Inverting a CSG object
/// later does not change its box, so an inverted CSG object is cut off at the box of the object
/// it came from: rays that miss the box miss the object.
fn pov_bounding_box(object: &Object) -> Option<Aabb> {
    let own = own_pov_bounding_box(object);
    match kept_bound_box(object, own) {
        Some(bound) => clipped_box(object, Some(bound)),
        None => own,
    }
}

/// The box of `object`'s `bounded_by` objects in its parent's space, when POV-Ray keeps it:
/// only when its volume is smaller than the volume of the object's own box `own` (measured:
/// POV-Ray 3.7 drops a larger bound as "unnecessary", even one that cuts the object). Rays
/// that miss a kept box miss the object, but shadow rays ignore it.
fn kept_bound_box(object: &Object, own: Option<Aabb>) -> Option<Aabb> {
    if object.bounded_by.is_empty() {
        return None;
    }
    let parent_from_local = &object.transform().outer_from_inner;
    let bound = object
        .bounded_by
        .iter()
        .try_fold(Aabb::EMPTY, |all, bound| {
            pov_bounding_box(bound).map(|b| all.union(&b))
        })
        .map(|local| local.transformed(parent_from_local))?;
    let volume = |bounds: &Aabb| {
        if bounds.is_empty() {
            0.0
        } else {
            let extent = bounds.extent();
            extent.x * extent.y * extent.z
        }
    };
    own.is_none_or(|own| volume(&bound) < volume(&own))
        .then_some(bound)
}

/// POV-Ray's bounding box of `object` without its `bounded_by` objects. A clipped bicubic
/// patch is bounded by its clipping objects' box alone (measured with `trace`: rays crossing
/// that box below the patch's own box still see the patch).
fn own_pov_bounding_box(object: &Object) -> Option<Aabb> {
    let unclippable = matches!(&object.shape, Shape::Mesh(mesh) if mesh.ignores_clipped_by);
    if unclippable && !object.clipped_by.is_empty() {
        return clipped_box(object, None);
    }
    clipped_box(object, unclipped_pov_bounding_box(object))
}

/// `unclipped` cut to the boxes of `object`'s (not inverted) clipping objects.
fn clipped_box(object: &Object, unclipped: Option<Aabb>) -> Option<Aabb> {
    let parent_from_local = &object.transform().outer_from_inner;
    object
        .clipped_by
        .iter()
        .filter(|clip| !(clip.inverse && invertible(&clip.shape)))
        .filter_map(pov_bounding_box)
        .map(|clip| {
            if clip.is_empty() {
                Aabb::EMPTY
            } else {
                clip.transformed(parent_from_local)
            }
        })
        .fold(unclipped, |all, clip| {
            Some(all.map_or(clip, |all| all.intersection(&clip)))
        })
}

/// [`pov_bounding_box`] ignoring `clipped_by`.
fn unclipped_pov_bounding_box(object: &Object) -> Option<Aabb> {
    let parent_from_local = &object.transform().outer_from_inner;
    let local = match &object.shape {
        Shape::Csg {
            operation: CsgOperation::Union | CsgOperation::Merge,
            children,
        } => children.iter().try_fold(Aabb::EMPTY, |all, child| {
            pov_bounding_box(child).map(|b| all.union(&b))
        })?,
        Shape::Csg {
            operation,
            children,
        } => {
            let subtract = *operation == CsgOperation::Difference;
            let mut common: Option<Aabb> = None;
            for (position, child) in children.iter().enumerate() {
                let subtracted = subtract && position > 0;
                if (child.inverse || subtracted) && invertible(&child.shape) {
                    continue;
                }
                if let Some(bounds) = pov_bounding_box(child) {
                    common = Some(common.map_or(bounds, |common| common.intersection(&bounds)));
                }
            }
            common?
        }
        shape if object.inverse && invertible(shape) => return None,
        shape => {
            return LocalShape::pieces(shape)
                .iter()
                .try_fold(Aabb::EMPTY, |all, piece| {
                    piece
                        .pov_bounds(parent_from_local)
                        .map(|bounds| all.union(&bounds))
                })
        }
    };
    if local.is_empty() {
        return Some(Aabb::EMPTY);
    }
    Some(local.transformed(parent_from_local))
}

/// False for shapes POV-Ray cannot invert (triangles, polygons, meshes without an inside):
/// `inverse` leaves them unchanged.
fn invertible(shape: &Shape) -> bool {
    match shape {
        Shape::Triangle { .. } | Shape::SmoothTriangle { .. } | Shape::Polygon(_) => false,
        Shape::Mesh(mesh) => mesh.inside_vector.is_some(),
        _ => true,
    }
}

/// Pads bounds so box tests are conservative; non-finite bounds become unbounded.
fn padded(bounds: Option<Aabb>) -> Option<Aabb> {
    let bounds = bounds?;
    if bounds.is_empty() {
        return Some(Aabb::EMPTY);
    }
    let bounds = bounds.padded(BOUNDS_RELATIVE_PADDING, BOUNDS_ABSOLUTE_PADDING);
    bounds.is_finite().then_some(bounds)
}

impl Builder {
    /// A fresh number for an object that owns a texture or interior.
    fn new_owner(&mut self) -> usize {
        self.next_owner += 1;
        self.next_owner
    }

    /// The appearance `object` passes on, given what it inherits.
    fn appearance<'a>(
        &mut self,
        object: &Object,
        world_from_local: &Transform,
        inherited: &'a Appearance,
    ) -> Cow<'a, Appearance> {
        let mut flags = inherited.flags;
        flags.no_shadow |= object.no_shadow;
        flags.no_image |= object.no_image;
        flags.no_reflection |= object.no_reflection;
        flags.no_radiosity |= object.no_radiosity;
        flags.double_illuminate |= object.double_illuminate;
        if let Some(hollow) = object.hollow {
            flags.hollow = hollow;
        }
        // Photon items merge one by one: what an outer CSG set wins over the inner.
        let mut photons = object.photons;
        photons.inherit(&inherited.flags.photons);
        flags.photons = photons;
        // Nested light groups (measured): the innermost group's lights light an object,
        // the outermost group's `global_lights` decides whether scene lights do.
        if let Some(group) = object.light_group {
            let global_lights = flags
                .light_group
                .map_or(group.global_lights, |outer| outer.global_lights);
            flags.light_group = Some(crate::scene::LightGroup {
                global_lights,
                ..group
            });
        }
        if object.texture.is_none()
            && object.interior_texture.is_none()
            && object.interior.is_none()
            && flags == inherited.flags
        {
            // Most children of a generated union: no reference counts to touch.
            return Cow::Borrowed(inherited);
        }
        let mut appearance = inherited.clone();
        appearance.flags = flags;
        if let Some(texture) = &object.texture {
            (appearance.texture, appearance.texture_key) =
                self.placed_texture(texture, world_from_local);
        }
        if let Some(texture) = &object.interior_texture {
            appearance.interior_texture = Some(self.placed_texture(texture, world_from_local));
        }
        if let Some(interior) = &object.interior {
            let mut interior = Interior::clone(interior);
            // Media densities move with the object, like its texture.
            for media in &mut interior.media {
                media.transform(world_from_local);
            }
            appearance.interior = Arc::new(interior);
            appearance.interior_key = InteriorKey::Owned(self.new_owner());
        }
        Cow::Owned(appearance)
    }

    /// `texture` as used by an object placed with `world_from_local`, and the key materials
    /// share it by: one that depends on position and is moved gets its own world-space copy;
    /// any other is shared by every object that uses the same texture.
    fn placed_texture(
        &mut self,
        texture: &Arc<Texture>,
        world_from_local: &Transform,
    ) -> (Arc<Texture>, TextureKey) {
        if texture.depends_on_position() && *world_from_local != Transform::IDENTITY {
            let placed = Arc::new(texture_to_world(texture, world_from_local));
            (placed, TextureKey::Owned(self.new_owner()))
        } else {
            let key = TextureKey::Shared(Arc::as_ptr(texture) as usize);
            (Arc::clone(texture), key)
        }
    }

    /// The material index for an appearance, creating the material on first use.
    fn material(&mut self, appearance: &Appearance) -> u32 {
        let key = appearance.material_key();
        // Generated scenes place long runs of objects with one material.
        if let Some((last_key, index)) = self.last_material {
            if last_key == key {
                return index;
            }
        }
        if let Some(&index) = self.material_of.get(&key) {
            self.last_material = Some((key, index));
            return index;
        }
        let index = self.unshared_material(appearance);
        self.material_of.insert(key, index);
        index
    }

    /// A new material for an appearance no other object can share (so it is not entered in
    /// the table that shares materials: a million uniquely coloured spheres would fill it
    /// for nothing).
    fn unshared_material(&mut self, appearance: &Appearance) -> u32 {
        let index = self.materials.len() as u32;
        self.materials.push(Material {
            texture: Arc::clone(&appearance.texture),
            interior_texture: appearance
                .interior_texture
                .as_ref()
                .map(|(texture, _)| Arc::clone(texture)),
            interior: appearance.interior.clone(),
            no_shadow: appearance.flags.no_shadow,
            no_image: appearance.flags.no_image,
            no_reflection: appearance.flags.no_reflection,
            no_radiosity: appearance.flags.no_radiosity,
            double_illuminate: appearance.flags.double_illuminate,
            hollow: appearance.flags.hollow,
            uses_uv: texture_uses_uv(&appearance.texture)
                || appearance
                    .interior_texture
                    .as_ref()
                    .is_some_and(|(texture, _)| texture_uses_uv(texture)),
            light_group: appearance.flags.light_group,
            photons: appearance.flags.photons,
        });
        self.last_material = Some((appearance.material_key(), index));
        index
    }

    /// How leaves of `material` are placed: shapes whose texture uses uv coordinates keep
    /// their own space, so the uv follows the object's orientation.
    fn leaf_placement(&self, material: u32) -> PlaceLeaf {
        if self.materials[material as usize].uses_uv {
            Leaf::from_local_keeping_frame
        } else {
            Leaf::from_local
        }
    }

    /// The material of each texture slot of a mesh placed with `appearance`: the object's
    /// own first, then one per triangle texture (placed like the object's, so shared alike).
    fn mesh_materials(
        &mut self,
        mesh: &Mesh,
        appearance: &Appearance,
        world_from_local: &Transform,
    ) -> Box<[u32]> {
        let mut materials = vec![self.material(appearance)];
        for texture in &mesh.textures {
            let mut own = appearance.clone();
            (own.texture, own.texture_key) = self.placed_texture(texture, world_from_local);
            materials.push(self.material(&own));
        }
        materials.into_boxed_slice()
    }

    /// The material of each component of a blob placed with `appearance` (material `own`):
    /// a component's own texture placed like the blob's, else `own`.
    fn blob_materials(
        &mut self,
        blob: &SceneBlob,
        appearance: &Appearance,
        own: u32,
        world_from_local: &Transform,
    ) -> Vec<u32> {
        blob.components
            .iter()
            .map(|component| match &component.texture {
                Some(texture) => {
                    let mut part = appearance.clone();
                    (part.texture, part.texture_key) =
                        self.placed_texture(texture, world_from_local);
                    self.material(&part)
                }
                None => own,
            })
            .collect()
    }

    /// The leaf shapes of `shape` shown with `material` (a blob's component textures get
    /// their own materials).
    fn shape_pieces(
        &mut self,
        shape: &Shape,
        appearance: &Appearance,
        material: u32,
        world_from_local: &Transform,
    ) -> Vec<LocalShape> {
        match shape {
            Shape::Blob(blob) if blob.has_component_textures() => {
                let materials = self.blob_materials(blob, appearance, material, world_from_local);
                vec![LocalShape::textured_blob(blob, &materials)]
            }
            _ => LocalShape::pieces(shape),
        }
    }

    /// Adds a top-level object (or a child of a flattened top-level union).
    ///
    /// A union that is not inverted is split into its children (like POV-Ray's
    /// `split_union`); everything else that is CSG becomes one tree. `enclosing_unions` holds
    /// the transforms of the split unions around the object, outermost first.
    fn add_top_level(
        &mut self,
        object: &Object,
        world_from_parent: &Transform,
        inherited: &Appearance,
        enclosing_unions: &mut Vec<DAffine3>,
        out: &mut Primitives,
    ) {
        let world_from_local = object.transform().then(world_from_parent);
        match &object.shape {
            Shape::Csg {
                operation: CsgOperation::Union,
                children,
            } if !object.inverse
                && object.clipped_by.is_empty()
                && object.bounded_by.is_empty() =>
            {
                let appearance = self.appearance(object, &world_from_local, inherited);
                enclosing_unions.push(object.transform().outer_from_inner);
                for child in children {
                    self.add_top_level(
                        child,
                        &world_from_local,
                        &appearance,
                        enclosing_unions,
                        out,
                    );
                }
                enclosing_unions.pop();
            }
            shape
                if matches!(shape, Shape::Csg { .. })
                    || !object.clipped_by.is_empty()
                    || !object.bounded_by.is_empty() =>
            {
                let mut leaves = Vec::new();
                let inversion = Inversion {
                    odd: false,
                    any: false,
                };
                let root =
                    self.csg_node(object, world_from_parent, inherited, inversion, &mut leaves);
                // Each enclosing union maps the box on, innermost first, as POV-Ray does.
                let to_world = |bounds: Option<Aabb>| {
                    bounds
                        .map(|bounds| {
                            enclosing_unions
                                .iter()
                                .rev()
                                .fold(bounds, |bounds, map| bounds.transformed(map))
                        })
                        .filter(Aabb::is_finite)
                };
                let own = own_pov_bounding_box(object);
                let clip = to_world(own);
                let bound = kept_bound_box(object, own)
                    .and_then(|bound| to_world(clipped_box(object, Some(bound))));
                // Shadow rays see the object inside `clip` (not `bound`), so the surface bounds
                // must cover all of it. A bicubic patch's hits can lie outside its clip box
                // (rays need only cross the box), so its surface bounds stay whole.
                let unclippable =
                    matches!(&object.shape, Shape::Mesh(mesh) if mesh.ignores_clipped_by);
                let clip_surface = clip.filter(|_| !unclippable).and_then(|b| padded(Some(b)));
                let surface = match (root.bounds().surface, clip_surface) {
                    (Some(surface), Some(clip)) => Some(surface.intersection(&clip)),
                    (surface, clip) => surface.or(clip),
                };
                if surface.is_some_and(|bounds| bounds.is_empty()) {
                    return;
                }
                let tree = CsgTree {
                    leaves,
                    root,
                    clip,
                    bound,
                };
                out.push(Primitive::Csg(Box::new(tree)), surface);
            }
            Shape::Mesh(mesh) => {
                let appearance = self.appearance(object, &world_from_local, inherited);
                let materials = self.mesh_materials(mesh, &appearance, &world_from_local);
                let needs_uv = materials
                    .iter()
                    .any(|&material| self.materials[material as usize].uses_uv);
                let geometry = self
                    .meshes
                    .entry(Arc::as_ptr(mesh) as usize)
                    .or_insert_with(|| Arc::new(MeshGeometry::new(mesh)))
                    .clone();
                let triangles = geometry.len();
                if let Some((instance, bounds)) =
                    MeshInstance::new(geometry, &world_from_local, materials, needs_uv)
                {
                    self.leaf_count += triangles;
                    out.push(Primitive::Mesh(Box::new(instance)), padded(Some(bounds)));
                }
            }
            shape => {
                // Owners are numbered from 1 up (`new_owner` hands out the count after
                // adding one), so the first one made for this object is the next number: an
                // interior or texture an enclosing union made is shared by all its children
                // (each child's own material made them refract as separate objects).
                let first_own_owner = self.next_owner + 1;
                // A texture no other object or identifier holds: this object's material
                // cannot be shared (checked before the appearance takes its own reference).
                let sole_texture = object
                    .texture
                    .as_ref()
                    .is_some_and(|texture| Arc::strong_count(texture) == 1);
                let appearance = self.appearance(object, &world_from_local, inherited);
                let material = if sole_texture || appearance.owned_since(first_own_owner) {
                    self.unshared_material(&appearance)
                } else {
                    self.material(&appearance)
                };
                let place = self.leaf_placement(material);
                for piece in self.shape_pieces(shape, &appearance, material, &world_from_local) {
                    let (leaf, bounds) = place(
                        piece,
                        &world_from_local,
                        material,
                        object.inverse,
                        &mut self.frames,
                    );
                    let surface = padded(bounds.surface);
                    if leaf.is_empty() || surface.is_some_and(|bounds| bounds.is_empty()) {
                        continue;
                    }
                    self.leaf_count += 1;
                    out.push(Primitive::Leaf(leaf), surface);
                }
            }
        }
    }

    /// Builds the CSG subtree for `object`, appending its leaves to `leaves`.
    ///
    /// `inherited_inversion` describes the inversions applied from above (an inverted ancestor,
    /// or being a subtracted child of a difference).
    fn csg_node(
        &mut self,
        object: &Object,
        world_from_parent: &Transform,
        inherited: &Appearance,
        inherited_inversion: Inversion,
        leaves: &mut Vec<Leaf>,
    ) -> CsgNode {
        let world_from_local = object.transform().then(world_from_parent);
        let appearance = self.appearance(object, &world_from_local, inherited);
        let inversion = Inversion {
            odd: inherited_inversion.odd != object.inverse,
            any: inherited_inversion.any || object.inverse,
        };
        let node = self.unclipped_node(object, &world_from_local, &appearance, inversion, leaves);
        // A bicubic patch is only bounded by its clipping objects' box (the tree's clip box).
        let unclippable = matches!(&object.shape, Shape::Mesh(mesh) if mesh.ignores_clipped_by);
        if object.clipped_by.is_empty() || unclippable {
            return node;
        }
        // The clipping objects are never inverted with the object: inverting a clipped
        // object swaps its inside but keeps the same visible surfaces.
        let upright = Inversion {
            odd: false,
            any: false,
        };
        let mut nodes = vec![node];
        for clip in &object.clipped_by {
            nodes.push(self.csg_node(clip, &world_from_local, &appearance, upright, leaves));
        }
        let combination = if inversion.odd {
            Combination::InvertedClip
        } else {
            Combination::Clip
        };
        CsgNode::combine(combination, nodes)
    }

    /// The CSG node of `object` without its `clipped_by`.
    fn unclipped_node(
        &mut self,
        object: &Object,
        world_from_local: &Transform,
        appearance: &Appearance,
        inversion: Inversion,
        leaves: &mut Vec<Leaf>,
    ) -> CsgNode {
        let world_from_local = *world_from_local;
        let appearance = appearance.clone();
        match &object.shape {
            Shape::Csg {
                operation,
                children,
            } => {
                // Like POV-Ray, inverting a CSG node inverts its children and changes its kind:
                // union to intersection, intersection to merge, merge to intersection.
                let combination = match (operation, inversion.odd, inversion.any) {
                    (CsgOperation::Union, _, false) => Combination::Union,
                    (CsgOperation::Union, true, true) => Combination::Intersection,
                    (CsgOperation::Union, false, true) => Combination::Merge,
                    (CsgOperation::Merge, false, _) => Combination::Merge,
                    (CsgOperation::Merge, true, _) => Combination::Intersection,
                    (CsgOperation::Intersection | CsgOperation::Difference, false, _) => {
                        Combination::Intersection
                    }
                    (CsgOperation::Intersection | CsgOperation::Difference, true, _) => {
                        Combination::Merge
                    }
                };
                let subtract = *operation == CsgOperation::Difference;
                let nodes = children
                    .iter()
                    .enumerate()
                    .map(|(position, child)| {
                        let subtracted = subtract && position > 0;
                        let passed_down = Inversion {
                            odd: inversion.odd != subtracted,
                            any: inversion.any || subtracted,
                        };
                        self.csg_node(child, &world_from_local, &appearance, passed_down, leaves)
                    })
                    .collect();
                CsgNode::combine(combination, nodes)
            }
            shape => {
                let material = self.material(&appearance);
                // A mesh's triangles keep their corners' uv coordinates and materials.
                let pieces: Vec<(LocalShape, u32)> = match shape {
                    Shape::Mesh(mesh) => {
                        let materials = self.mesh_materials(mesh, &appearance, &world_from_local);
                        LocalShape::mesh_pieces(mesh, &materials)
                    }
                    _ => self
                        .shape_pieces(shape, &appearance, material, &world_from_local)
                        .into_iter()
                        .map(|piece| (piece, material))
                        .collect(),
                };
                let mut nodes: Vec<CsgNode> = pieces
                    .into_iter()
                    .map(|(piece, material)| {
                        let inside_quadric = piece
                            .inside_quadric(&world_from_local.inner_from_outer, inversion.odd)
                            .map(Box::new);
                        let place = self.leaf_placement(material);
                        let (leaf, bounds) = place(
                            piece,
                            &world_from_local,
                            material,
                            inversion.odd,
                            &mut self.frames,
                        );
                        let index = leaves.len() as u32;
                        leaves.push(leaf);
                        self.leaf_count += 1;
                        let bounds = NodeBounds {
                            surface: padded(bounds.surface),
                            inside: padded(bounds.inside),
                            outside: padded(bounds.outside),
                        };
                        CsgNode::Leaf {
                            index,
                            bounds,
                            inside_quadric,
                        }
                    })
                    .collect();
                let solid_direction = match shape {
                    Shape::Mesh(mesh) => mesh.inside_vector.and_then(|vector| {
                        world_from_local
                            .outer_from_inner
                            .transform_vector3(vector)
                            .try_normalize()
                    }),
                    _ => None,
                };
                if let Some(direction) = solid_direction {
                    // A mesh with an `inside_vector` is a solid: inside by crossing parity.
                    let solid = Combination::Solid {
                        direction,
                        inverted: inversion.odd,
                    };
                    CsgNode::combine(solid, nodes)
                } else if nodes.len() == 1 {
                    nodes
                        .pop()
                        .unwrap_or_else(|| CsgNode::combine(Combination::Union, Vec::new()))
                } else if inversion.odd && matches!(shape, Shape::Text(_)) {
                    // Outside every letter: the inverted letters intersected.
                    CsgNode::combine(Combination::Intersection, nodes)
                } else {
                    CsgNode::combine(Combination::Union, nodes)
                }
            }
        }
    }
}
