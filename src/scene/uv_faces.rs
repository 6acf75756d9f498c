//! The faces of a uv-mapped mesh camera (distribution 3), indexed by their uv triangles.
//!
//! In: world-space faces with the uv coordinates of their corners. Out: [`UvFaces`], which
//! answers "the first face whose uv triangle holds this (u, v), and where in it". Holds:
//! faces keep the order they were written in (meshes in turn), and a lookup returns the
//! first of them that holds the point, as POV-Ray does; faces with a degenerate uv
//! triangle are dropped; a lookup does not allocate.

use glam::{DVec2, DVec3};

/// How far outside a uv triangle (in barycentric weight) a point still counts as inside,
/// so points on a shared edge find a face despite rounding.
const EDGE_TOLERANCE: f64 = 1e-9;

/// The most grid cells along each side of the uv index.
const MAX_GRID_SIDE: usize = 1024;

/// The uv index holds at most this many (cell, face) entries per face, unless it is a
/// single cell.
const MAX_ENTRIES_PER_FACE: usize = 16;

/// One face of a uv-mapped camera mesh, in world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UvFace {
    /// The corners.
    pub corners: [DVec3; 3],
    /// Unit normals at the corners, which `smooth` interpolates (a flat face's normal at
    /// each corner for a flat face).
    pub corner_normals: [DVec3; 3],
    /// Unit face normal: `(c − a) × (b − a)` for corners a, b, c.
    pub normal: DVec3,
    /// The corners' uv coordinates.
    pub uvs: [DVec2; 3],
}

/// A point found on a face: the face and the barycentric weights of its corners.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UvHit<'a> {
    /// The face holding the point.
    pub face: &'a UvFace,
    /// Weights of the corners (summing to 1).
    pub weights: [f64; 3],
}

impl UvHit<'_> {
    /// The point on the face.
    pub fn position(&self) -> DVec3 {
        let [a, b, c] = self.face.corners;
        a * self.weights[0] + b * self.weights[1] + c * self.weights[2]
    }

    /// The corner normals interpolated by the weights and normalised; the face normal when
    /// the interpolation cancels out.
    pub fn smooth_normal(&self) -> DVec3 {
        let [a, b, c] = self.face.corner_normals;
        (a * self.weights[0] + b * self.weights[1] + c * self.weights[2])
            .try_normalize()
            .unwrap_or(self.face.normal)
    }
}

/// Faces of a uv-mapped mesh camera with a grid over uv space listing, per cell, the faces
/// whose uv bounding box touches it (in face order).
#[derive(Clone, Debug, Default)]
pub struct UvFaces {
    faces: Vec<UvFace>,
    /// Lower corner of the grid in uv space.
    origin: DVec2,
    /// Size of one cell.
    cell: DVec2,
    /// Cells along u and along v.
    side: [usize; 2],
    /// For cell i, its faces are `cell_faces[cell_start[i]..cell_start[i + 1]]`.
    cell_start: Vec<u32>,
    cell_faces: Vec<u32>,
}

impl UvFaces {
    /// Indexes `faces` (in the order POV-Ray searches them); faces whose uv triangle has
    /// no area or non-finite coordinates are dropped.
    pub fn new(faces: Vec<UvFace>) -> UvFaces {
        let faces: Vec<UvFace> = faces
            .into_iter()
            .filter(|face| {
                let [a, b, c] = face.uvs;
                let area = (b - a).perp_dot(c - a);
                area.is_finite() && area != 0.0 && face.corners.iter().all(|p| p.is_finite())
            })
            .collect();
        if faces.is_empty() {
            return UvFaces::default();
        }
        let (mut low, mut high) = (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
        for face in &faces {
            for uv in face.uvs {
                low = low.min(uv);
                high = high.max(uv);
            }
        }
        let extent = (high - low).max(DVec2::splat(f64::MIN_POSITIVE));
        let mut index = UvFaces {
            faces,
            origin: low,
            ..UvFaces::default()
        };
        // A grid about as fine as the faces are many, made coarser while faces spanning
        // many cells would make the index much larger than the faces (down to one cell).
        let mut side_length =
            ((index.faces.len() as f64).sqrt().ceil() as usize).clamp(1, MAX_GRID_SIDE);
        let budget = index.faces.len().saturating_mul(MAX_ENTRIES_PER_FACE);
        loop {
            index.side = [side_length; 2];
            index.cell = extent / side_length as f64;
            if side_length == 1 || index.entries() <= budget {
                break;
            }
            side_length /= 2;
        }
        let side = index.side;
        let mut per_cell: Vec<Vec<u32>> = vec![Vec::new(); side[0] * side[1]];
        for (number, face) in index.faces.iter().enumerate() {
            let [first, last] = index.cell_span(face);
            for v in first[1]..=last[1] {
                for u in first[0]..=last[0] {
                    per_cell[v * side[0] + u].push(number as u32);
                }
            }
        }
        index.cell_start.push(0);
        for faces in per_cell {
            index.cell_faces.extend(faces);
            index.cell_start.push(index.cell_faces.len() as u32);
        }
        index
    }

    /// The first and last grid cells a face's uv bounding box touches.
    fn cell_span(&self, face: &UvFace) -> [[usize; 2]; 2] {
        let [a, b, c] = face.uvs;
        [self.cell_of(a.min(b).min(c)), self.cell_of(a.max(b).max(c))]
    }

    /// How many (cell, face) entries the grid would hold.
    fn entries(&self) -> usize {
        self.faces
            .iter()
            .map(|face| {
                let [first, last] = self.cell_span(face);
                (last[0] - first[0] + 1) * (last[1] - first[1] + 1)
            })
            .fold(0, usize::saturating_add)
    }

    /// Whether there are no faces.
    pub fn is_empty(&self) -> bool {
        self.faces.is_empty()
    }

    /// The grid cell (column, row) holding `uv`, clamped to the grid.
    fn cell_of(&self, uv: DVec2) -> [usize; 2] {
        let relative = (uv - self.origin) / self.cell;
        let clamp = |value: f64, side: usize| {
            if value.is_nan() || value <= 0.0 {
                0
            } else {
                (value as usize).min(side - 1)
            }
        };
        [
            clamp(relative.x, self.side[0]),
            clamp(relative.y, self.side[1]),
        ]
    }

    /// The first face whose uv triangle holds `uv` (edges included), with the weights.
    pub fn find(&self, uv: DVec2) -> Option<UvHit<'_>> {
        if self.faces.is_empty() || !uv.is_finite() {
            return None;
        }
        let [u, v] = self.cell_of(uv);
        let cell = v * self.side[0] + u;
        let range = self.cell_start[cell] as usize..self.cell_start[cell + 1] as usize;
        self.cell_faces[range].iter().find_map(|&number| {
            let face = &self.faces[number as usize];
            let weights = barycentric(face.uvs, uv)?;
            Some(UvHit { face, weights })
        })
    }
}

/// The barycentric weights of `point` in the triangle `corners`, if it lies inside.
fn barycentric(corners: [DVec2; 3], point: DVec2) -> Option<[f64; 3]> {
    let [a, b, c] = corners;
    let area = (b - a).perp_dot(c - a);
    let weight_b = (point - a).perp_dot(c - a) / area;
    let weight_c = (b - a).perp_dot(point - a) / area;
    let weight_a = 1.0 - weight_b - weight_c;
    let inside = [weight_a, weight_b, weight_c]
        .iter()
        .all(|&w| w >= -EDGE_TOLERANCE);
    inside.then_some([weight_a, weight_b, weight_c])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A face whose corners sit at `(u, v, 0)` times 10 of its uv coordinates.
    fn face(uvs: [DVec2; 3]) -> UvFace {
        UvFace {
            corners: uvs.map(|uv| (uv * 10.0).extend(0.0)),
            corner_normals: [DVec3::Z; 3],
            normal: DVec3::Z,
            uvs,
        }
    }

    #[test]
    fn finds_the_point_on_the_face_holding_it() {
        let faces = UvFaces::new(vec![
            face([DVec2::ZERO, DVec2::X, DVec2::ONE]),
            face([DVec2::ZERO, DVec2::ONE, DVec2::Y]),
        ]);
        let hit = faces.find(DVec2::new(0.25, 0.75)).unwrap();
        assert!((hit.position() - DVec3::new(2.5, 7.5, 0.0)).length() < 1e-12);
        assert!(faces.find(DVec2::new(1.5, 0.5)).is_none());
        // On the shared diagonal the first face wins.
        let edge = faces.find(DVec2::splat(0.5)).unwrap();
        assert_eq!(edge.face.uvs[1], DVec2::X);
    }

    #[test]
    fn faces_spanning_the_whole_range_keep_the_index_small() {
        // Every face covers the whole uv range: a fine grid would list each in every cell.
        let faces: Vec<_> = (0..400)
            .map(|_| face([DVec2::ZERO, DVec2::X * 2.0, DVec2::Y * 2.0]))
            .chain([face([DVec2::ONE, DVec2::ONE * 1.5, DVec2::new(1.0, 1.5)])])
            .collect();
        let index = UvFaces::new(faces);
        assert!(index.cell_faces.len() <= 401 * MAX_ENTRIES_PER_FACE);
        assert!(index.find(DVec2::splat(0.5)).is_some());
    }

    #[test]
    fn degenerate_faces_are_dropped() {
        let faces = UvFaces::new(vec![face([DVec2::ZERO, DVec2::X, DVec2::X * 2.0])]);
        assert!(faces.is_empty());
        assert!(faces.find(DVec2::ZERO).is_none());
    }

    #[test]
    fn smooth_normals_interpolate_by_weight() {
        let mut smooth = face([DVec2::ZERO, DVec2::X, DVec2::Y]);
        smooth.corner_normals = [DVec3::Z, DVec3::Z, DVec3::Y];
        let faces = UvFaces::new(vec![smooth]);
        let hit = faces.find(DVec2::new(0.0, 0.5)).unwrap();
        let expected = DVec3::new(0.0, 0.5, 0.5).normalize();
        assert!((hit.smooth_normal() - expected).length() < 1e-12);
    }
}
