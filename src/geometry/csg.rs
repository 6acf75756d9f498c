//! CSG trees evaluated per ray over their children's hit lists.
//!
//! In: a tree of [`Leaf`] primitives under union, intersection and merge nodes, with every
//! inversion already pushed down to the leaves (a difference arrives as an intersection whose
//! later children are inverted). Out: the nearest surviving surface hit of a ray, tagged with
//! the leaf it lies on, and inside tests for whole subtrees.
//! Holds: a node's hits are its children's hits filtered by the inside tests of the siblings
//! (intersection keeps hits inside all siblings, merge drops hits inside any sibling, union
//! keeps all); among hits at the same distance the later child's wins. An object may carry
//! POV-Ray's bounding box as a clip: rays missing it miss the object (shadow rays ignore the
//! part of it that comes from `bounded_by`). Hits are gathered into
//! one per-thread scratch vector, so no ray allocates once the vector has grown.

use super::leaf::Leaf;
use super::quadric_bounds::InsideQuadric;
use super::roots::Roots;
use super::Ray;
use crate::accel::{Aabb, Bvh};
use glam::DVec3;
use std::cell::RefCell;

/// How a CSG node combines its children.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Combination {
    /// A mesh with an `inside_vector`: every surface of its triangles, inside where a ray from
    /// the point along `direction` (world space) crosses them an odd number of times
    /// (swapped when `inverted`).
    Solid {
        /// The mesh's `inside_vector` in world space.
        direction: DVec3,
        /// The mesh is inverted.
        inverted: bool,
    },
    /// Every surface of every child.
    Union,
    /// Surfaces of each child that lie inside all other children.
    Intersection,
    /// Surfaces of each child that lie inside no other child.
    Merge,
    /// `clipped_by`: the surfaces of the first child that lie inside all later children (the
    /// clipping objects, whose own surfaces are never seen); inside all children.
    Clip,
    /// A clipped object inverted: the same surfaces, but inside where the (already inverted)
    /// first child is inside or any clipping object is not.
    InvertedClip,
}

/// Bounds of a CSG subtree in world space.
#[derive(Clone, Copy, Debug)]
pub struct NodeBounds {
    /// Where the subtree's surfaces can be hit; `None` when unbounded.
    pub surface: Option<Aabb>,
    /// Where points inside the subtree can be; `None` when they can be anywhere.
    pub inside: Option<Aabb>,
    /// Where points outside the subtree can be; `None` when they can be anywhere. Bounded for
    /// inverted finite shapes (a difference's subtracted parts) and what is built of them.
    pub outside: Option<Aabb>,
}

/// Crossings closer than this to the start of a mesh's inside ray do not count.
const SOLID_EPSILON: f64 = 1e-9;

/// Nodes with at least this many children index them by their boxes.
const INDEXED_CHILDREN: usize = 12;

/// The children of a wide CSG node indexed by their boxes, so that a ray or a point visits
/// only the few children it can touch instead of all of them.
#[derive(Clone, Debug)]
pub struct ChildIndex {
    /// Children with a bounded, non-empty surface, by surface box.
    surface: Bvh,
    /// Child position of each primitive position of `surface`.
    surface_children: Vec<u32>,
    /// Children whose surface is unbounded: every ray visits them.
    unbounded_surface: Vec<u32>,
    /// For union and merge, children by the box of their inside (where they can contain a
    /// point); for intersection and clip, by the box of their outside (where they can fail to
    /// contain one). Children that can never matter to a point test are left out.
    filter: Bvh,
    /// Child position of each primitive position of `filter`.
    filter_children: Vec<u32>,
    /// Children whose filter region is unbounded: every point test checks them.
    unbounded_filter: Vec<u32>,
}

impl ChildIndex {
    /// Indexes `children` combined by `combination`; `None` for small nodes and inverted clips.
    fn new(combination: Combination, children: &[NodeBounds]) -> Option<ChildIndex> {
        if children.len() < INDEXED_CHILDREN || combination == Combination::InvertedClip {
            return None;
        }
        let by_inside = matches!(combination, Combination::Union | Combination::Merge);
        let split = |region: &dyn Fn(&NodeBounds) -> Option<Aabb>| {
            let mut boxes = Vec::new();
            let mut boxed_children = Vec::new();
            let mut unbounded = Vec::new();
            for (position, bounds) in children.iter().enumerate() {
                match region(bounds) {
                    None => unbounded.push(position as u32),
                    Some(region) if region.is_empty() => {}
                    Some(region) => {
                        boxes.push(region);
                        boxed_children.push(position as u32);
                    }
                }
            }
            let (tree, order) = Bvh::build(&boxes);
            let children = order.iter().map(|&i| boxed_children[i as usize]).collect();
            (tree, children, unbounded)
        };
        let (surface, surface_children, unbounded_surface) = split(&|b| b.surface);
        let (filter, filter_children, unbounded_filter) = if by_inside {
            split(&|b| b.inside)
        } else {
            split(&|b| b.outside)
        };
        Some(ChildIndex {
            surface,
            surface_children,
            unbounded_surface,
            filter,
            filter_children,
            unbounded_filter,
        })
    }

    /// True when `test(child)` holds for a child whose filter region contains `point`.
    fn any_filtered(&self, point: DVec3, mut test: impl FnMut(usize) -> bool) -> bool {
        self.unbounded_filter
            .iter()
            .any(|&child| test(child as usize))
            || self.filter.any_containing(point, |position| {
                test(self.filter_children[position] as usize)
            })
    }
}

/// One node of a CSG tree.
#[derive(Clone, Debug)]
pub enum CsgNode {
    /// A leaf primitive, by index into the tree's leaves.
    Leaf {
        /// Position in [`CsgTree::leaves`].
        index: u32,
        /// The leaf's bounds.
        bounds: NodeBounds,
        /// The inside of an unbounded plane or quadric leaf, which an intersection uses to
        /// bound its other children's region.
        inside_quadric: Option<Box<InsideQuadric>>,
    },
    /// A combination of child subtrees.
    Combine {
        /// How the children combine.
        combination: Combination,
        /// The child subtrees.
        children: Vec<CsgNode>,
        /// The node's bounds.
        bounds: NodeBounds,
        /// The children indexed by their boxes, for wide nodes.
        index: Option<Box<ChildIndex>>,
    },
}

impl CsgNode {
    /// The node's world bounds.
    pub fn bounds(&self) -> NodeBounds {
        match self {
            CsgNode::Leaf { bounds, .. } | CsgNode::Combine { bounds, .. } => *bounds,
        }
    }

    /// Removes the child indexes of this subtree (tests compare against the plain search).
    #[cfg(test)]
    pub fn strip_child_indexes(&mut self) {
        if let CsgNode::Combine {
            children, index, ..
        } = self
        {
            *index = None;
            children.iter_mut().for_each(CsgNode::strip_child_indexes);
        }
    }

    /// A combination node, computing its bounds from the children.
    pub fn combine(combination: Combination, children: Vec<CsgNode>) -> CsgNode {
        let child_bounds: Vec<NodeBounds> = children.iter().map(CsgNode::bounds).collect();
        let bounds = match combination {
            Combination::Solid { inverted, .. } => {
                let surface = child_bounds
                    .iter()
                    .try_fold(Aabb::EMPTY, |all, b| Some(all.union(&b.surface?)));
                if inverted {
                    NodeBounds {
                        surface,
                        inside: None,
                        outside: surface,
                    }
                } else {
                    NodeBounds {
                        surface,
                        inside: surface,
                        outside: None,
                    }
                }
            }
            Combination::Union | Combination::Merge => NodeBounds {
                surface: child_bounds
                    .iter()
                    .try_fold(Aabb::EMPTY, |all, b| Some(all.union(&b.surface?))),
                inside: child_bounds
                    .iter()
                    .try_fold(Aabb::EMPTY, |all, b| Some(all.union(&b.inside?))),
                // Outside a union only where outside every child.
                outside: child_bounds
                    .iter()
                    .fold(None, |all, b| overlap(all, b.outside)),
            },
            Combination::Clip | Combination::InvertedClip => {
                let clips = child_bounds
                    .iter()
                    .skip(1)
                    .fold(None, |all, b| overlap(all, b.inside));
                let first = child_bounds.first().copied().unwrap_or(NodeBounds {
                    surface: Some(Aabb::EMPTY),
                    inside: Some(Aabb::EMPTY),
                    outside: None,
                });
                let clip = combination == Combination::Clip;
                NodeBounds {
                    surface: overlap(first.surface, clips),
                    inside: if clip {
                        overlap(first.inside, clips)
                    } else {
                        None
                    },
                    // Outside a clipped object where outside the object or any clip.
                    outside: if clip {
                        child_bounds
                            .iter()
                            .try_fold(Aabb::EMPTY, |all, b| Some(all.union(&b.outside?)))
                    } else {
                        None
                    },
                }
            }
            Combination::Intersection => {
                // A child's surface survives only inside every other child.
                let mut inside_before = Vec::with_capacity(child_bounds.len() + 1);
                inside_before.push(None);
                for bounds in &child_bounds {
                    let last = *inside_before.last().unwrap_or(&None);
                    inside_before.push(overlap(last, bounds.inside));
                }
                let mut inside_after = None;
                let mut surface = Some(Aabb::EMPTY);
                for (position, bounds) in child_bounds.iter().enumerate().rev() {
                    let others = overlap(inside_before[position], inside_after);
                    surface = join(surface, overlap(bounds.surface, others));
                    inside_after = overlap(inside_after, bounds.inside);
                }
                // Unbounded planes and quadrics cut the region down further.
                let region = bounded_by_quadrics(&children, &child_bounds);
                NodeBounds {
                    surface: overlap(surface, region),
                    inside: overlap(inside_after, region),
                    // Outside an intersection where outside any child.
                    outside: child_bounds
                        .iter()
                        .try_fold(Aabb::EMPTY, |all, b| Some(all.union(&b.outside?))),
                }
            }
        };
        let bounds = NodeBounds {
            surface: bounds.surface.map(canonical_empty),
            inside: bounds.inside.map(canonical_empty),
            outside: bounds.outside.map(canonical_empty),
        };
        let index = ChildIndex::new(combination, &child_bounds).map(Box::new);
        CsgNode::Combine {
            combination,
            children,
            bounds,
            index,
        }
    }
}

/// A box holding every point that lies inside all of an intersection's `children` but at
/// most one flat one (a triangle or mesh has no inside, yet its surface inside the others
/// survives), found by cutting the overlap of the other children's boxes down by the children
/// that are unbounded planes or quadrics; `None` when that gives no bound.
fn bounded_by_quadrics(children: &[CsgNode], child_bounds: &[NodeBounds]) -> Option<Aabb> {
    let quadrics: Vec<&InsideQuadric> = children
        .iter()
        .filter_map(|child| match child {
            CsgNode::Leaf {
                inside_quadric: Some(quadric),
                ..
            } => Some(&**quadric),
            _ => None,
        })
        .collect();
    if quadrics.is_empty() {
        return None;
    }
    let start = child_bounds
        .iter()
        .filter_map(|bounds| bounds.inside.filter(|inside| !inside.is_empty()))
        .fold(None, |all, inside| overlap(all, Some(inside)));
    let mut corners = start.map_or((DVec3::NEG_INFINITY, DVec3::INFINITY), |r| (r.min, r.max));
    // Each cut can let another cut further: a few rounds reach the box in practice.
    for _ in 0..3 {
        for quadric in &quadrics {
            match quadric.tighten(corners) {
                Some(tighter) => corners = tighter,
                None => return Some(Aabb::EMPTY),
            }
        }
    }
    let found = Aabb::from_corners(corners.0, corners.1);
    found.is_finite().then_some(found)
}

/// The overlap of two regions, where `None` stands for all of space.
fn overlap(first: Option<Aabb>, second: Option<Aabb>) -> Option<Aabb> {
    match (first, second) {
        (Some(first), Some(second)) => Some(first.intersection(&second)),
        (first, second) => first.or(second),
    }
}

/// The union of two regions, where `None` stands for all of space.
fn join(first: Option<Aabb>, second: Option<Aabb>) -> Option<Aabb> {
    Some(first?.union(&second?))
}

/// A box whose min exceeds its max on some axis, made canonical so it reads as empty.
fn canonical_empty(bounds: Aabb) -> Aabb {
    if bounds.is_empty() {
        Aabb::EMPTY
    } else {
        bounds
    }
}

/// One surface hit gathered while evaluating a CSG tree.
#[derive(Clone, Copy, Debug)]
pub struct CsgHit {
    /// Ray parameter of the hit.
    pub distance: f64,
    /// Position of the hit leaf in [`CsgTree::leaves`].
    pub leaf: u32,
    /// Surface part tag from the leaf's shape.
    pub part: u8,
}

/// Per-thread scratch reused by every ray, so no ray allocates once the vectors have grown.
#[derive(Default)]
struct Scratch {
    /// Surface hits gathered so far.
    hits: Vec<CsgHit>,
    /// A stack of candidate child lists of the wide nodes being gathered.
    candidates: Vec<u32>,
}

thread_local! {
    static SCRATCH: RefCell<Scratch> = RefCell::new(Scratch::default());
}

/// A whole CSG object: its leaves and the node tree over them.
#[derive(Clone, Debug)]
pub struct CsgTree {
    /// Every leaf primitive of the tree.
    pub leaves: Vec<Leaf>,
    /// The root node.
    pub root: CsgNode,
    /// POV-Ray's bounding box of the whole object: rays missing it miss the object, even where
    /// the box is smaller than the surface (inverted CSG). `None` when infinite.
    pub clip: Option<Aabb>,
    /// The box of the object's `bounded_by` objects where POV-Ray keeps it: rays missing it
    /// miss the object, except shadow rays, which ignore it (as POV-Ray's shadows do).
    pub bound: Option<Aabb>,
}

/// What a ray query needs beyond the ray itself.
struct Query<'a> {
    ray: &'a Ray,
    inverse_direction: DVec3,
    min_distance: f64,
    max_distance: f64,
}

impl CsgTree {
    /// The nearest surviving hit strictly between the limits.
    ///
    /// `keep` can reject hits (by leaf) after CSG filtering, for example to ignore shadowless
    /// leaves; `shadow` rays ignore the `bounded_by` box.
    pub fn nearest(
        &self,
        ray: &Ray,
        inverse_direction: DVec3,
        (min_distance, max_distance): (f64, f64),
        shadow: bool,
        keep: impl Fn(&Leaf) -> bool,
    ) -> Option<CsgHit> {
        let bound = self.bound.filter(|_| !shadow);
        for bounds in self.clip.iter().chain(&bound) {
            bounds.ray_entry(ray.origin, inverse_direction, 0.0, f64::INFINITY)?;
        }
        let query = Query {
            ray,
            inverse_direction,
            min_distance,
            max_distance,
        };
        let search = |scratch: &mut Scratch| {
            let Scratch { hits, candidates } = scratch;
            hits.clear();
            candidates.clear();
            self.gather(&self.root, &query, hits, candidates);
            let mut best: Option<CsgHit> = None;
            // Among hits at exactly the same distance the later child wins, as in POV-Ray.
            for hit in hits.iter() {
                if best.is_none_or(|nearest| hit.distance <= nearest.distance)
                    && keep(&self.leaves[hit.leaf as usize])
                {
                    best = Some(*hit);
                }
            }
            best
        };
        SCRATCH.with(|scratch| match scratch.try_borrow_mut() {
            Ok(mut scratch) => search(&mut scratch),
            Err(_) => search(&mut Scratch::default()),
        })
    }

    /// Appends the surviving hits of `node` within the query's limits to `hits`.
    ///
    /// `candidates` is scratch: each wide node pushes the children the ray can reach, in
    /// order, and pops them again before returning.
    fn gather(
        &self,
        node: &CsgNode,
        query: &Query,
        hits: &mut Vec<CsgHit>,
        candidates: &mut Vec<u32>,
    ) {
        if let Some(surface) = node.bounds().surface {
            let entry = surface.ray_entry(
                query.ray.origin,
                query.inverse_direction,
                query.min_distance,
                query.max_distance,
            );
            if entry.is_none() {
                return;
            }
        }
        match node {
            CsgNode::Leaf { index, .. } => {
                let leaf = &self.leaves[*index as usize];
                let mut roots = Roots::new();
                leaf.intersect(query.ray, &mut roots);
                for (distance, part) in roots.iter() {
                    if distance > query.min_distance && distance < query.max_distance {
                        hits.push(CsgHit {
                            distance,
                            leaf: *index,
                            part,
                        });
                    }
                }
            }
            CsgNode::Combine {
                combination,
                children,
                index: None,
                ..
            } => {
                for position in 0..children.len() {
                    self.gather_child(
                        *combination,
                        children,
                        None,
                        position,
                        query,
                        hits,
                        candidates,
                    );
                }
            }
            CsgNode::Combine {
                combination,
                children,
                index: Some(index),
                ..
            } => {
                let start = candidates.len();
                index.surface.for_each_on_ray(
                    query.ray.origin,
                    query.inverse_direction,
                    query.min_distance,
                    query.max_distance,
                    |position| candidates.push(index.surface_children[position]),
                );
                candidates.extend_from_slice(&index.unbounded_surface);
                // Children in their written order: among equally near hits the later wins.
                candidates[start..].sort_unstable();
                let end = candidates.len();
                for slot in start..end {
                    let position = candidates[slot] as usize;
                    self.gather_child(
                        *combination,
                        children,
                        Some(index),
                        position,
                        query,
                        hits,
                        candidates,
                    );
                }
                candidates.truncate(start);
            }
        }
    }

    /// Gathers the hits of child `position` of a combination and keeps those its siblings
    /// let through.
    #[allow(clippy::too_many_arguments)]
    fn gather_child(
        &self,
        combination: Combination,
        children: &[CsgNode],
        index: Option<&ChildIndex>,
        position: usize,
        query: &Query,
        hits: &mut Vec<CsgHit>,
        candidates: &mut Vec<u32>,
    ) {
        let clipping = matches!(combination, Combination::Clip | Combination::InvertedClip);
        if clipping && position > 0 {
            // The clipping objects' own surfaces are never seen.
            return;
        }
        let child_start = hits.len();
        self.gather(&children[position], query, hits, candidates);
        if matches!(combination, Combination::Union | Combination::Solid { .. }) {
            return;
        }
        let mut kept = child_start;
        for slot in child_start..hits.len() {
            let hit = hits[slot];
            let point = query.ray.at(hit.distance);
            let inside =
                |other: usize| other != position && self.inside_node(&children[other], point);
            let outside =
                |other: usize| other != position && !self.inside_node(&children[other], point);
            let survives = match (combination, index) {
                (Combination::Merge, Some(index)) => !index.any_filtered(point, inside),
                (Combination::Merge, None) => !(0..children.len()).any(inside),
                (_, Some(index)) => !index.any_filtered(point, outside),
                (_, None) => !(0..children.len()).any(outside),
            };
            if survives {
                hits[kept] = hit;
                kept += 1;
            }
        }
        hits.truncate(kept);
    }

    /// True when the world `point` is inside the whole object.
    pub fn inside(&self, point: DVec3) -> bool {
        self.inside_node(&self.root, point)
    }

    /// True when a ray from `point` along `direction` crosses the surfaces of `children` (a
    /// mesh's triangles) an odd number of times.
    fn odd_crossings(
        &self,
        children: &[CsgNode],
        index: Option<&ChildIndex>,
        point: DVec3,
        direction: DVec3,
    ) -> bool {
        let ray = Ray::new(point, direction);
        let mut odd = false;
        let mut count = |child: usize| {
            if let Some(CsgNode::Leaf { index, .. }) = children.get(child) {
                let mut roots = Roots::new();
                self.leaves[*index as usize].intersect(&ray, &mut roots);
                for (distance, _) in roots.iter() {
                    if distance > SOLID_EPSILON {
                        odd = !odd;
                    }
                }
            }
        };
        match index {
            Some(index) => {
                index.surface.for_each_on_ray(
                    point,
                    direction.recip(),
                    0.0,
                    f64::INFINITY,
                    |position| count(index.surface_children[position] as usize),
                );
                index
                    .unbounded_surface
                    .iter()
                    .for_each(|&child| count(child as usize));
            }
            None => (0..children.len()).for_each(&mut count),
        }
        odd
    }

    /// True when the world `point` is inside the subtree `node`.
    fn inside_node(&self, node: &CsgNode, point: DVec3) -> bool {
        let bounds = node.bounds();
        if let Some(inside) = bounds.inside {
            if !inside.contains(point) {
                return false;
            }
        }
        if let Some(outside) = bounds.outside {
            if !outside.contains(point) {
                return true;
            }
        }
        match node {
            CsgNode::Leaf { index, .. } => self.leaves[*index as usize].inside(point),
            CsgNode::Combine {
                combination,
                children,
                index,
                ..
            } => match (combination, index) {
                (
                    Combination::Solid {
                        direction,
                        inverted,
                    },
                    index,
                ) => self.odd_crossings(children, index.as_deref(), point, *direction) != *inverted,
                (Combination::InvertedClip, _) => {
                    let mut parts = children.iter();
                    let first_inside = parts
                        .next()
                        .is_some_and(|first| self.inside_node(first, point));
                    first_inside || !parts.all(|clip| self.inside_node(clip, point))
                }
                (Combination::Intersection | Combination::Clip, Some(index)) => {
                    !index.any_filtered(point, |child| !self.inside_node(&children[child], point))
                }
                (Combination::Intersection | Combination::Clip, None) => {
                    children.iter().all(|child| self.inside_node(child, point))
                }
                (Combination::Union | Combination::Merge, Some(index)) => {
                    index.any_filtered(point, |child| self.inside_node(&children[child], point))
                }
                (Combination::Union | Combination::Merge, None) => {
                    children.iter().any(|child| self.inside_node(child, point))
                }
            },
        }
    }
}
