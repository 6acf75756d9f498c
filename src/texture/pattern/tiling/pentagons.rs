//! `tiling 25`: Penrose's aperiodic tiling of pentagons, stars, boats and diamonds (his
//! first one, "P1"), bevelled towards its tiles' edges like the other tilings.
//!
//! In: a point (x, z) of the plane. Out: the value in [0, 1]. Holds: no tables but the
//! tiling's constants; no allocation, and the work per value grows with the logarithm of the
//! point's distance from the origin.
//!
//! What was measured (probe scenes against POV-Ray 3.7, `pigment { tiling 25 }` through a
//! black-to-white colour map): the tiling has a pentagon with unit edges at the origin, one
//! corner towards −x, and the full five-fold symmetry about it. Its six tile types are three
//! kinds of pentagon (told apart by how they split, below: 0 is the kind at the centre of a
//! split pentagon, 1 and 2 the other two), 3 stars, 4 boats (three points of a star) and
//! 5 diamonds (thin rhombs with 36° corners), all with unit edges; every type has the same
//! bevel width.
//!
//! How a value is found: the tiling is what is left after splitting ("deflating") a large
//! pentagon again and again. A split scales by 1/φ² and turns each kind of tile into its
//! own arrangement of smaller tiles (the well-known substitution of the P1 tiling); the
//! arrangements reach a little past their tile, and neighbours make the tiles on their
//! shared edges twice. So a point is followed down from a pentagon round the origin large
//! enough to hold it, keeping at every level the few tiles whose offspring can reach the
//! point, until the level of unit tiles, where the tile holding the point is picked.

use glam::DVec2;

use super::penrose::{ORIGIN_RADIUS, PHI};

/// The number of tile types.
const TYPES: f64 = 6.0;

/// The width over which a tile's value rises towards its edges (measured: the slope of the
/// values across edges, the same in every tile type).
const BEVEL: f64 = 0.291_537_7;

/// The most tiles kept at one level (measured: at most 5 were kept at any of 1500 random
/// points from 0.1 to 10⁵ units out; the tests check a spiral of points).
const MAX_KEPT: usize = 16;

/// The most tiles one tile splits into (a star and a type-0 pentagon make 11).
const MAX_CHILDREN: usize = 11;

/// A direction turned by a whole number of tenths of a turn, from its cosine and sine.
#[derive(Clone, Copy)]
struct Turn(DVec2);

/// 36°.
const TURN_36: Turn = Turn(DVec2::new(0.809_016_994_374_947_5, 0.587_785_252_292_473_1));
/// 72°.
const TURN_72: Turn = Turn(DVec2::new(
    0.309_016_994_374_947_45,
    0.951_056_516_295_153_5,
));
/// 18°.
const TURN_18: Turn = Turn(DVec2::new(
    0.951_056_516_295_153_5,
    0.309_016_994_374_947_45,
));
/// 54°.
const TURN_54: Turn = Turn(DVec2::new(0.587_785_252_292_473_1, 0.809_016_994_374_947_5));
/// 108°.
const TURN_108: Turn = Turn(DVec2::new(
    -0.309_016_994_374_947_45,
    0.951_056_516_295_153_5,
));

impl Turn {
    /// The opposite turn.
    const fn back(self) -> Self {
        Self(DVec2::new(self.0.x, -self.0.y))
    }
}

/// `point` turned about `centre`.
fn turned(centre: DVec2, point: DVec2, turn: Turn) -> DVec2 {
    centre + turn.0.rotate(point - centre)
}

/// The point a fraction `t` of the way from `from` to `to`.
fn between(from: DVec2, to: DVec2, t: f64) -> DVec2 {
    from + (to - from) * t
}

/// 1/φ², the scale of a split, and the share of an edge its corner's smaller tile takes.
const SPLIT: f64 = 0.381_966_011_250_105_1;

/// The kinds of tile, in the order of their types.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Shape {
    /// Type 0: the pentagon at the centre of every split pentagon.
    CentrePentagon,
    /// Type 1: the pentagon a diamond, boat or star splits into.
    OuterPentagon,
    /// Type 2: the pentagon on the corners of a type-0 pentagon's split.
    CornerPentagon,
    /// Type 3: a five-pointed star.
    Star,
    /// Type 4: three neighbouring points of a star.
    Boat,
    /// Type 5: a rhomb with 36° and 144° corners.
    Diamond,
}

/// A tile: its shape, a corner ("apex": a pentagon's, or a sharp point of the others) and
/// the two corners next to it, the left one first counter-clockwise; which corner is the
/// apex fixes how the tile splits.
#[derive(Clone, Copy, Debug)]
struct Tile {
    shape: Shape,
    apex: DVec2,
    left: DVec2,
    right: DVec2,
}

/// The ten corners of a star (a boat uses the first seven): the apex point, the notches
/// either side of it, the next points, the notches beyond them and the two far points with
/// the notch between them.
struct StarCorners {
    apex: DVec2,
    left_notch: DVec2,
    right_notch: DVec2,
    left_point: DVec2,
    right_point: DVec2,
    far_left_notch: DVec2,
    far_right_notch: DVec2,
    far_left_point: DVec2,
    far_right_point: DVec2,
    far_notch: DVec2,
}

impl StarCorners {
    /// The five points, counter-clockwise from the apex.
    fn points(&self) -> [DVec2; 5] {
        [
            self.apex,
            self.left_point,
            self.far_left_point,
            self.far_right_point,
            self.right_point,
        ]
    }

    /// The notches either side of each point of `points`, in the same order.
    fn notches(&self) -> [(DVec2, DVec2); 5] {
        [
            (self.right_notch, self.left_notch),
            (self.left_notch, self.far_left_notch),
            (self.far_left_notch, self.far_notch),
            (self.far_notch, self.far_right_notch),
            (self.far_right_notch, self.right_notch),
        ]
    }

    /// The centre of the star.
    fn centre(&self) -> DVec2 {
        (self.left_notch
            + self.right_notch
            + self.far_left_notch
            + self.far_right_notch
            + self.far_notch)
            / 5.0
    }
}

impl Tile {
    /// A pentagon from its apex and left corner.
    fn pentagon(shape: Shape, apex: DVec2, left: DVec2) -> Self {
        let right = turned(apex, left, TURN_108);
        Self {
            shape,
            apex,
            left,
            right,
        }
    }

    /// A pentagon from its apex and right corner.
    fn pentagon_right(shape: Shape, apex: DVec2, right: DVec2) -> Self {
        let left = turned(apex, right, TURN_108.back());
        Self {
            shape,
            apex,
            left,
            right,
        }
    }

    /// A pentagon from the two corners next to its apex.
    fn pentagon_across(shape: Shape, left: DVec2, right: DVec2) -> Self {
        let apex = left + TURN_36.0.rotate(right - left) / PHI;
        Self {
            shape,
            apex,
            left,
            right,
        }
    }

    /// A diamond, boat or star from its apex point and the corner left of it.
    fn pointed(shape: Shape, apex: DVec2, left: DVec2) -> Self {
        let right = turned(apex, left, TURN_36);
        Self {
            shape,
            apex,
            left,
            right,
        }
    }

    /// A star from the two notches next to its apex point.
    fn star_across(left: DVec2, right: DVec2) -> Self {
        let apex = left + TURN_72.0.rotate(right - left) * PHI;
        Self {
            shape: Shape::Star,
            apex,
            left,
            right,
        }
    }

    /// The edge length.
    fn edge(&self) -> f64 {
        self.apex.distance(self.left)
    }

    /// A pentagon's corners counter-clockwise from the apex.
    fn pentagon_corners(&self) -> [DVec2; 5] {
        let after_left = turned(self.left, self.apex, TURN_108.back());
        let before_right = turned(self.right, self.apex, TURN_108);
        [self.apex, self.left, after_left, before_right, self.right]
    }

    /// A diamond's corners counter-clockwise from the apex.
    fn diamond_corners(&self) -> [DVec2; 4] {
        let far = self.left + self.right - self.apex;
        [self.apex, self.left, far, self.right]
    }

    /// The corners of the star this tile is (or is three points of).
    fn star_corners(&self) -> StarCorners {
        let left_point = turned(self.left, self.apex, TURN_108);
        let right_point = turned(self.right, self.apex, TURN_108.back());
        let far_left_notch = turned(left_point, self.left, TURN_36.back());
        let far_right_notch = turned(right_point, self.right, TURN_36);
        let far_left_point = turned(far_left_notch, left_point, TURN_108);
        let far_right_point = turned(far_right_notch, right_point, TURN_108.back());
        let far_notch = turned(far_left_point, far_left_notch, TURN_36.back());
        StarCorners {
            apex: self.apex,
            left_notch: self.left,
            right_notch: self.right,
            left_point,
            right_point,
            far_left_notch,
            far_right_notch,
            far_left_point,
            far_right_point,
            far_notch,
        }
    }

    /// The centre the reach of the tile's offspring is measured from: a pentagon's or
    /// star's centre (a boat's star's), a diamond's middle.
    fn centre(&self) -> DVec2 {
        let along_left = self.left - self.apex;
        match self.shape {
            // The centre lies on the apex corner's bisector, the circumradius (1 / (2 sin
            // 36°) edges) from the apex, or for a star its points' radius (tan 54° edges).
            Shape::CentrePentagon | Shape::OuterPentagon | Shape::CornerPentagon => {
                self.apex + TURN_54.0.rotate(along_left) * (0.5 / TURN_36.0.y)
            }
            Shape::Star | Shape::Boat => {
                self.apex + TURN_18.0.rotate(along_left) * (TURN_54.0.y / TURN_54.0.x)
            }
            Shape::Diamond => (self.left + self.right) / 2.0,
        }
    }

    /// How far (in edge lengths) from its centre the tiles this one splits into, and
    /// theirs in turn, can reach, with a margin for rounding (measured over six splits of
    /// each kind: a type-0 or type-2 pentagon 1.0515, a type-1 pentagon 0.8828, a diamond
    /// 0.9511 and a star or boat 1.3764, the last three their own corners' distances).
    fn reach(&self) -> f64 {
        let measured = match self.shape {
            Shape::CentrePentagon | Shape::CornerPentagon => 1.0515,
            Shape::OuterPentagon => 0.8828,
            Shape::Diamond => 0.9511,
            Shape::Star | Shape::Boat => 1.3764,
        };
        measured + 0.01
    }

    /// The tiles one split makes of this one, scaled by 1/φ² (`None` pads the list).
    fn split(&self) -> [Option<Tile>; MAX_CHILDREN] {
        let mut children = [None; MAX_CHILDREN];
        let mut count = 0;
        let mut add = |tile: Tile| {
            children[count] = Some(tile);
            count += 1;
        };
        // A diamond across the middle of a pentagon's edge from `corner` to `next`.
        let diamond_on_edge = |corner: DVec2, next: DVec2| {
            let near = between(corner, next, SPLIT);
            Tile::pointed(Shape::Diamond, turned(near, corner, TURN_108.back()), near)
        };
        // The type-0 pentagon in the middle of a pentagon with `corners`.
        let centre_pentagon = |corners: &[DVec2; 5]| {
            let [_, _, c3, c4, c2] = *corners;
            let apex = turned(between(c3, c4, SPLIT), c3, TURN_108.back());
            let left = turned(between(c4, c2, SPLIT), c4, TURN_108.back());
            Tile::pentagon(Shape::CentrePentagon, apex, left)
        };
        match self.shape {
            Shape::CentrePentagon => {
                let corners = self.pentagon_corners();
                for (i, &corner) in corners.iter().enumerate() {
                    let next = corners[(i + 1) % 5];
                    let near = between(corner, next, SPLIT);
                    add(Tile::pentagon(Shape::CornerPentagon, corner, near));
                    add(diamond_on_edge(corner, next));
                }
                add(centre_pentagon(&corners));
            }
            Shape::CornerPentagon => {
                let corners = self.pentagon_corners();
                let [c0, c1, c3, c4, c2] = corners;
                add(Tile::pentagon(
                    Shape::CornerPentagon,
                    c0,
                    between(c0, c1, SPLIT),
                ));
                add(Tile::pentagon(
                    Shape::CornerPentagon,
                    c1,
                    between(c1, c3, SPLIT),
                ));
                add(Tile::pentagon(
                    Shape::OuterPentagon,
                    between(c3, c1, SPLIT),
                    c3,
                ));
                add(Tile::pentagon_right(
                    Shape::OuterPentagon,
                    between(c4, c2, SPLIT),
                    c4,
                ));
                add(Tile::pentagon(
                    Shape::CornerPentagon,
                    c2,
                    between(c2, c0, SPLIT),
                ));
                add(diamond_on_edge(c0, c1));
                add(diamond_on_edge(c2, c0));
                add(centre_pentagon(&corners));
            }
            Shape::OuterPentagon => {
                let corners = self.pentagon_corners();
                let [c0, c1, c3, c4, c2] = corners;
                add(Tile::pentagon(
                    Shape::CornerPentagon,
                    c0,
                    between(c0, c1, SPLIT),
                ));
                add(Tile::pentagon(
                    Shape::OuterPentagon,
                    between(c1, c0, SPLIT),
                    c1,
                ));
                add(Tile::pentagon_right(
                    Shape::OuterPentagon,
                    between(c3, c4, SPLIT),
                    c3,
                ));
                add(Tile::pentagon(
                    Shape::OuterPentagon,
                    between(c4, c3, SPLIT),
                    c4,
                ));
                add(Tile::pentagon_right(
                    Shape::OuterPentagon,
                    between(c2, c0, SPLIT),
                    c2,
                ));
                add(centre_pentagon(&corners));
            }
            Shape::Diamond => {
                let [apex, left, far, right] = self.diamond_corners();
                add(Tile::pentagon_across(Shape::OuterPentagon, right, left));
                add(Tile::pointed(Shape::Boat, apex, between(apex, left, SPLIT)));
                add(Tile::pointed(Shape::Star, far, between(far, right, SPLIT)));
            }
            Shape::Star | Shape::Boat => {
                let star = self.star_corners();
                // The boat at each of the tile's points, the star in the middle and the
                // pentagons in its notches; a boat lacks the two far points and the notch
                // between them.
                let mut boat_at = |point: DVec2, toward: DVec2| {
                    add(Tile::pointed(
                        Shape::Boat,
                        point,
                        between(point, toward, SPLIT),
                    ))
                };
                boat_at(star.apex, star.left_notch);
                boat_at(star.left_point, star.far_left_notch);
                boat_at(star.right_point, star.right_notch);
                if self.shape == Shape::Star {
                    boat_at(star.far_left_point, star.far_notch);
                    boat_at(star.far_right_point, star.far_right_notch);
                }
                add(Tile::star_across(
                    between(star.far_right_notch, star.far_left_notch, SPLIT),
                    between(star.far_left_notch, star.far_right_notch, SPLIT),
                ));
                let notch_pentagon =
                    |left, right| Tile::pentagon_across(Shape::OuterPentagon, left, right);
                add(notch_pentagon(star.right_notch, star.left_notch));
                add(notch_pentagon(star.left_notch, star.far_left_notch));
                add(notch_pentagon(star.far_right_notch, star.right_notch));
                if self.shape == Shape::Star {
                    add(notch_pentagon(star.far_left_notch, star.far_notch));
                    add(notch_pentagon(star.far_notch, star.far_right_notch));
                }
            }
        }
        children
    }

    /// How far inside the tile `point` is: positive inside, negative outside (the
    /// smallest signed distance to the edges of the convex piece it is deepest in).
    fn insideness(&self, point: DVec2) -> f64 {
        match self.shape {
            Shape::CentrePentagon | Shape::OuterPentagon | Shape::CornerPentagon => {
                convex_insideness(&self.pentagon_corners(), point)
            }
            Shape::Diamond => convex_insideness(&self.diamond_corners(), point),
            Shape::Star | Shape::Boat => {
                let star = self.star_corners();
                // The middle: the inner pentagon, or for a boat the part of it on this
                // side of the line between its two far notches.
                let middle = if self.shape == Shape::Star {
                    convex_insideness(
                        &[
                            star.right_notch,
                            star.left_notch,
                            star.far_left_notch,
                            star.far_notch,
                            star.far_right_notch,
                        ],
                        point,
                    )
                } else {
                    convex_insideness(
                        &[
                            star.right_notch,
                            star.left_notch,
                            star.far_left_notch,
                            star.far_right_notch,
                        ],
                        point,
                    )
                };
                let points = if self.shape == Shape::Star { 5 } else { 3 };
                // A boat's points are the first, second and last of the star's.
                let boat_points = [0, 1, 4];
                (0..points)
                    .map(|i| {
                        let index = if self.shape == Shape::Star {
                            i
                        } else {
                            boat_points[i]
                        };
                        let (before, after) = star.notches()[index];
                        convex_insideness(&[before, star.points()[index], after], point)
                    })
                    .fold(middle, f64::max)
            }
        }
    }

    /// The distance from `point` (inside the tile) to the edges the bevel is measured
    /// from: for a convex tile the nearest line through an edge; for a star the lines
    /// through the two edges of the point whose direction from the centre is nearest
    /// the point's; for a boat those of its own points, or of the edges next to its base
    /// where a missing point's direction is nearest, and the line through the base
    /// (measured: POV-Ray's values follow these lines, not the edges' ends).
    fn edge_distance(&self, point: DVec2) -> f64 {
        match self.shape {
            Shape::CentrePentagon | Shape::OuterPentagon | Shape::CornerPentagon => {
                nearest_edge_line(&self.pentagon_corners(), point)
            }
            Shape::Diamond => nearest_edge_line(&self.diamond_corners(), point),
            Shape::Star | Shape::Boat => {
                let star = self.star_corners();
                let centre = star.centre();
                let points = star.points();
                let nearest = (0..5)
                    .max_by(|&a, &b| {
                        let along = |i: usize| (points[i] - centre).dot(point - centre);
                        along(a).total_cmp(&along(b))
                    })
                    .unwrap_or(0);
                let point_lines = |index: usize| {
                    let (before, after) = star.notches()[index];
                    line_distance(point, before, points[index]).min(line_distance(
                        point,
                        points[index],
                        after,
                    ))
                };
                if self.shape == Shape::Star {
                    return point_lines(nearest);
                }
                let base = line_distance(point, star.far_left_notch, star.far_right_notch);
                let sides = match nearest {
                    0 | 1 | 4 => point_lines(nearest),
                    _ => line_distance(point, star.left_point, star.far_left_notch)
                        .min(line_distance(point, star.far_right_notch, star.right_point)),
                };
                base.min(sides)
            }
        }
    }
}

/// The smallest signed distance from `point` to the sides of the convex polygon `corners`
/// (either winding), positive inside.
fn convex_insideness(corners: &[DVec2], point: DVec2) -> f64 {
    let count = corners.len();
    let orientation = (corners[1] - corners[0])
        .perp_dot(corners[2] - corners[1])
        .signum();
    (0..count)
        .map(|i| {
            let from = corners[i];
            let side = corners[(i + 1) % count] - from;
            orientation * side.perp_dot(point - from) / side.length()
        })
        .fold(f64::INFINITY, f64::min)
}

/// The distance from `point` to the nearest line through a side of the polygon `corners`.
fn nearest_edge_line(corners: &[DVec2], point: DVec2) -> f64 {
    let count = corners.len();
    (0..count)
        .map(|i| line_distance(point, corners[i], corners[(i + 1) % count]))
        .fold(f64::INFINITY, f64::min)
}

/// The distance from `point` to the line through `from` and `to`.
fn line_distance(point: DVec2, from: DVec2, to: DVec2) -> f64 {
    let along = to - from;
    along.perp_dot(point - from).abs() / along.length()
}

/// The type-0 pentagon round the origin that holds `point` after `splits` splits, each of
/// which turns it by 180° and shrinks it by 1/φ², down to the unit one with a corner
/// towards −x; `None` for a point too far out (or not finite).
fn starting_pentagon(point: DVec2) -> Option<(Tile, i32)> {
    // A pentagon's inradius is 0.688 of its edge; a margin keeps the point clear of it.
    let needed = (point.length() + 2.0) / 0.68;
    if !needed.is_finite() || needed >= f64::MAX / 16.0 {
        return None;
    }
    let mut splits = 1;
    while PHI.powi(2 * splits) < needed {
        splits += 1;
    }
    let edge = PHI.powi(2 * splits);
    let circumradius = edge / (2.0 * TURN_36.0.y);
    let sign = if splits % 2 == 0 { 1.0 } else { -1.0 };
    let apex = DVec2::new(-circumradius * sign, 0.0);
    let left = TURN_72.0.rotate(apex);
    Some((Tile::pentagon(Shape::CentrePentagon, apex, left), splits))
}

/// The value of `tiling 25` at `(x, z)`.
pub(super) fn value(x: f64, z: f64) -> f64 {
    let point = DVec2::new(x, z);
    // POV-Ray gives 1 at the origin itself, as for tilings 26 and 27 (measured).
    if point.length() <= ORIGIN_RADIUS {
        return 1.0;
    }
    let Some((start, splits)) = starting_pentagon(point) else {
        return 0.0;
    };
    let mut kept = [start; MAX_KEPT];
    let mut kept_count = 1;
    for _ in 0..splits {
        let mut next = [start; MAX_KEPT];
        let mut next_centres = [DVec2::ZERO; MAX_KEPT];
        let mut next_count = 0;
        for parent in &kept[..kept_count] {
            for child in parent.split().into_iter().flatten() {
                let edge = child.edge();
                let centre = child.centre();
                if centre.distance(point) > child.reach() * edge {
                    continue;
                }
                // Neighbours make the tiles on their shared edges twice.
                let twice = next_centres[..next_count]
                    .iter()
                    .any(|other| other.distance(centre) < 1e-6 * edge);
                if !twice && next_count < MAX_KEPT {
                    next[next_count] = child;
                    next_centres[next_count] = centre;
                    next_count += 1;
                }
            }
        }
        if next_count == 0 {
            return 0.0;
        }
        kept = next;
        kept_count = next_count;
    }
    // The tile the point is deepest in (the first of equals), which always exists even
    // where rounding puts the point a hair outside every tile.
    let mut tile = kept[0];
    let mut best = f64::NEG_INFINITY;
    for candidate in &kept[..kept_count] {
        let insideness = candidate.insideness(point);
        if insideness > best {
            best = insideness;
            tile = *candidate;
        }
    }
    let kind = f64::from(tile.shape as u8);
    let rise = 1.0 - (tile.edge_distance(point) / BEVEL).clamp(0.0, 1.0);
    // POV-Ray keeps every type a millionth below the next one's lowest value (measured on
    // edges of types 0, 2 and 5: 1/6 − 1e-6, 1/2 − 1e-6, 1 − 1e-6), and lifts the flat
    // middles of every type but 0 a millionth above k / 6 (measured: 1/6 + 1e-6,
    // 1/3 + 1e-6, 1/2 + 1e-6).
    let value = ((kind + rise) / TYPES).min((kind + 1.0) / TYPES - 1e-6);
    if kind > 0.0 {
        value.max(kind / TYPES + 1e-6)
    } else {
        value
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// POV-Ray 3.7's values of `tiling 25` through a black-to-white colour map at random
    /// points: two of each tile type in its flat middle and in its bevel, boats whose value
    /// follows the line through their base, and points out to 10⁵ units.
    const SAMPLES: &[(f64, f64, f64)] = &[
        (1.9664271182352309, 3.8685918281716702, 0.497048586607),
        (4.723097049051146, 7.079204540432805, 0.166667670012),
        (3.8383771958388913, 6.757199946646672, 0.291884899139),
        (-7.535916347462164, -0.5500375299503144, 0.331102579832),
        (7.093707471973019, 2.3835928501907873, 0.101997017860),
        (6.414407868009963, -6.18870456554969, 0.166667670012),
        (-0.49489523548538017, -4.054834678082715, 0.396362125874),
        (0.7001737477748868, 1.1830590068496125, 0.333334326744),
        (-7.790172966577565, -4.5323231925784295, 0.333334326744),
        (4.251607226066268, -5.446332602271388, 0.000000000000),
        (1.8792403274578664, -5.972812279195685, 0.531384468079),
        (-7.971602204759446, 5.942475915588513, 0.049269214272),
        (7.718737741214804, 5.95852424698883, 0.602486968040),
        (-4.723527767459315, 7.055616017407985, 0.797370433807),
        (-5.66876944734908, -6.95776458598918, 0.805533707142),
        (3.274706146254548, -7.087985127427361, 0.980561614037),
        (3.996720356660372, 5.518094230210075, 0.000000000000),
        (3.7066307740268236, 7.19677700195038, 0.966131448746),
        (1.842688624790144, -5.748792251892114, 0.500001013279),
        (-4.802336955525741, -3.4237070223498733, 0.500001013279),
        (2.11403489205496, -1.2842792400968897, 0.273444592953),
        (-15.709384084079229, 19.74725532505375, 0.211966440082),
        (-13.574504739004528, -29.394536373753912, 0.476043075323),
        (-13.026984658557964, -38.71708330063919, 0.295691907406),
        (-11.093493126953689, 37.22832311182955, 0.962498068810),
        (-88.63322814771738, -97.10468174586495, 0.810838401318),
        (605.819515428261, -46.76001833236535, 0.806578099728),
        (247.01151945105357, 669.6276160845414, 0.267256796360),
        (-9594.46569511097, 7690.284169309984, 0.363978773355),
        (-7997.28624014737, -2612.941728888605, 0.000000000000),
        (-3999.8596627240586, 4575.7646667235, 0.326852321625),
        (37845.19312964182, -56594.526571144896, 0.267574071884),
        (-8858.45940587169, 53533.42473705506, 0.166667670012),
        (74146.43799168142, 83429.6515919953, 0.166667670012),
        (-2.5606475739864862, 6.787161910844651, 0.762998819351),
        (-2.0965115647238637, 7.007072813379008, 0.800570726395),
        (-4.78364101471818, -7.601114800605766, 0.688769698143),
        (5.708269444720962, -4.5694438666166945, 0.795973718166),
    ];

    /// Compares with POV-Ray's values (single precision colours, so to 1e-6).
    fn check(samples: &[(f64, f64, f64)]) {
        for &(x, z, expected) in samples {
            let found = value(x, z);
            assert!(
                (found - expected).abs() < 1e-6,
                "at ({x}, {z}): {found} against {expected}"
            );
        }
    }

    #[test]
    fn matches_povray() {
        check(SAMPLES);
    }

    #[test]
    fn every_type_stays_a_millionth_below_the_next() {
        let inradius = 0.5 / TURN_36.0.y * TURN_36.0.x;
        let circumradius = 0.5 / TURN_36.0.y;
        check(&[
            // Just inside the centre pentagon's edge facing +x, and just outside it.
            (inradius - 1e-7, 0.0, 0.166_665_673_3),
            (inradius + 1e-7, 0.0, 0.499_998_986_7),
            // A point on the edge of the diamond at the centre pentagon's corner.
            (
                -circumradius - 0.5 * TURN_72.0.y + 1e-7,
                0.5 * TURN_72.0.x - 1e-7,
                0.999_998_986_7,
            ),
        ]);
    }

    #[test]
    fn has_the_symmetry_of_a_pentagon_about_the_origin() {
        let point = DVec2::new(3.7, -1.3);
        let expected = value(point.x, point.y);
        for turn in 1..5 {
            let turned =
                DVec2::from_angle(f64::from(turn) * 0.4 * std::f64::consts::PI).rotate(point);
            assert!((value(turned.x, turned.y) - expected).abs() < 1e-9);
        }
    }

    #[test]
    fn every_point_lies_in_a_tile() {
        // Points on a spiral from near the origin to 10⁴ units out: a tile kept to the end
        // holds the point (to rounding), so no offspring that could hold it was dropped.
        for step in 0..2000 {
            let radius = 0.01 * 1.007_f64.powi(step);
            let point = DVec2::from_angle(f64::from(step) * 2.4) * radius;
            let (start, splits) = starting_pentagon(point).expect("a finite point");
            let mut deepest = f64::NEG_INFINITY;
            let mut kept = vec![start];
            let mut most_kept = 1;
            for _ in 0..splits {
                let mut next: Vec<Tile> = Vec::new();
                for parent in &kept {
                    for child in parent.split().into_iter().flatten() {
                        if child.centre().distance(point) <= child.reach() * child.edge() {
                            next.push(child);
                        }
                    }
                }
                kept = next;
                most_kept = most_kept.max(kept.len());
            }
            for tile in &kept {
                deepest = deepest.max(tile.insideness(point));
            }
            assert!(deepest > -1e-9, "no tile holds {point}");
            // Even counting the tiles made twice, the kept tiles fit.
            assert!(most_kept <= MAX_KEPT, "{most_kept} tiles kept at {point}");
        }
    }

    #[test]
    fn the_origin_gives_1_and_its_pentagon_has_a_corner_towards_minus_x() {
        check(&[(0.0, 0.0, 1.0)]);
        // Across the pentagon's edge facing +x lies a type-2 pentagon; towards −x the
        // centre pentagon's corner.
        assert!(value(0.7, 0.0) > 2.0 / 6.0);
        assert!(value(-0.7, 0.0) < 1.0 / 6.0);
    }

    #[test]
    fn huge_and_non_finite_points_give_a_value() {
        assert_eq!(value(f64::NAN, 0.0), 0.0);
        assert_eq!(value(0.0, f64::INFINITY), 0.0);
        let far = value(1e300, -1e300);
        assert!((0.0..=1.0).contains(&far));
        assert_eq!(value(f64::MAX, f64::MAX), 0.0);
    }
}
