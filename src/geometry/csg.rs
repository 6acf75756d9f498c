//! CSG trees evaluated per ray over their children's hit lists.
//!
//! In: a tree of [`Leaf`] primitives under union, intersection and merge nodes, with every
//! inversion already pushed down to the leaves (a difference arrives as an intersection whose
//! later children are inverted). Out: the nearest surviving surface hit of a ray, tagged with
//! the leaf it lies on, and inside tests for whole subtrees.
//! Holds: a node's hits are its children's hits filtered by the inside tests of the siblings
//! (intersection keeps hits inside all siblings, merge drops hits inside any sibling, union
//! keeps all); among hits at the same distance the later child's wins. An object may carry
//! POV-Ray's bounding box as a clip: rays missing it miss the object. Hits are gathered into
//! one per-thread scratch vector, so no ray allocates once the vector has grown.

use super::leaf::Leaf;
use super::roots::Roots;
use super::Ray;
use crate::accel::Aabb;
use glam::DVec3;
use std::cell::RefCell;

/// How a CSG node combines its children.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Combination {
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
    },
    /// A combination of child subtrees.
    Combine {
        /// How the children combine.
        combination: Combination,
        /// The child subtrees.
        children: Vec<CsgNode>,
        /// The node's bounds.
        bounds: NodeBounds,
    },
}

impl CsgNode {
    /// The node's world bounds.
    pub fn bounds(&self) -> NodeBounds {
        match self {
            CsgNode::Leaf { bounds, .. } | CsgNode::Combine { bounds, .. } => *bounds,
        }
    }

    /// A combination node, computing its bounds from the children.
    pub fn combine(combination: Combination, children: Vec<CsgNode>) -> CsgNode {
        let child_bounds: Vec<NodeBounds> = children.iter().map(CsgNode::bounds).collect();
        let bounds = match combination {
            Combination::Union | Combination::Merge => NodeBounds {
                surface: child_bounds
                    .iter()
                    .try_fold(Aabb::EMPTY, |all, b| Some(all.union(&b.surface?))),
                inside: child_bounds
                    .iter()
                    .try_fold(Aabb::EMPTY, |all, b| Some(all.union(&b.inside?))),
            },
            Combination::Clip | Combination::InvertedClip => {
                let clips = child_bounds
                    .iter()
                    .skip(1)
                    .fold(None, |all, b| overlap(all, b.inside));
                let first = child_bounds.first().copied().unwrap_or(NodeBounds {
                    surface: Some(Aabb::EMPTY),
                    inside: Some(Aabb::EMPTY),
                });
                NodeBounds {
                    surface: overlap(first.surface, clips),
                    inside: if combination == Combination::Clip {
                        overlap(first.inside, clips)
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
                NodeBounds {
                    surface,
                    inside: inside_after,
                }
            }
        };
        let bounds = NodeBounds {
            surface: bounds.surface.map(canonical_empty),
            inside: bounds.inside.map(canonical_empty),
        };
        CsgNode::Combine {
            combination,
            children,
            bounds,
        }
    }
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

thread_local! {
    /// Per-thread scratch for gathering CSG hits, reused by every ray.
    static SCRATCH: RefCell<Vec<CsgHit>> = const { RefCell::new(Vec::new()) };
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
    /// leaves.
    pub fn nearest(
        &self,
        ray: &Ray,
        inverse_direction: DVec3,
        min_distance: f64,
        max_distance: f64,
        keep: impl Fn(&Leaf) -> bool,
    ) -> Option<CsgHit> {
        if let Some(clip) = self.clip {
            clip.ray_entry(ray.origin, inverse_direction, 0.0, f64::INFINITY)?;
        }
        let query = Query {
            ray,
            inverse_direction,
            min_distance,
            max_distance,
        };
        let search = |hits: &mut Vec<CsgHit>| {
            hits.clear();
            self.gather(&self.root, &query, hits);
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
            Ok(mut hits) => search(&mut hits),
            Err(_) => search(&mut Vec::new()),
        })
    }

    /// Appends the surviving hits of `node` within the query's limits to `hits`.
    fn gather(&self, node: &CsgNode, query: &Query, hits: &mut Vec<CsgHit>) {
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
                ..
            } => {
                let clipping = matches!(combination, Combination::Clip | Combination::InvertedClip);
                for (position, child) in children.iter().enumerate() {
                    if clipping && position > 0 {
                        break;
                    }
                    let child_start = hits.len();
                    self.gather(child, query, hits);
                    if *combination == Combination::Union {
                        continue;
                    }
                    let mut kept = child_start;
                    for index in child_start..hits.len() {
                        let hit = hits[index];
                        let point = query.ray.at(hit.distance);
                        let mut siblings = children
                            .iter()
                            .enumerate()
                            .filter(|&(other, _)| other != position)
                            .map(|(_, sibling)| sibling);
                        let survives = match combination {
                            Combination::Intersection
                            | Combination::Clip
                            | Combination::InvertedClip => {
                                siblings.all(|sibling| self.inside_node(sibling, point))
                            }
                            _ => !siblings.any(|sibling| self.inside_node(sibling, point)),
                        };
                        if survives {
                            hits[kept] = hit;
                            kept += 1;
                        }
                    }
                    hits.truncate(kept);
                }
            }
        }
    }

    /// True when the world `point` is inside the whole object.
    pub fn inside(&self, point: DVec3) -> bool {
        self.inside_node(&self.root, point)
    }

    /// True when the world `point` is inside the subtree `node`.
    fn inside_node(&self, node: &CsgNode, point: DVec3) -> bool {
        if let Some(inside) = node.bounds().inside {
            if !inside.contains(point) {
                return false;
            }
        }
        match node {
            CsgNode::Leaf { index, .. } => self.leaves[*index as usize].inside(point),
            CsgNode::Combine {
                combination,
                children,
                ..
            } => match combination {
                Combination::Intersection | Combination::Clip => {
                    children.iter().all(|child| self.inside_node(child, point))
                }
                Combination::InvertedClip => {
                    let mut parts = children.iter();
                    let first_inside = parts
                        .next()
                        .is_some_and(|first| self.inside_node(first, point));
                    first_inside || !parts.all(|clip| self.inside_node(clip, point))
                }
                Combination::Union | Combination::Merge => {
                    children.iter().any(|child| self.inside_node(child, point))
                }
            },
        }
    }
}
