//! The `tiling N` pattern: periodic tilings of the x-z plane by convex tiles, each tile
//! bevelled towards its edges.
//!
//! In: a pattern-space point (y is ignored) and the tiling number. Out: the value in [0, 1].
//! Holds: static tables, no allocation; non-finite input is the caller's concern (the
//! pattern gives 0 for it).
//!
//! What a value means (manual, "Tiling Pattern", and measured against POV-Ray 3.7): a
//! tiling with `T` tile types gives a tile of type `k` the value `k / T` where it is farther
//! than the tiling's bevel width from every edge of the tile, rising linearly to `(k + 1) / T`
//! at the edges. Every tile of a tiling shares one bevel width; for the tilings made of one
//! regular polygon it is the polygon's inradius, so the bevel reaches the centre.
//!
//! Each layout below was measured with probe scenes (`pigment { tiling N }` through a
//! black-to-white colour map, sampled on grids with `#debug`): the period, the tiles in one
//! period, their types and the bevel width.

/// √3, for the tilings built on equilateral triangles and hexagons.
const SQRT_3: f64 = 1.732_050_807_568_877_2;

/// One tile: its type and its vertices (x, z) counter-clockwise or clockwise.
struct Tile {
    /// The tile type, below the layout's `types`.
    kind: u8,
    /// The corners of the convex tile.
    corners: &'static [(f64, f64)],
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
}

/// `tiling 1`: unit squares with corners on the integer lattice.
const SQUARES: Layout = Layout {
    period: [(1.0, 0.0), (0.0, 1.0)],
    types: 1,
    bevel: 0.5,
    tiles: &[Tile {
        kind: 0,
        corners: &[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)],
    }],
};

/// `tiling 2`: hexagons of side 1 with corners along ±x, one centred at (−1, 0).
const HEXAGONS: Layout = Layout {
    period: [(3.0, 0.0), (0.0, SQRT_3)],
    types: 1,
    bevel: SQRT_3 / 2.0,
    tiles: &[
        Tile {
            kind: 0,
            corners: &[
                (0.0, 0.0),
                (-0.5, SQRT_3 / 2.0),
                (-1.5, SQRT_3 / 2.0),
                (-2.0, 0.0),
                (-1.5, -SQRT_3 / 2.0),
                (-0.5, -SQRT_3 / 2.0),
            ],
        },
        Tile {
            kind: 0,
            corners: &[
                (1.5, SQRT_3 / 2.0),
                (1.0, SQRT_3),
                (0.0, SQRT_3),
                (-0.5, SQRT_3 / 2.0),
                (0.0, 0.0),
                (1.0, 0.0),
            ],
        },
    ],
};

/// `tiling 3`: equilateral triangles of side 1 with horizontal edges on `z = k √3/2`;
/// triangles pointing up (+z) are type 0, pointing down type 1.
const TRIANGLES: Layout = Layout {
    period: [(1.0, 0.0), (0.0, SQRT_3)],
    types: 2,
    bevel: SQRT_3 / 6.0,
    tiles: &[
        Tile {
            kind: 0,
            corners: &[(0.0, 0.0), (1.0, 0.0), (0.5, SQRT_3 / 2.0)],
        },
        Tile {
            kind: 1,
            corners: &[(0.5, SQRT_3 / 2.0), (1.0, 0.0), (1.5, SQRT_3 / 2.0)],
        },
        Tile {
            kind: 0,
            corners: &[(0.5, SQRT_3 / 2.0), (1.5, SQRT_3 / 2.0), (1.0, SQRT_3)],
        },
        Tile {
            kind: 1,
            corners: &[(0.0, SQRT_3), (0.5, SQRT_3 / 2.0), (1.0, SQRT_3)],
        },
    ],
};

/// Half of √3: the height of an equilateral triangle of side 1.
const H: f64 = SQRT_3 / 2.0;

/// `tiling 4`: rhombi of side 1 with 60° corners at the origin, edges along x and at 60°.
const LOZENGES: Layout = Layout {
    period: [(1.0, 0.0), (0.0, SQRT_3)],
    types: 1,
    bevel: SQRT_3 / 4.0,
    tiles: &[
        Tile {
            kind: 0,
            corners: &[(0.0, 0.0), (1.0, 0.0), (1.5, H), (0.5, H)],
        },
        Tile {
            kind: 0,
            corners: &[(0.5, H), (1.5, H), (2.0, SQRT_3), (1.0, SQRT_3)],
        },
    ],
};

/// `tiling 5`: the hexagons of `tiling 2` each cut into three rhombi (a stack of cubes):
/// type 0 the lower right, type 1 the left (long axis along z), type 2 the upper right.
const CUBES: Layout = Layout {
    period: [(3.0, 0.0), (0.0, SQRT_3)],
    types: 3,
    bevel: SQRT_3 / 4.0,
    tiles: &[
        // The hexagon centred at (0.5, √3/2).
        Tile {
            kind: 0,
            corners: &[(0.0, 0.0), (1.0, 0.0), (1.5, H), (0.5, H)],
        },
        Tile {
            kind: 1,
            corners: &[(0.0, 0.0), (0.5, H), (0.0, SQRT_3), (-0.5, H)],
        },
        Tile {
            kind: 2,
            corners: &[(0.5, H), (1.5, H), (1.0, SQRT_3), (0.0, SQRT_3)],
        },
        // The hexagon centred at (-1, 0).
        Tile {
            kind: 0,
            corners: &[(0.0, 0.0), (-1.0, 0.0), (-1.5, -H), (-0.5, -H)],
        },
        Tile {
            kind: 1,
            corners: &[(-1.0, 0.0), (-1.5, H), (-2.0, 0.0), (-1.5, -H)],
        },
        Tile {
            kind: 2,
            corners: &[(0.0, 0.0), (-0.5, H), (-1.5, H), (-1.0, 0.0)],
        },
    ],
};

/// `tiling 6`: 1 × 2 rectangles in a staircase: upright ones (long along z, type 1) and
/// flat ones (long along x, type 0).
const STAIRCASE: Layout = Layout {
    period: [(1.0, 1.0), (-2.0, 2.0)],
    types: 2,
    bevel: 0.5,
    tiles: &[
        Tile {
            kind: 1,
            corners: &[(0.0, 0.0), (1.0, 0.0), (1.0, 2.0), (0.0, 2.0)],
        },
        Tile {
            kind: 0,
            corners: &[(-2.0, 1.0), (0.0, 1.0), (0.0, 2.0), (-2.0, 2.0)],
        },
    ],
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
        Tile {
            kind: 1,
            corners: &[
                (OCTAGON_INRADIUS, -0.5),
                (OCTAGON_INRADIUS, 0.5),
                (0.5, OCTAGON_INRADIUS),
                (-0.5, OCTAGON_INRADIUS),
                (-OCTAGON_INRADIUS, 0.5),
                (-OCTAGON_INRADIUS, -0.5),
                (-0.5, -OCTAGON_INRADIUS),
                (0.5, -OCTAGON_INRADIUS),
            ],
        },
        Tile {
            kind: 0,
            corners: &[
                (OCTAGON_INRADIUS, 0.5),
                (2.0 * OCTAGON_INRADIUS - 0.5, OCTAGON_INRADIUS),
                (OCTAGON_INRADIUS, 2.0 * OCTAGON_INRADIUS - 0.5),
                (0.5, OCTAGON_INRADIUS),
            ],
        },
    ],
};

/// `tiling 8`: rows of unit squares (type 2) between rows of equilateral triangles, up
/// (type 0) and down (type 1); each square row is half a square along from the last.
const SQUARES_AND_TRIANGLES: Layout = Layout {
    period: [(1.0, 0.0), (0.5, 1.0 + H)],
    types: 3,
    bevel: SQRT_3 / 6.0,
    tiles: &[
        Tile {
            kind: 2,
            corners: &[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)],
        },
        Tile {
            kind: 0,
            corners: &[(0.0, 1.0), (1.0, 1.0), (0.5, 1.0 + H)],
        },
        Tile {
            kind: 1,
            corners: &[(0.5, 1.0 + H), (1.0, 1.0), (1.5, 1.0 + H)],
        },
    ],
};

/// `tiling 9`: hexagons of side 1 (type 2) meeting at their corners, with the triangles
/// between them pointing up (type 0) and down (type 1).
const HEXAGONS_AND_TRIANGLES: Layout = Layout {
    period: [(2.0, 0.0), (1.0, SQRT_3)],
    types: 3,
    bevel: SQRT_3 / 6.0,
    tiles: &[
        Tile {
            kind: 2,
            corners: &[
                (0.0, 0.0),
                (1.0, 0.0),
                (1.5, H),
                (1.0, SQRT_3),
                (0.0, SQRT_3),
                (-0.5, H),
            ],
        },
        Tile {
            kind: 0,
            corners: &[(1.0, 0.0), (2.0, 0.0), (1.5, H)],
        },
        Tile {
            kind: 1,
            corners: &[(0.0, 0.0), (0.5, -H), (1.0, 0.0)],
        },
    ],
};

/// `tiling 10`: unit squares in rows, each row half a square along from the last.
const OFFSET_SQUARES: Layout = Layout {
    period: [(1.0, 0.0), (0.5, 1.0)],
    types: 1,
    bevel: 0.5,
    tiles: &[Tile {
        kind: 0,
        corners: &[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)],
    }],
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
        _ => None,
    }
}

/// Whether `tiling number` is implemented.
pub fn is_supported(number: u8) -> bool {
    layout(number).is_some()
}

/// The value of `tiling number` at `point` (x and z); 0 for an unsupported number.
pub fn tiling_value(number: u8, point: glam::DVec3) -> f64 {
    let Some(layout) = layout(number) else {
        return 0.0;
    };
    // The point inside the period's parallelogram (lattice coordinates taken down to their
    // fractional parts); tiles reaching past it are tried shifted by one period each way.
    let [(ux, uz), (vx, vz)] = layout.period;
    let determinant = ux * vz - uz * vx;
    let along_u = ((point.x * vz - point.z * vx) / determinant).floor();
    let along_v = ((ux * point.z - uz * point.x) / determinant).floor();
    let x = point.x - along_u * ux - along_v * vx;
    let z = point.z - along_u * uz - along_v * vz;
    let mut best_kind = 0;
    let mut best_depth = f64::NEG_INFINITY;
    for shift_u in [-1.0, 0.0, 1.0] {
        for shift_v in [-1.0, 0.0, 1.0] {
            let tile_x = x - shift_u * ux - shift_v * vx;
            let tile_z = z - shift_u * uz - shift_v * vz;
            for tile in layout.tiles {
                let inside = depth_inside(tile.corners, tile_x, tile_z);
                if inside > best_depth {
                    best_depth = inside;
                    best_kind = tile.kind;
                }
            }
        }
    }
    let rise = (1.0 - best_depth.max(0.0) / layout.bevel).clamp(0.0, 1.0);
    (f64::from(best_kind) + rise) / f64::from(layout.types)
}

/// The distance from `(x, z)` to the nearest edge of a convex polygon, negative outside
/// (the smallest signed distance to the edges' lines, either winding).
fn depth_inside(corners: &[(f64, f64)], x: f64, z: f64) -> f64 {
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
            orientation * (edge_x * (z - az) - edge_z * (x - ax)) / length
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
}
