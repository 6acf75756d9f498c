//! CSG trees evaluated per ray over their children's hit lists.
//!
//! In: a tree of [`Leaf`] primitives under union, intersection and merge nodes (a difference
//! arrives as an intersection whose later children are inverted). Out: the nearest surviving
//! surface hit of a ray, tagged with the leaf it lies on and whether the normal is flipped, and
//! inside tests for whole subtrees.
//! Holds: a node's hits are its children's hits filtered by the inside tests of the siblings
//! (intersection keeps hits inside all siblings, merge drops hits inside any sibling, union
//! keeps all); an inverted node flips the normals of all its hits. Hits are gathered into one
//! per-thread scratch vector, so no ray allocates once the vector has grown.

use super::leaf::Leaf;
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
        /// Inside and outside swapped, normals flipped.
        inverse: bool,
        /// The child subtrees.
        children: Vec<CsgNode>,
        /// The node's bounds (inverse already applied).
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
    pub fn combine(combination: Combination, inverse: bool, children: Vec<CsgNode>) -> CsgNode {
        let mut child_bounds = children.iter().map(CsgNode::bounds);
        let surfaces_union = child_bounds.clone().try_fold(Aabb::EMPTY, |all, bounds| {
            bounds.surface.map(|b| all.union(&b))
        });
        let bounds = match combination {
            Combination::Union | Combination::Merge => NodeBounds {
                surface: surfaces_union,
                inside: child_bounds.try_fold(Aabb::EMPTY, |all, bounds| {
                    bounds.inside.map(|b| all.union(&b))
                }),
            },
            Combination::Intersection => {
                let inside = child_bounds.fold(None, |common: Option<Aabb>, bounds| {
                    match (common, bounds.inside) {
                        (Some(common), Some(inside)) => Some(common.intersection(&inside)),
                        (common, inside) => common.or(inside),
                    }
                });
                let surface = match (surfaces_union, inside) {
                    (Some(surface), Some(inside)) => Some(surface.intersection(&inside)),
                    (surface, inside) => surface.or(inside),
                };
                NodeBounds { surface, inside }
            }
        };
        let bounds = NodeBounds {
            surface: bounds.surface.map(empty_if_inverted),
            inside: if inverse {
                None
            } else {
                bounds.inside.map(empty_if_inverted)
            },
        };
        CsgNode::Combine {
            combination,
            inverse,
            children,
            bounds,
        }
    }
}

/// A box whose min exceeds its max on some axis, made canonical so it reads as empty.
fn empty_if_inverted(bounds: Aabb) -> Aabb {
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
    /// True when an odd number of inverted ancestors flip the leaf's normal.
    pub flip: bool,
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
            for hit in hits.iter() {
                if best.is_none_or(|nearest| hit.distance < nearest.distance)
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
                let mut roots = super::roots::Roots::new();
                leaf.intersect(query.ray, &mut roots);
                for (distance, part) in roots.iter() {
                    if distance > query.min_distance && distance < query.max_distance {
                        hits.push(CsgHit {
                            distance,
                            leaf: *index,
                            part,
                            flip: false,
                        });
                    }
                }
            }
            CsgNode::Combine {
                combination,
                inverse,
                children,
                ..
            } => {
                let start = hits.len();
                for (position, child) in children.iter().enumerate() {
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
                            Combination::Intersection => {
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
                if *inverse {
                    for hit in &mut hits[start..] {
                        hit.flip = !hit.flip;
                    }
                }
            }
        }
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
                inverse,
                children,
                ..
            } => {
                let inside = match combination {
                    Combination::Intersection => {
                        children.iter().all(|child| self.inside_node(child, point))
                    }
                    Combination::Union | Combination::Merge => {
                        children.iter().any(|child| self.inside_node(child, point))
                    }
                };
                inside != *inverse
            }
        }
    }
}
