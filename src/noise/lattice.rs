//! POV-Ray's lattice noise: the value-plus-gradient noise behind noise generators 1 and 2 and
//! behind every vector noise (the `turbulence` warp and `vturbulence`), whatever the generator.
//!
//! In: a point in pattern space. Out: the raw lattice sum (roughly [-1, 1]) for one of three
//! components. Holds: two constant tables, nothing else; no allocation.
//!
//! Everything here was measured from POV-Ray 3.7 with probe scenes (`scripts/probe-noise.py`):
//! - the point is shifted by +10000 on every axis and split into a lattice cell (floor) and
//!   the fraction inside it; each fraction is smoothed with the cubic 3t² − 2t³;
//! - each of the cell's 8 corners contributes `0.5·T[e] + T[e+1]·dx + T[e+2]·dy + T[e+3]·dz`
//!   (dx, dy, dz: the point minus the corner), weighted trilinearly by the smoothed fractions;
//!   vector noise takes its y and z components from `T[e+4..]` and `T[e+8..]`;
//! - the entry `e` (0 to 255) comes from hashing the corner's coordinates (mod 4096) through a
//!   4096-entry permutation, the identity shuffled by the LCG `s = s·1812433253 + 12345`
//!   (seed 0, draw `(s >> 16) & 0x7FFF`, swap position i with draw mod 4096, i from 4095
//!   down to 0): `e = P[P[P[x] ^ y] ^ z] & 255`;
//! - `T` holds 267 numbers of six significant digits, recovered by least squares from
//!   thousands of probe values (residual below 1e-14) and listed in `NOISE_TABLE`.

use glam::DVec3;

/// Number of entries in the hash permutation (lattice coordinates repeat with this period).
const HASH_SIZE: usize = 4096;

/// Offset POV-Ray adds to every coordinate before finding the lattice cell.
const LATTICE_OFFSET: f64 = 10000.0;

/// The identity permutation of 0..4096 shuffled by POV-Ray's LCG seeded with 0.
static HASH: [u16; HASH_SIZE] = shuffled_permutation();

/// Builds `HASH` at compile time: a downward Fisher–Yates-style pass whose swap partner is the
/// LCG's 15-bit draw modulo 4096.
const fn shuffled_permutation() -> [u16; HASH_SIZE] {
    let mut table = [0u16; HASH_SIZE];
    let mut i = 0;
    while i < HASH_SIZE {
        table[i] = i as u16;
        i += 1;
    }
    let mut state: u32 = 0;
    let mut position = HASH_SIZE;
    while position > 0 {
        position -= 1;
        state = state.wrapping_mul(1_812_433_253).wrapping_add(12_345);
        let partner = ((state >> 16) & 0x7FFF) as usize % HASH_SIZE;
        let held = table[position];
        table[position] = table[partner];
        table[partner] = held;
    }
    table
}

/// POV-Ray's table of random lattice values and gradients, as measured: entry `e` of the
/// scalar noise uses `[e..e + 4]`, vector noise also `[e + 4..e + 8]` and `[e + 8..e + 12]`.
#[rustfmt::skip]
static NOISE_TABLE: [f64; 267] = [
    -1.0, 0.604974, -0.937102, 0.414115, 0.576226, -0.0161593,
    0.432334, 0.103685, 0.590539, 0.0286412, 0.46981, -0.84622,
    -0.0734112, -0.304097, -0.40206, -0.210132, -0.919127, 0.652033,
    -0.83151, -0.183948, -0.671107, 0.852476, 0.043595, -0.404532,
    0.75494, -0.335653, 0.618433, 0.605707, 0.708583, -0.477195,
    0.899474, 0.490623, 0.221729, -0.400381, -0.853727, -0.932586,
    0.659113, 0.961303, 0.325948, -0.750851, 0.842466, 0.734401,
    -0.649866, 0.394491, -0.466056, -0.434073, 0.109026, 0.0847028,
    -0.738857, 0.241505, 0.16228, -0.71426, -0.883665, -0.150408,
    -0.90396, -0.686549, -0.785214, 0.488548, 0.0246433, 0.142473,
    -0.602136, 0.375845, -0.00779736, 0.498955, -0.268147, 0.856382,
    -0.386007, -0.596094, -0.867735, -0.570977, -0.914366, 0.28896,
    0.672206, -0.233783, 0.94815, 0.895262, 0.343252, -0.173388,
    -0.767971, -0.314748, 0.824308, -0.342092, 0.721431, -0.24004,
    -0.63653, 0.553277, 0.376272, 0.158984, -0.452659, 0.396323,
    -0.420676, -0.454154, 0.122179, 0.295857, 0.0664225, -0.202075,
    -0.724788, 0.453513, 0.224567, -0.908812, 0.176349, -0.320516,
    -0.697139, 0.742702, -0.900786, 0.471489, -0.133532, 0.119127,
    -0.889769, -0.23183, -0.669673, -0.046891, -0.803433, -0.966735,
    0.475578, -0.652644, 0.0112459, -0.730007, 0.128283, 0.145647,
    -0.619318, 0.272023, 0.392966, 0.646418, -0.0207675, -0.315908,
    0.480797, 0.535668, -0.250172, -0.83093, -0.653773, -0.443809,
    0.119982, -0.897642, 0.89453, 0.165789, 0.633875, -0.886839,
    0.930877, -0.537194, 0.587732, 0.722011, -0.209461, -0.0424659,
    -0.814267, -0.919432, 0.280262, -0.66302, -0.558099, -0.537469,
    -0.598779, 0.929656, -0.170794, -0.537163, 0.312581, 0.959442,
    0.722652, 0.499931, 0.175616, -0.534874, -0.685115, 0.444999,
    0.17171, 0.108202, -0.768704, -0.463828, 0.254231, 0.546014,
    0.869474, 0.875212, -0.944427, 0.130724, -0.110185, 0.312184,
    -0.33138, -0.629206, 0.0606546, 0.722866, -0.0979477, 0.821561,
    0.0931258, -0.972808, 0.0318151, -0.867033, -0.387228, 0.280995,
    -0.218189, -0.539178, -0.427359, -0.602075, 0.311971, 0.277974,
    0.773159, 0.592493, -0.0331884, -0.630854, -0.269947, 0.339132,
    0.581079, 0.209461, -0.317433, -0.284993, 0.181323, 0.341634,
    0.804959, -0.229572, -0.758907, -0.336721, 0.605463, -0.991272,
    -0.0188754, -0.300191, 0.368307, -0.176135, -0.3832, -0.749569,
    0.62356, -0.573938, 0.278309, -0.971313, 0.839994, -0.830686,
    0.439078, 0.66128, 0.694514, 0.0565042, 0.54342, -0.438804,
    -0.0228428, -0.687068, 0.857267, 0.301991, -0.494255, -0.941039,
    0.775509, 0.410575, -0.362081, -0.671534, -0.348379, 0.932433,
    0.886442, 0.868681, -0.225666, -0.062211, -0.0976425, -0.641444,
    -0.848112, 0.724697, 0.473503, 0.998749, 0.174701, 0.559625,
    -0.029099, -0.337392, -0.958129, -0.659785, 0.236042, -0.246937,
    0.659449, -0.027512, 0.821897, -0.226215, 0.0181735, 0.500481,
    -0.420127, -0.427878, 0.566186,
];

/// POV-Ray's 12-bit hash of the integer triple `(x, y, z)` (each taken modulo 4096):
/// `P[P[P[x] ^ y] ^ z]` through the shuffled permutation.
pub(super) fn hash3(x: i32, y: i32, z: i32) -> usize {
    let mask = HASH_SIZE as i32 - 1;
    let xy = HASH[HASH[(x & mask) as usize] as usize ^ (y & mask) as usize] as usize;
    HASH[xy ^ (z & mask) as usize] as usize
}

/// The hash entry (0 to 255) of the lattice corner `(x, y, z)`.
fn corner_entry(x: i32, y: i32, z: i32) -> usize {
    hash3(x, y, z) & 0xFF
}

/// Lattice cell of one coordinate: the cell index and the fraction inside it, as POV-Ray
/// computes them. Beyond the 32-bit range the index is `i32::MIN` (what the x86 conversion
/// POV-Ray relies on yields), which makes the fraction huge and the result garbage, as there.
fn cell(coordinate: f64) -> (i32, f64) {
    let shifted = coordinate + LATTICE_OFFSET;
    let floor = shifted.floor();
    let index = if (-2_147_483_648.0..2_147_483_648.0).contains(&floor) {
        floor as i32
    } else {
        i32::MIN
    };
    (index, shifted - f64::from(index))
}

/// The cubic ease curve 3t² − 2t³.
fn smooth(t: f64) -> f64 {
    t * t * (3.0 - 2.0 * t)
}

/// Sums the corner contributions of the cell around `point` for the table slices starting at
/// `component_offsets` (0 for x, 4 for y, 8 for z), one sum per offset.
fn lattice_sums<const N: usize>(point: DVec3, component_offsets: [usize; N]) -> [f64; N] {
    let (ix, fx) = cell(point.x);
    let (iy, fy) = cell(point.y);
    let (iz, fz) = cell(point.z);
    let (sx, sy, sz) = (smooth(fx), smooth(fy), smooth(fz));
    let mut sums = [0.0; N];
    for corner in 0..8 {
        let (cx, cy, cz) = (corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        // Trilinear weight of this corner and the point's offset from it.
        let weight = (if cx == 1 { sx } else { 1.0 - sx })
            * (if cy == 1 { sy } else { 1.0 - sy })
            * (if cz == 1 { sz } else { 1.0 - sz });
        let (dx, dy, dz) = (fx - cx as f64, fy - cy as f64, fz - cz as f64);
        let entry = corner_entry(
            ix.wrapping_add(cx),
            iy.wrapping_add(cy),
            iz.wrapping_add(cz),
        );
        for (sum, offset) in sums.iter_mut().zip(component_offsets) {
            let values = &NOISE_TABLE[entry + offset..entry + offset + 4];
            *sum += weight * (0.5 * values[0] + values[1] * dx + values[2] * dy + values[3] * dz);
        }
    }
    sums
}

/// The raw scalar lattice sum at `point` (generators 1 and 2 map it to [0, 1]).
pub(super) fn scalar_sum(point: DVec3) -> f64 {
    lattice_sums(point, [0])[0]
}

/// The vector lattice noise at `point`: three independent lattice sums.
pub(super) fn vector_sum(point: DVec3) -> DVec3 {
    let [x, y, z] = lattice_sums(point, [0, 4, 8]);
    DVec3::new(x, y, z)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hash_is_a_permutation() {
        let mut seen = [false; HASH_SIZE];
        for &value in HASH.iter() {
            seen[value as usize] = true;
        }
        assert!(seen.iter().all(|&s| s));
    }

    #[test]
    fn lattice_points_give_half_the_table_value() {
        // At a lattice point only one corner counts and its offsets are zero.
        let entry = corner_entry(10000, 10000, 10000);
        assert_eq!(scalar_sum(DVec3::ZERO), 0.5 * NOISE_TABLE[entry]);
    }

    #[test]
    fn far_points_do_not_panic() {
        for coordinate in [1e300, -1e300, f64::INFINITY, f64::NAN, 3e9, -3e9] {
            let _ = vector_sum(DVec3::splat(coordinate));
        }
    }
}
