//! The `tiling N` pattern: periodic tilings of the x-z plane by convex tiles, each tile
//! bevelled towards its edges; the aperiodic Penrose tilings live in `pentagons` (25) and
//! `penrose` (26 and 27).
//!
//! In: a pattern-space point (y is ignored) and the tiling number. Out: the value in [0, 1].
//! Holds: static tables, no allocation; non-finite input is the caller's concern (the
//! pattern gives 0 for it).
//!
//! What a value means (manual, "Tiling Pattern", and measured against POV-Ray 3.7): a
//! tiling with `T` tile types gives a tile of type `k` the value `k / T` where it is farther
//! than the tiling's bevel width from every edge of the tile, rising linearly to `(k + 1) / T`
//! at the edges. Every tile of a tiling shares one bevel width (but for a few edges of the
//! dodecagons of `tiling 22`); for the tilings made of one regular polygon it is the
//! polygon's inradius, so the bevel reaches the centre. A point on an edge belongs to the
//! tile it enters when moved along +z (or, on an edge along z, along +x), as in POV-Ray
//! for most edges; exactly on some lattice lines POV-Ray gives other values (e.g. on whole
//! numbers x in `tiling 3`, on x = 0 in `tiling 12`), which these tables do not reproduce,
//! but for the 0 of `tiling 13` and `tiling 14` on the x axis.
//!
//! Each layout below was measured with probe scenes (`pigment { tiling N }` through a
//! black-to-white colour map, sampled on grids with `#debug`): the period, the tiles in one
//! period, their types and the bevel width.

mod penrose;
mod pentagons;

use penrose::Penrose;

/// √3, for the tilings built on equilateral triangles and hexagons.
const SQRT_3: f64 = 1.732_050_807_568_877_2;

/// One tile: its type and its vertices (x, z) counter-clockwise or clockwise.
struct Tile {
    /// The tile type, below the layout's `types`.
    kind: u8,
    /// The corners of the convex tile.
    corners: &'static [(f64, f64)],
    /// The bevel width of each edge (from corner `i` to corner `i + 1`), where they are
    /// not all the layout's.
    edge_bevels: Option<&'static [f64]>,
}

impl Tile {
    /// A tile bevelled by its layout's width on every edge.
    const fn new(kind: u8, corners: &'static [(f64, f64)]) -> Self {
        Self {
            kind,
            corners,
            edge_bevels: None,
        }
    }

    /// A tile with its own bevel width for each edge.
    const fn with_edge_bevels(
        kind: u8,
        corners: &'static [(f64, f64)],
        edge_bevels: &'static [f64],
    ) -> Self {
        Self {
            kind,
            corners,
            edge_bevels: Some(edge_bevels),
        }
    }
}

/// A periodic tiling: the tiles of one period (tiles may reach past the period's
/// parallelogram, by less than one period).
struct Layout {
    /// The two vectors (x, z) the tiling repeats along.
    period: [(f64, f64); 2],
    /// How many tile types there are.
    types: u8,
    /// The distance from an edge over which the bevel rises.
    bevel: f64,
    /// The tiles of one period.
    tiles: &'static [Tile],
    /// Whether POV-Ray gives 0 exactly on the x axis and near the origin on the z axis
    /// (`tiling 13` and `tiling 14`; farther along the z axis its values there follow no
    /// tile and are not reproduced).
    zero_on_axes: bool,
}

/// `tiling 1`: unit squares with corners on the integer lattice.
const SQUARES: Layout = Layout {
    period: [(1.0, 0.0), (0.0, 1.0)],
    types: 1,
    bevel: 0.5,
    tiles: &[Tile::new(
        0,
        &[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)],
    )],
    zero_on_axes: false,
};

/// `tiling 2`: hexagons of side 1 with corners along ±x, one centred at (−1, 0).
const HEXAGONS: Layout = Layout {
    period: [(3.0, 0.0), (0.0, SQRT_3)],
    types: 1,
    bevel: SQRT_3 / 2.0,
    tiles: &[
        Tile::new(
            0,
            &[
                (0.0, 0.0),
                (-0.5, SQRT_3 / 2.0),
                (-1.5, SQRT_3 / 2.0),
                (-2.0, 0.0),
                (-1.5, -SQRT_3 / 2.0),
                (-0.5, -SQRT_3 / 2.0),
            ],
        ),
        Tile::new(
            0,
            &[
                (1.5, SQRT_3 / 2.0),
                (1.0, SQRT_3),
                (0.0, SQRT_3),
                (-0.5, SQRT_3 / 2.0),
                (0.0, 0.0),
                (1.0, 0.0),
            ],
        ),
    ],
    zero_on_axes: false,
};

/// `tiling 3`: equilateral triangles of side 1 with horizontal edges on `z = k √3/2`;
/// triangles pointing up (+z) are type 0, pointing down type 1.
const TRIANGLES: Layout = Layout {
    period: [(1.0, 0.0), (0.0, SQRT_3)],
    types: 2,
    bevel: SQRT_3 / 6.0,
    tiles: &[
        Tile::new(0, &[(0.0, 0.0), (1.0, 0.0), (0.5, SQRT_3 / 2.0)]),
        Tile::new(1, &[(0.5, SQRT_3 / 2.0), (1.0, 0.0), (1.5, SQRT_3 / 2.0)]),
        Tile::new(
            0,
            &[(0.5, SQRT_3 / 2.0), (1.5, SQRT_3 / 2.0), (1.0, SQRT_3)],
        ),
        Tile::new(1, &[(0.0, SQRT_3), (0.5, SQRT_3 / 2.0), (1.0, SQRT_3)]),
    ],
    zero_on_axes: false,
};

/// Half of √3: the height of an equilateral triangle of side 1.
const H: f64 = SQRT_3 / 2.0;

/// `tiling 4`: rhombi of side 1 with 60° corners at the origin, edges along x and at 60°.
const LOZENGES: Layout = Layout {
    period: [(1.0, 0.0), (0.0, SQRT_3)],
    types: 1,
    bevel: SQRT_3 / 4.0,
    tiles: &[
        Tile::new(0, &[(0.0, 0.0), (1.0, 0.0), (1.5, H), (0.5, H)]),
        Tile::new(0, &[(0.5, H), (1.5, H), (2.0, SQRT_3), (1.0, SQRT_3)]),
    ],
    zero_on_axes: false,
};

/// `tiling 5`: the hexagons of `tiling 2` each cut into three rhombi (a stack of cubes):
/// type 0 the lower right, type 1 the left (long axis along z), type 2 the upper right.
const CUBES: Layout = Layout {
    period: [(3.0, 0.0), (0.0, SQRT_3)],
    types: 3,
    bevel: SQRT_3 / 4.0,
    tiles: &[
        // The hexagon centred at (0.5, √3/2).
        Tile::new(0, &[(0.0, 0.0), (1.0, 0.0), (1.5, H), (0.5, H)]),
        Tile::new(1, &[(0.0, 0.0), (0.5, H), (0.0, SQRT_3), (-0.5, H)]),
        Tile::new(2, &[(0.5, H), (1.5, H), (1.0, SQRT_3), (0.0, SQRT_3)]),
        // The hexagon centred at (-1, 0).
        Tile::new(0, &[(0.0, 0.0), (-1.0, 0.0), (-1.5, -H), (-0.5, -H)]),
        Tile::new(1, &[(-1.0, 0.0), (-1.5, H), (-2.0, 0.0), (-1.5, -H)]),
        Tile::new(2, &[(0.0, 0.0), (-0.5, H), (-1.5, H), (-1.0, 0.0)]),
    ],
    zero_on_axes: false,
};

/// `tiling 6`: 1 × 2 rectangles in a staircase: upright ones (long along z, type 1) and
/// flat ones (long along x, type 0).
const STAIRCASE: Layout = Layout {
    period: [(1.0, 1.0), (-2.0, 2.0)],
    types: 2,
    bevel: 0.5,
    tiles: &[
        Tile::new(1, &[(0.0, 0.0), (1.0, 0.0), (1.0, 2.0), (0.0, 2.0)]),
        Tile::new(0, &[(-2.0, 1.0), (0.0, 1.0), (0.0, 2.0), (-2.0, 2.0)]),
    ],
    zero_on_axes: false,
};

/// Half the width of a regular octagon of side 1: (1 + √2) / 2.
const OCTAGON_INRADIUS: f64 = 1.207_106_781_186_547_6;

/// `tiling 7`: regular octagons of side 1 (type 1) centred on the lattice of spacing
/// 1 + √2, with the squares between them (type 0, turned 45°).
const OCTAGONS: Layout = Layout {
    period: [(2.0 * OCTAGON_INRADIUS, 0.0), (0.0, 2.0 * OCTAGON_INRADIUS)],
    types: 2,
    bevel: 0.5,
    tiles: &[
        Tile::new(
            1,
            &[
                (OCTAGON_INRADIUS, -0.5),
                (OCTAGON_INRADIUS, 0.5),
                (0.5, OCTAGON_INRADIUS),
                (-0.5, OCTAGON_INRADIUS),
                (-OCTAGON_INRADIUS, 0.5),
                (-OCTAGON_INRADIUS, -0.5),
                (-0.5, -OCTAGON_INRADIUS),
                (0.5, -OCTAGON_INRADIUS),
            ],
        ),
        Tile::new(
            0,
            &[
                (OCTAGON_INRADIUS, 0.5),
                (2.0 * OCTAGON_INRADIUS - 0.5, OCTAGON_INRADIUS),
                (OCTAGON_INRADIUS, 2.0 * OCTAGON_INRADIUS - 0.5),
                (0.5, OCTAGON_INRADIUS),
            ],
        ),
    ],
    zero_on_axes: false,
};

/// `tiling 8`: rows of unit squares (type 2) between rows of equilateral triangles, up
/// (type 0) and down (type 1); each square row is half a square along from the last.
const SQUARES_AND_TRIANGLES: Layout = Layout {
    period: [(1.0, 0.0), (0.5, 1.0 + H)],
    types: 3,
    bevel: SQRT_3 / 6.0,
    tiles: &[
        Tile::new(2, &[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]),
        Tile::new(0, &[(0.0, 1.0), (1.0, 1.0), (0.5, 1.0 + H)]),
        Tile::new(1, &[(0.5, 1.0 + H), (1.0, 1.0), (1.5, 1.0 + H)]),
    ],
    zero_on_axes: false,
};

/// `tiling 9`: hexagons of side 1 (type 2) meeting at their corners, with the triangles
/// between them pointing up (type 0) and down (type 1).
const HEXAGONS_AND_TRIANGLES: Layout = Layout {
    period: [(2.0, 0.0), (1.0, SQRT_3)],
    types: 3,
    bevel: SQRT_3 / 6.0,
    tiles: &[
        Tile::new(
            2,
            &[
                (0.0, 0.0),
                (1.0, 0.0),
                (1.5, H),
                (1.0, SQRT_3),
                (0.0, SQRT_3),
                (-0.5, H),
            ],
        ),
        Tile::new(0, &[(1.0, 0.0), (2.0, 0.0), (1.5, H)]),
        Tile::new(1, &[(0.0, 0.0), (0.5, -H), (1.0, 0.0)]),
    ],
    zero_on_axes: false,
};

/// `tiling 10`: unit squares in rows, each row half a square along from the last.
const OFFSET_SQUARES: Layout = Layout {
    period: [(1.0, 0.0), (0.5, 1.0)],
    types: 1,
    bevel: 0.5,
    tiles: &[Tile::new(
        0,
        &[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)],
    )],
    zero_on_axes: false,
};

/// `tiling 11`: unit squares (type 0), each with four 1 × 2 rectangles around it in a
/// pinwheel, flat ones (long along x, type 1) and upright ones (type 2); period 3 × 3.
const SQUARE_PINWHEELS: Layout = Layout {
    period: [(3.0, 0.0), (0.0, 3.0)],
    types: 3,
    bevel: 0.5,
    tiles: &[
        Tile::new(0, &[(1.0, 1.0), (2.0, 1.0), (2.0, 2.0), (1.0, 2.0)]),
        Tile::new(1, &[(1.0, 0.0), (3.0, 0.0), (3.0, 1.0), (1.0, 1.0)]),
        Tile::new(1, &[(0.0, 2.0), (2.0, 2.0), (2.0, 3.0), (0.0, 3.0)]),
        Tile::new(2, &[(0.0, 0.0), (1.0, 0.0), (1.0, 2.0), (0.0, 2.0)]),
        Tile::new(2, &[(2.0, 1.0), (3.0, 1.0), (3.0, 3.0), (2.0, 3.0)]),
    ],
    zero_on_axes: false,
};

/// `tiling 12`: blocks of four 1 × 2 rectangles, flat (type 1) and upright (type 2), in a
/// basket weave with unit squares (type 0) in the gaps.
const BASKET_WEAVE: Layout = Layout {
    period: [(3.0, 3.0), (3.0, -3.0)],
    types: 3,
    bevel: 0.5,
    tiles: &[
        Tile::new(0, &[(1.0, 1.0), (2.0, 1.0), (2.0, 2.0), (1.0, 2.0)]),
        Tile::new(0, &[(4.0, 1.0), (5.0, 1.0), (5.0, 2.0), (4.0, 2.0)]),
        Tile::new(1, &[(1.0, -1.0), (3.0, -1.0), (3.0, 0.0), (1.0, 0.0)]),
        Tile::new(1, &[(3.0, -1.0), (5.0, -1.0), (5.0, 0.0), (3.0, 0.0)]),
        Tile::new(1, &[(1.0, 0.0), (3.0, 0.0), (3.0, 1.0), (1.0, 1.0)]),
        Tile::new(1, &[(3.0, 0.0), (5.0, 0.0), (5.0, 1.0), (3.0, 1.0)]),
        Tile::new(2, &[(2.0, 1.0), (3.0, 1.0), (3.0, 3.0), (2.0, 3.0)]),
        Tile::new(2, &[(3.0, 1.0), (4.0, 1.0), (4.0, 3.0), (3.0, 3.0)]),
        Tile::new(2, &[(2.0, 3.0), (3.0, 3.0), (3.0, 5.0), (2.0, 5.0)]),
        Tile::new(2, &[(3.0, 3.0), (4.0, 3.0), (4.0, 5.0), (3.0, 5.0)]),
    ],
    zero_on_axes: false,
};

/// Half of √2: the offsets of `tiling 13` and `tiling 14`.
const HALF_SQRT_2: f64 = std::f64::consts::FRAC_1_SQRT_2;

/// The trapezoid right of a lattice point of `tiling 13` and `tiling 14`, along z.
const TRAPEZOID_RIGHT: &[(f64, f64)] = &[
    (0.0, 0.0),
    (HALF_SQRT_2, HALF_SQRT_2),
    (HALF_SQRT_2, 3.0 * HALF_SQRT_2),
    (0.0, 4.0 * HALF_SQRT_2),
];
/// The trapezoid left of a lattice point, along z.
const TRAPEZOID_LEFT: &[(f64, f64)] = &[
    (0.0, 0.0),
    (0.0, 4.0 * HALF_SQRT_2),
    (-HALF_SQRT_2, 3.0 * HALF_SQRT_2),
    (-HALF_SQRT_2, HALF_SQRT_2),
];
/// The trapezoid above a lattice point (+z), along x.
const TRAPEZOID_ABOVE: &[(f64, f64)] = &[
    (0.0, 0.0),
    (4.0 * HALF_SQRT_2, 0.0),
    (3.0 * HALF_SQRT_2, HALF_SQRT_2),
    (HALF_SQRT_2, HALF_SQRT_2),
];
/// The trapezoid below a lattice point, along x.
const TRAPEZOID_BELOW: &[(f64, f64)] = &[
    (0.0, 0.0),
    (HALF_SQRT_2, -HALF_SQRT_2),
    (3.0 * HALF_SQRT_2, -HALF_SQRT_2),
    (4.0 * HALF_SQRT_2, 0.0),
];
/// The square of side √2 between the trapezoids.
const TRAPEZOIDS_SQUARE: &[(f64, f64)] = &[
    (HALF_SQRT_2, HALF_SQRT_2),
    (3.0 * HALF_SQRT_2, HALF_SQRT_2),
    (3.0 * HALF_SQRT_2, 3.0 * HALF_SQRT_2),
    (HALF_SQRT_2, 3.0 * HALF_SQRT_2),
];

/// `tiling 13`: squares of side √2 (type 0) on a lattice of spacing 2√2, the strips
/// between them cut into trapezoids meeting at the lattice points: flat ones (type 1) and
/// upright ones (type 2).
const TRAPEZOIDS: Layout = Layout {
    period: [(4.0 * HALF_SQRT_2, 0.0), (0.0, 4.0 * HALF_SQRT_2)],
    types: 3,
    bevel: HALF_SQRT_2 / 2.0,
    tiles: &[
        Tile::new(0, TRAPEZOIDS_SQUARE),
        Tile::new(1, TRAPEZOID_ABOVE),
        Tile::new(1, TRAPEZOID_BELOW),
        Tile::new(2, TRAPEZOID_RIGHT),
        Tile::new(2, TRAPEZOID_LEFT),
    ],
    zero_on_axes: true,
};

/// `tiling 14`: `tiling 13` with each trapezoid of its own type: left 0, right 1, above 2,
/// below 3, and the squares 4.
const TRAPEZOIDS_FIVE: Layout = Layout {
    period: [(4.0 * HALF_SQRT_2, 0.0), (0.0, 4.0 * HALF_SQRT_2)],
    types: 5,
    bevel: HALF_SQRT_2 / 2.0,
    tiles: &[
        Tile::new(4, TRAPEZOIDS_SQUARE),
        Tile::new(2, TRAPEZOID_ABOVE),
        Tile::new(3, TRAPEZOID_BELOW),
        Tile::new(1, TRAPEZOID_RIGHT),
        Tile::new(0, TRAPEZOID_LEFT),
    ],
    zero_on_axes: true,
};

/// `tiling 15`: unit squares (type 0) and squares of side 2 (type 1) in a pinwheel.
const TWO_SQUARES: Layout = Layout {
    period: [(2.0, 1.0), (-1.0, 2.0)],
    types: 2,
    bevel: 0.5,
    tiles: &[
        Tile::new(0, &[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]),
        Tile::new(1, &[(-2.0, 0.0), (0.0, 0.0), (0.0, 2.0), (-2.0, 2.0)]),
    ],
    zero_on_axes: false,
};

/// 1 + √3: the distance between neighbouring hexagons of `tiling 16`.
const HEXAGON_SPACING: f64 = 1.0 + SQRT_3;

/// The hexagon of `tiling 16` and `tiling 17`, side 1, centred at (−1, 0).
const HST_HEXAGON: &[(f64, f64)] = &[
    (0.0, 0.0),
    (-0.5, H),
    (-1.5, H),
    (-2.0, 0.0),
    (-1.5, -H),
    (-0.5, -H),
];
/// The square below that hexagon.
const HST_SQUARE_BELOW: &[(f64, f64)] =
    &[(-1.5, -H), (-0.5, -H), (-0.5, -H - 1.0), (-1.5, -H - 1.0)];
/// The square on the hexagon's lower right edge.
const HST_SQUARE_LOWER_RIGHT: &[(f64, f64)] =
    &[(-0.5, -H), (0.0, 0.0), (H, -0.5), (H - 0.5, -H - 0.5)];
/// The square on the hexagon's upper right edge.
const HST_SQUARE_UPPER_RIGHT: &[(f64, f64)] =
    &[(0.0, 0.0), (-0.5, H), (H - 0.5, H + 0.5), (H, 0.5)];
/// The triangle right of the hexagon.
const HST_TRIANGLE_RIGHT: &[(f64, f64)] = &[(0.0, 0.0), (H, -0.5), (H, 0.5)];
/// The triangle left of the hexagon, moved one period along to lie near the others.
const HST_TRIANGLE_LEFT: &[(f64, f64)] = &[(H - 0.5, 0.5 + H), (-0.5, 1.0 + H), (-0.5, H)];

/// `tiling 16`: hexagons of side 1 (type 2, one centred at (−1, 0), corners along ±x),
/// unit squares on their edges (type 0) and triangles between the squares (type 1).
const HEXAGONS_SQUARES_TRIANGLES: Layout = Layout {
    period: [
        (0.0, HEXAGON_SPACING),
        (HEXAGON_SPACING * H, HEXAGON_SPACING / 2.0),
    ],
    types: 3,
    bevel: SQRT_3 / 6.0,
    tiles: &[
        Tile::new(2, HST_HEXAGON),
        Tile::new(0, HST_SQUARE_BELOW),
        Tile::new(0, HST_SQUARE_LOWER_RIGHT),
        Tile::new(0, HST_SQUARE_UPPER_RIGHT),
        Tile::new(1, HST_TRIANGLE_RIGHT),
        Tile::new(1, HST_TRIANGLE_LEFT),
    ],
    zero_on_axes: false,
};

/// `tiling 17`: the layout of `tiling 16` with six types: squares below a hexagon (0),
/// right of its upper right edge (1) and of its lower right edge (2), triangles left of a
/// hexagon (3) and right of it (4), hexagons (5).
const HEXAGONS_SQUARES_TRIANGLES_SIX: Layout = Layout {
    period: [
        (0.0, HEXAGON_SPACING),
        (HEXAGON_SPACING * H, HEXAGON_SPACING / 2.0),
    ],
    types: 6,
    bevel: SQRT_3 / 6.0,
    tiles: &[
        Tile::new(5, HST_HEXAGON),
        Tile::new(0, HST_SQUARE_BELOW),
        Tile::new(2, HST_SQUARE_LOWER_RIGHT),
        Tile::new(1, HST_SQUARE_UPPER_RIGHT),
        Tile::new(4, HST_TRIANGLE_RIGHT),
        Tile::new(3, HST_TRIANGLE_LEFT),
    ],
    zero_on_axes: false,
};

/// `tiling 18`: 2 × 2 blocks of two 1 × 2 rectangles in a checkerboard, flat (type 0)
/// and upright (type 1).
const RECTANGLE_PAIRS: Layout = Layout {
    period: [(2.0, 2.0), (2.0, -2.0)],
    types: 2,
    bevel: 0.5,
    tiles: &[
        Tile::new(1, &[(0.0, 0.0), (1.0, 0.0), (1.0, 2.0), (0.0, 2.0)]),
        Tile::new(1, &[(1.0, 0.0), (2.0, 0.0), (2.0, 2.0), (1.0, 2.0)]),
        Tile::new(0, &[(2.0, 0.0), (4.0, 0.0), (4.0, 1.0), (2.0, 1.0)]),
        Tile::new(0, &[(2.0, 1.0), (4.0, 1.0), (4.0, 2.0), (2.0, 2.0)]),
    ],
    zero_on_axes: false,
};

/// `tiling 19`: hexagons of side 1 (type 2, one centred at (−1, 0)) among equilateral
/// triangles pointing up (type 0) and down (type 1), the hexagons √7 apart (snub hexagonal,
/// turning one way).
const SNUB_HEXAGONS_RIGHT: Layout = Layout {
    period: [(2.0, SQRT_3), (2.5, -H)],
    types: 3,
    bevel: SQRT_3 / 6.0,
    tiles: &[
        Tile::new(
            2,
            &[
                (0.0, 0.0),
                (-0.5, H),
                (-1.5, H),
                (-2.0, 0.0),
                (-1.5, -H),
                (-0.5, -H),
            ],
        ),
        Tile::new(1, &[(0.0, 0.0), (0.5, H), (-0.5, H)]),
        Tile::new(1, &[(0.5, -H), (1.0, 0.0), (0.0, 0.0)]),
        Tile::new(0, &[(0.0, 0.0), (1.0, 0.0), (0.5, H)]),
        Tile::new(1, &[(1.0, 0.0), (1.5, H), (0.5, H)]),
        Tile::new(0, &[(1.0, 0.0), (2.0, 0.0), (1.5, H)]),
        Tile::new(1, &[(2.0, 0.0), (2.5, H), (1.5, H)]),
        Tile::new(0, &[(1.5, H), (2.5, H), (2.0, 2.0 * H)]),
        Tile::new(0, &[(2.0, 0.0), (3.0, 0.0), (2.5, H)]),
    ],
    zero_on_axes: false,
};

/// `tiling 20`: the other hand of `tiling 19`, one hexagon centred at (1, √3).
const SNUB_HEXAGONS_LEFT: Layout = Layout {
    period: [(0.5, 3.0 * H), (-2.0, SQRT_3)],
    types: 3,
    bevel: SQRT_3 / 6.0,
    tiles: &[
        Tile::new(
            2,
            &[
                (2.0, 2.0 * H),
                (1.5, 3.0 * H),
                (0.5, 3.0 * H),
                (0.0, 2.0 * H),
                (0.5, H),
                (1.5, H),
            ],
        ),
        Tile::new(1, &[(-0.5, 5.0 * H), (0.0, 6.0 * H), (-1.0, 6.0 * H)]),
        Tile::new(1, &[(0.0, 4.0 * H), (0.5, 5.0 * H), (-0.5, 5.0 * H)]),
        Tile::new(0, &[(-0.5, 5.0 * H), (0.5, 5.0 * H), (0.0, 6.0 * H)]),
        Tile::new(1, &[(0.5, 5.0 * H), (1.0, 6.0 * H), (0.0, 6.0 * H)]),
        Tile::new(0, &[(-0.5, 3.0 * H), (0.5, 3.0 * H), (0.0, 4.0 * H)]),
        Tile::new(1, &[(0.5, 3.0 * H), (1.0, 4.0 * H), (0.0, 4.0 * H)]),
        Tile::new(0, &[(0.0, 4.0 * H), (1.0, 4.0 * H), (0.5, 5.0 * H)]),
        Tile::new(0, &[(0.5, 3.0 * H), (1.5, 3.0 * H), (1.0, 4.0 * H)]),
    ],
    zero_on_axes: false,
};

/// `tiling 21`: unit squares in two orientations (types 4 and 5) and equilateral
/// triangles (snub square): a triangle pointing along +x (0) and one along −x (2) share the
/// edge from (0, −½) to (0, ½); those along +z (1) and −z (3) sit above and below it.
const SNUB_SQUARES: Layout = Layout {
    period: [(0.5 + H, 0.5 + H), (0.5 + H, -0.5 - H)],
    types: 6,
    bevel: SQRT_3 / 6.0,
    tiles: &[
        Tile::new(4, &[(H, 0.0), (0.5 + H, H), (0.5, 0.5 + H), (0.0, 0.5)]),
        Tile::new(5, &[(H, 0.0), (0.5 + H, -H), (0.5, -0.5 - H), (0.0, -0.5)]),
        Tile::new(0, &[(0.0, -0.5), (H, 0.0), (0.0, 0.5)]),
        Tile::new(2, &[(0.0, -0.5), (0.0, 0.5), (-H, 0.0)]),
        Tile::new(1, &[(0.0, 0.5), (0.5, 0.5 + H), (-0.5, 0.5 + H)]),
        Tile::new(3, &[(0.0, -0.5), (-0.5, -0.5 - H), (0.5, -0.5 - H)]),
    ],
    zero_on_axes: false,
};

/// The bevel widths of the edges of the dodecagon of `tiling 22`, from the edge facing +x
/// counter-clockwise: as measured, the edges facing ±x and −z are bevelled wider than the
/// others.
const DODECAGON_EDGE_BEVELS: &[f64] = &[
    1.0 / 3.0,
    SQRT_3 / 6.0,
    SQRT_3 / 6.0,
    SQRT_3 / 6.0,
    SQRT_3 / 6.0,
    SQRT_3 / 6.0,
    1.0 / 3.0,
    SQRT_3 / 6.0,
    SQRT_3 / 6.0,
    1.0 / 3.0,
    SQRT_3 / 6.0,
    SQRT_3 / 6.0,
];

/// The dodecagon of side 1 centred at (0, −½ − √3/2) shared by tilings 22–24.
const DODECAGON: &[(f64, f64)] = &[
    (1.0 + H, -1.0 - H),
    (1.0 + H, -H),
    (0.5 + H, 0.0),
    (0.5, 0.5),
    (-0.5, 0.5),
    (-0.5 - H, 0.0),
    (-1.0 - H, -H),
    (-1.0 - H, -1.0 - H),
    (-0.5 - H, -1.0 - 2.0 * H),
    (-0.5, -1.5 - 2.0 * H),
    (0.5, -1.5 - 2.0 * H),
    (0.5 + H, -1.0 - 2.0 * H),
];

/// The hexagon above [`DODECAGON`] in tilings 23 and 24.
const DHS_HEXAGON_ABOVE: &[(f64, f64)] = &[
    (1.0, 0.5 + H),
    (0.5, 0.5 + 2.0 * H),
    (-0.5, 0.5 + 2.0 * H),
    (-1.0, 0.5 + H),
    (-0.5, 0.5),
    (0.5, 0.5),
];

/// The hexagon to the right of [`DODECAGON`] in tilings 23 and 24.
const DHS_HEXAGON_BESIDE: &[(f64, f64)] = &[
    (2.5 + H, 0.0),
    (2.0 + H, H),
    (1.0 + H, H),
    (0.5 + H, 0.0),
    (1.0 + H, -H),
    (2.0 + H, -H),
];

/// The squares of tilings 23 and 24: along the axes, turned 60° and turned 120°.
const DHS_SQUARE_ALONG_AXES: &[(f64, f64)] = &[
    (1.0 + H, -1.0 - H),
    (2.0 + H, -1.0 - H),
    (2.0 + H, -H),
    (1.0 + H, -H),
];
const DHS_SQUARE_TURNED_60: &[(f64, f64)] =
    &[(0.5 + H, 0.0), (1.0 + H, H), (1.0, 0.5 + H), (0.5, 0.5)];
const DHS_SQUARE_TURNED_120: &[(f64, f64)] =
    &[(-0.5, 0.5), (-1.0, 0.5 + H), (-1.0 - H, H), (-0.5 - H, 0.0)];

/// `tiling 22`: dodecagons of side 1 (type 2, one centred at (0, −½ − √3/2)) with the
/// triangles between them pointing up (0) and down (1).
const DODECAGONS_TRIANGLES: Layout = Layout {
    period: [(2.0 + SQRT_3, 0.0), (1.0 + H, 1.5 + SQRT_3)],
    types: 3,
    bevel: SQRT_3 / 6.0,
    tiles: &[
        Tile::with_edge_bevels(2, DODECAGON, DODECAGON_EDGE_BEVELS),
        Tile::new(0, &[(-0.5, 0.5), (0.5, 0.5), (0.0, 0.5 + H)]),
        Tile::new(1, &[(0.5 + H, 0.0), (1.5 + H, 0.0), (1.0 + H, -H)]),
    ],
    zero_on_axes: false,
};

/// `tiling 23`: dodecagons of side 1 (type 2, one centred at (0, −½ − √3/2)), hexagons
/// (type 0) and unit squares (type 1) between them.
const DODECAGONS_HEXAGONS_SQUARES: Layout = Layout {
    period: [(3.0 + SQRT_3, 0.0), (1.5 + H, 1.5 + 3.0 * H)],
    types: 3,
    bevel: 0.5,
    tiles: &[
        Tile::new(2, DODECAGON),
        Tile::new(0, DHS_HEXAGON_ABOVE),
        Tile::new(0, DHS_HEXAGON_BESIDE),
        Tile::new(1, DHS_SQUARE_ALONG_AXES),
        Tile::new(1, DHS_SQUARE_TURNED_60),
        Tile::new(1, DHS_SQUARE_TURNED_120),
    ],
    zero_on_axes: false,
};

/// `tiling 24`: the layout of `tiling 23` with the squares typed by orientation: along
/// the axes 1, turned 60° 2, turned 120° 3; hexagons 0, dodecagons 4.
const DODECAGONS_HEXAGONS_SQUARES_FIVE: Layout = Layout {
    period: [(3.0 + SQRT_3, 0.0), (1.5 + H, 1.5 + 3.0 * H)],
    types: 5,
    bevel: 0.5,
    tiles: &[
        Tile::new(4, DODECAGON),
        Tile::new(0, DHS_HEXAGON_ABOVE),
        Tile::new(0, DHS_HEXAGON_BESIDE),
        Tile::new(1, DHS_SQUARE_ALONG_AXES),
        Tile::new(2, DHS_SQUARE_TURNED_60),
        Tile::new(3, DHS_SQUARE_TURNED_120),
    ],
    zero_on_axes: false,
};

/// The layout of a tiling number, `None` for numbers not (yet) supported.
fn layout(number: u8) -> Option<&'static Layout> {
    match number {
        1 => Some(&SQUARES),
        2 => Some(&HEXAGONS),
        3 => Some(&TRIANGLES),
        4 => Some(&LOZENGES),
        5 => Some(&CUBES),
        6 => Some(&STAIRCASE),
        7 => Some(&OCTAGONS),
        8 => Some(&SQUARES_AND_TRIANGLES),
        9 => Some(&HEXAGONS_AND_TRIANGLES),
        10 => Some(&OFFSET_SQUARES),
        11 => Some(&SQUARE_PINWHEELS),
        12 => Some(&BASKET_WEAVE),
        13 => Some(&TRAPEZOIDS),
        14 => Some(&TRAPEZOIDS_FIVE),
        15 => Some(&TWO_SQUARES),
        16 => Some(&HEXAGONS_SQUARES_TRIANGLES),
        17 => Some(&HEXAGONS_SQUARES_TRIANGLES_SIX),
        18 => Some(&RECTANGLE_PAIRS),
        19 => Some(&SNUB_HEXAGONS_RIGHT),
        20 => Some(&SNUB_HEXAGONS_LEFT),
        21 => Some(&SNUB_SQUARES),
        22 => Some(&DODECAGONS_TRIANGLES),
        23 => Some(&DODECAGONS_HEXAGONS_SQUARES),
        24 => Some(&DODECAGONS_HEXAGONS_SQUARES_FIVE),
        _ => None,
    }
}

/// The number of the Penrose tiling of pentagons, stars, boats and diamonds.
const PENTAGONS: u8 = 25;

/// The value of `tiling number` at `point` (x and z); 0 for an unsupported number.
pub fn tiling_value(number: u8, point: glam::DVec3) -> f64 {
    if number == PENTAGONS {
        return pentagons::value(point.x, point.z);
    }
    if let Some(penrose) = Penrose::from_number(number) {
        return penrose.value(point.x, point.z);
    }
    let Some(layout) = layout(number) else {
        return 0.0;
    };
    if layout.zero_on_axes && (point.x as f32 == 0.0 || point.z as f32 == 0.0) {
        return 0.0;
    }
    // The point inside the period's parallelogram (lattice coordinates taken down to their
    // fractional parts); tiles reaching past it are tried shifted by one period each way.
    let [(ux, uz), (vx, vz)] = layout.period;
    let determinant = ux * vz - uz * vx;
    let along_u = ((point.x * vz - point.z * vx) / determinant).floor();
    let along_v = ((ux * point.z - uz * point.x) / determinant).floor();
    let x = point.x - along_u * ux - along_v * vx;
    let z = point.z - along_u * uz - along_v * vz;
    // The tile the point is deepest in (depths in bevel widths); on an edge shared by two
    // tiles, the one the point enters when moved a little along +z and a littler along +x,
    // as POV-Ray assigns most edges.
    let mut best_kind = 0;
    let mut best_depth = f64::NEG_INFINITY;
    let mut best_nudged_depth = f64::NEG_INFINITY;
    for shift_u in [-1.0, 0.0, 1.0] {
        for shift_v in [-1.0, 0.0, 1.0] {
            let tile_x = x - shift_u * ux - shift_v * vx;
            let tile_z = z - shift_u * uz - shift_v * vz;
            for tile in layout.tiles {
                let depth = depth_inside(tile, layout.bevel, tile_x, tile_z);
                if depth < best_depth - EDGE_TOLERANCE {
                    continue;
                }
                let nudged_depth = depth_inside(
                    tile,
                    layout.bevel,
                    tile_x + EDGE_NUDGE.0,
                    tile_z + EDGE_NUDGE.1,
                );
                if depth > best_depth + EDGE_TOLERANCE || nudged_depth > best_nudged_depth {
                    best_depth = depth;
                    best_nudged_depth = nudged_depth;
                    best_kind = tile.kind;
                }
            }
        }
    }
    let rise = 1.0 - best_depth.clamp(0.0, 1.0);
    // POV-Ray scales by 1 / types held in single precision, which lifts the values a hair
    // above k / types: a colour map entry at exactly k / types is passed (measured with
    // maps that change colour there).
    let type_width = f64::from(1.0 / f32::from(layout.types));
    (f64::from(best_kind) + rise) * type_width
}

/// Depths closer than this (in bevel widths) are a tie: the point is on an edge.
const EDGE_TOLERANCE: f64 = 1e-12;

/// How far a point on an edge is moved to see which tile it enters.
const EDGE_NUDGE: (f64, f64) = (4e-10, 1e-9);

/// How deep `(x, z)` is inside a convex tile: the smallest over its edges of the distance
/// to the edge's line divided by the edge's bevel width (`bevel` unless the tile says
/// otherwise); negative outside. Either winding.
fn depth_inside(tile: &Tile, bevel: f64, x: f64, z: f64) -> f64 {
    let corners = tile.corners;
    let count = corners.len();
    // The winding's sign, from twice the signed area.
    let area: f64 = (0..count)
        .map(|i| {
            let (ax, az) = corners[i];
            let (bx, bz) = corners[(i + 1) % count];
            ax * bz - bx * az
        })
        .sum();
    let orientation = area.signum();
    (0..count)
        .map(|i| {
            let (ax, az) = corners[i];
            let (bx, bz) = corners[(i + 1) % count];
            let (edge_x, edge_z) = (bx - ax, bz - az);
            let length = edge_x.hypot(edge_z);
            let edge_bevel = tile.edge_bevels.map_or(bevel, |bevels| bevels[i]);
            orientation * (edge_x * (z - az) - edge_z * (x - ax)) / (length * edge_bevel)
        })
        .fold(f64::INFINITY, f64::min)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    /// Values of POV-Ray 3.7's `tiling N` through a black-to-white colour map (single
    /// precision colours, so compared to 1e-6).
    fn check(number: u8, samples: &[(f64, f64, f64)]) {
        for &(x, z, expected) in samples {
            let value = tiling_value(number, DVec3::new(x, 0.0, z));
            assert!(
                (value - expected).abs() < 1e-6,
                "tiling {number} at ({x}, {z}): {value} against {expected}"
            );
        }
    }

    #[test]
    fn squares_match_povray() {
        check(1, &[(0.25, 0.25, 0.5), (0.5, 0.5, 0.0), (0.75, 0.5, 0.5)]);
    }

    #[test]
    fn hexagons_match_povray() {
        check(
            2,
            &[
                (0.0, 0.25, 0.8556624),
                (0.5, 0.5, 0.4226497),
                (1.25, 0.25, 0.8943376),
                (1.75, 0.5, 0.5773503),
                (2.0, 0.0, 0.0),
                (0.5, 0.75, 0.1339746),
            ],
        );
    }

    #[test]
    fn triangles_match_povray() {
        check(
            3,
            &[
                (0.5, 0.25, 0.0669873),
                (0.25, 0.5, 0.9419873),
                (0.3125, 0.5, 0.4642627),
                (0.25, 1.0, 0.2679492),
                (0.5, 1.25, 0.6674682),
                (0.25, 1.75, 0.4689111),
            ],
        );
    }

    #[test]
    fn lozenges_and_cubes_match_povray() {
        check(
            4,
            &[
                (0.75, 0.375, 0.1339746),
                (0.125, 0.25, 0.9613249),
                (0.375, 0.625, 0.9716879),
                (0.5, 0.75, 0.8660254),
            ],
        );
        check(
            5,
            &[
                (0.75, 0.5, 0.0515668),
                (0.0, 0.75, 0.3779915),
                (-0.75, 0.25, 0.8075499),
                (-0.75, -0.5, 0.0515668),
                (1.0, 1.25, 0.8144585),
            ],
        );
    }

    #[test]
    fn staircase_and_octagons_match_povray() {
        check(
            6,
            &[
                (1.5, 0.5, 0.0),
                (1.25, 0.5, 0.25),
                (0.5, 0.25, 0.75),
                (1.25, 1.25, 0.75),
                (1.5, 1.5, 0.5),
            ],
        );
        check(
            7,
            &[
                (1.25, 1.25, 0.0606602),
                (1.0, 0.0, 0.7928932),
                (1.5, 1.5, 0.4142136),
                (0.75, 0.5, 0.6767767),
                (0.25, 0.25, 0.5),
            ],
        );
    }

    #[test]
    fn squares_and_triangles_match_povray() {
        check(
            8,
            &[
                (0.5, 0.5, 0.6666667),
                (0.5, 1.2, 0.1023932),
                (0.0, 1.5, 0.3779915),
                (0.1, 0.5, 0.8845300),
                (0.5, -0.3, 0.3398717),
                (0.0, -0.5, 0.0446582),
            ],
        );
    }

    #[test]
    fn hexagons_and_triangles_match_povray() {
        check(
            9,
            &[
                (0.5, 0.866, 0.6666667),
                (1.5, 0.3, 0.0065384),
                (0.5, -0.3, 0.3398717),
                (1.2, 0.9, 0.7196152),
                (0.1, 0.2, 0.7845299),
            ],
        );
    }

    #[test]
    fn offset_squares_match_povray() {
        check(
            10,
            &[
                (0.5, 0.5, 0.0),
                (0.25, 0.75, 0.5),
                (0.0, 1.5, 0.0),
                (0.5, 1.75, 1.0),
                (0.25, 1.25, 0.5),
            ],
        );
    }

    #[test]
    fn rectangle_and_square_tilings_match_povray() {
        check(
            11,
            &[
                (-2.114, -4.19, 0.9240000),
                (1.811, -5.131, 0.5793333),
                (0.431, -1.612, 0.7126667),
                (-5.304, 0.089, 0.9406667),
                (-5.55, -0.796, 0.5306666),
                (-5.162, -4.911, 0.8920000),
            ],
        );
        check(
            12,
            &[
                (-0.906, 3.922, 0.6146666),
                (-4.514, -3.321, 0.4526667),
                (1.529, 5.373, 0.4180000),
                (0.925, -1.24, 0.9500000),
                (5.715, -5.441, 0.8100000),
                (4.302, -2.525, 0.4653333),
            ],
        );
        check(
            15,
            &[
                (2.753, -2.545, 0.5450000),
                (5.762, -4.583, 0.2620000),
                (-0.983, 3.086, 0.9830000),
                (-4.176, -0.132, 0.8680000),
                (-5.53, 2.019, 0.4810000),
                (3.175, 0.876, 0.8250000),
            ],
        );
        check(
            18,
            &[
                (-4.448, -3.029, 0.4710000),
                (-1.309, 4.457, 0.0430000),
                (-5.033, -0.61, 0.9670000),
                (0.593, 4.601, 0.5930000),
                (3.831, 4.368, 0.3310000),
                (-2.659, -1.016, 0.4840000),
            ],
        );
    }

    #[test]
    fn trapezoid_tilings_match_povray() {
        check(
            13,
            &[
                (-4.269, -4.586, 0.0000000),
                (-2.298, 3.794, 0.8334248),
                (-3.831, 0.979, 0.0769899),
                (1.667, -1.531, 0.0000000),
                (0.573, -5.247, 0.5579028),
                (-5.285, -3.528, 0.7815209),
            ],
        );
        check(
            14,
            &[
                (2.165, -0.869, 0.1752911),
                (-2.23, 1.027, 0.3385215),
                (-0.562, -2.403, 0.5453709),
                (3.533, 2.388, 0.6943417),
                (-3.071, 0.893, 0.0627801),
                (0.302, 4.502, 0.2291630),
            ],
        );
    }

    #[test]
    fn hexagon_square_triangle_tilings_match_povray() {
        check(
            16,
            &[
                (4.506, -2.235, 0.2724117),
                (2.344, 1.132, 0.2202441),
                (0.959, -0.526, 0.9699778),
                (4.08, 5.336, 0.6666667),
                (-0.311, 1.97, 0.2043631),
                (-5.272, 2.418, 0.6666667),
            ],
        );
        check(
            17,
            &[
                (1.766, 5.917, 0.1394725),
                (3.863, -2.585, 0.8333335),
                (-1.371, 2.024, 0.9087933),
                (-5.729, -0.46, 0.8333335),
                (-3.983, -4.595, 0.9519368),
                (-5.293, 3.219, 0.8600955),
            ],
        );
    }

    #[test]
    fn snub_tilings_match_povray() {
        check(
            19,
            &[
                (-1.695, 4.61, 0.6768305),
                (5.493, -4.189, 0.5921869),
                (-3.885, -3.217, 0.6390025),
                (-3.2, -0.18, 0.5705897),
                (1.069, -2.847, 0.3793829),
                (-5.951, -0.973, 0.6666670),
            ],
        );
        check(
            20,
            &[
                (-1.569, 0.796, 0.6666670),
                (5.437, 2.286, 0.2161561),
                (0.186, 1.411, 0.9993588),
                (2.114, -5.352, 0.6666670),
                (4.794, 3.36, 0.5464604),
                (4.494, 3.574, 0.2064336),
            ],
        );
        check(
            21,
            &[
                (-1.291, -1.212, 0.1233507),
                (-4.758, 1.611, 0.9370091),
                (-5.253, -5.192, 0.1136573),
                (-3.495, -4.052, 0.1137979),
                (-1.919, -5.369, 0.8010750),
                (-5.997, -4.185, 0.9660351),
            ],
        );
    }

    #[test]
    fn dodecagon_tilings_match_povray() {
        check(
            22,
            &[
                (-4.782, -1.637, 0.6666667),
                (-5.694, 4.492, 0.9653194),
                (1.369, -4.217, 0.6666667),
                (-2.973, -1.831, 0.6666667),
                (-1.63, -4.526, 0.6666667),
                (4.187, 5.917, 0.6666667),
            ],
        );
        check(
            23,
            &[
                (-0.408, -0.194, 0.6666670),
                (-4.969, -4.774, 0.2065989),
                (-1.888, -2.823, 0.0622876),
                (3.946, -4.063, 0.2215018),
                (-5.723, 5.412, 0.9050558),
                (0.339, -4.241, 0.0000000),
            ],
        );
        check(
            24,
            &[
                (0.518, -5.675, 0.9928002),
                (0.337, 5.742, 0.8000002),
                (4.36, 2.354, 0.3512203),
                (-2.867, -1.6, 0.9996104),
                (-3.995, 3.263, 0.9240732),
                (0.391, 3.349, 0.1532203),
            ],
        );
    }

    #[test]
    fn edges_belong_to_the_tile_along_plus_z_or_plus_x() {
        // On the vertical edge x = 0 between a flat and an upright rectangle, and on the
        // horizontal edge z = −1 between a flat and an upright block.
        check(11, &[(-3.0, -0.5, 0.6666667)]);
        check(12, &[(-2.25, -1.0, 0.6666667)]);
    }

    #[test]
    fn dodecagons_of_tiling_22_bevel_some_edges_wider() {
        check(
            22,
            &[
                (1.7, -1.366, 0.8339746),
                (1.55, -1.0, 0.6839746),
                (0.0, 0.3, 0.7690599),
            ],
        );
    }

    #[test]
    fn flat_tiles_lie_a_hair_above_their_type_value() {
        // POV-Ray's colour maps switch at exactly k / types to the next type's colour.
        let hexagon_centre = tiling_value(17, DVec3::new(-1.0, 0.0, 0.0));
        assert!(hexagon_centre > 5.0 / 6.0 && hexagon_centre < 5.0 / 6.0 + 1e-6);
        let dodecagon_centre = tiling_value(22, DVec3::new(0.0, 0.0, -1.366));
        assert!(dodecagon_centre > 2.0 / 3.0 && dodecagon_centre < 2.0 / 3.0 + 1e-6);
    }

    #[test]
    fn trapezoid_tilings_give_zero_on_the_axes() {
        check(13, &[(0.5, 0.0, 0.0), (0.0, 0.5, 0.0), (0.5, 1e-300, 0.0)]);
        check(14, &[(-2.25, 0.0, 0.0), (0.0, -1.0, 0.0)]);
    }
}
