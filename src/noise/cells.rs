//! The per-cube random numbers of the `cells` and `crackle` patterns, as measured from
//! POV-Ray 3.7.
//!
//! In: a point or an integer unit cube. Out: the cube's random value or random feature point.
//! Holds: one constant table of 32-bit random numbers; no allocation.
//!
//! What the probes showed: a cube's numbers are chosen by POV-Ray's 12-bit hash of its integer
//! corner (the noise lattice's hash, without the lattice's +10000 offset) from a table of
//! 32-bit numbers that is the standard MT19937 generator's output with its default seed 5489,
//! each divided by 2³². `cells` takes entry `h`; crackle's feature point of the cube is the
//! corner plus entries `h`, `h + 1` and `h + 2` on x, y and z. Both reproduce povray to the
//! last bit on the probes.

use super::lattice::hash3;
use glam::DVec3;

/// Number of MT19937 outputs used: one per hash value plus the two a feature point reads past.
const TABLE_SIZE: usize = 4096 + 2;

/// MT19937's state size, the offset of the word mixed in, and its default seed.
const STATE_SIZE: usize = 624;
const MIX_OFFSET: usize = 397;
const DEFAULT_SEED: u32 = 5489;

/// Amount `cells` adds to each coordinate before flooring (measured: a point 1e-10 below an
/// integer already belongs to the next cube, one 1e-9 below does not).
const CELLS_EPSILON: f64 = 1e-10;

/// The first `TABLE_SIZE` outputs of MT19937 seeded with 5489.
static RANDOM_TABLE: [u32; TABLE_SIZE] = mersenne_twister_outputs();

/// Runs the MT19937 generator (Matsumoto and Nishimura's published algorithm) at compile time.
const fn mersenne_twister_outputs() -> [u32; TABLE_SIZE] {
    let mut state = [0u32; STATE_SIZE];
    state[0] = DEFAULT_SEED;
    let mut i = 1;
    while i < STATE_SIZE {
        let previous = state[i - 1];
        state[i] = 1_812_433_253u32
            .wrapping_mul(previous ^ (previous >> 30))
            .wrapping_add(i as u32);
        i += 1;
    }
    let mut outputs = [0u32; TABLE_SIZE];
    let mut produced = 0;
    while produced < TABLE_SIZE {
        // Regenerate the whole state block.
        let mut k = 0;
        while k < STATE_SIZE {
            let joined = (state[k] & 0x8000_0000) | (state[(k + 1) % STATE_SIZE] & 0x7FFF_FFFF);
            let twist = if joined & 1 == 1 { 0x9908_B0DF } else { 0 };
            state[k] = state[(k + MIX_OFFSET) % STATE_SIZE] ^ (joined >> 1) ^ twist;
            k += 1;
        }
        // Temper each word of the block into an output.
        let mut k = 0;
        while k < STATE_SIZE && produced < TABLE_SIZE {
            let mut y = state[k];
            y ^= y >> 11;
            y ^= (y << 7) & 0x9D2C_5680;
            y ^= (y << 15) & 0xEFC6_0000;
            y ^= y >> 18;
            outputs[produced] = y;
            produced += 1;
            k += 1;
        }
    }
    outputs
}

/// Table entry `index` as a number in [0, 1).
fn unit_random(index: usize) -> f64 {
    f64::from(RANDOM_TABLE[index]) / 4_294_967_296.0
}

/// The integer cube `(x, y, z)`'s hash: the index of its first random number.
fn cube_hash(cube: [i64; 3]) -> usize {
    // Only the low 12 bits of each coordinate matter; truncating to i32 keeps them.
    hash3(cube[0] as i32, cube[1] as i32, cube[2] as i32)
}

/// The `cells` pattern's value at `point`: the random number of the unit cube holding it.
pub fn cells_value(point: DVec3) -> f64 {
    let corner = (point + DVec3::splat(CELLS_EPSILON)).floor();
    // Non-finite or huge coordinates saturate; any cube is as good as another there.
    cube_random_value([corner.x as i64, corner.y as i64, corner.z as i64])
}

/// The random number in [0, 1) of the unit cube whose lowest corner is `cube`.
pub fn cube_random_value(cube: [i64; 3]) -> f64 {
    unit_random(cube_hash(cube))
}

/// Three random numbers in [0, 1) of the unit cube whose lowest corner is `cube`: crackle's
/// feature point offset, and the jitter of a repeated black hole warp's centre in the repeat
/// cell with that index (measured: the same numbers to the last bit).
pub fn cube_random_vector(cube: [i64; 3]) -> DVec3 {
    let hash = cube_hash(cube);
    DVec3::new(
        unit_random(hash),
        unit_random(hash + 1),
        unit_random(hash + 2),
    )
}

/// Crackle's random feature point of the unit cube whose lowest corner is `cube` (inside that
/// cube).
pub fn crackle_feature_point(cube: [i64; 3]) -> DVec3 {
    DVec3::new(cube[0] as f64, cube[1] as f64, cube[2] as f64) + cube_random_vector(cube)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_is_the_standard_generator() {
        // MT19937's well-known first outputs for seed 5489.
        assert_eq!(
            RANDOM_TABLE[..3],
            [3_499_211_612, 581_869_302, 3_890_346_734]
        );
    }

    #[test]
    fn cells_values_match_povray() {
        // Printed by POV-Ray 3.7 for function { pattern { cells } }.
        let cases = [
            (DVec3::new(-2.5, -2.5, -2.5), 0.5307975534815341),
            (DVec3::new(-2.5, -2.5, -1.5), 0.0567046923097223),
            (DVec3::new(0.9999999999, 0.5, 0.5), 0.6812713705003262),
            (DVec3::new(0.999999999, 0.5, 0.5), 0.7118189153261483),
            (DVec3::new(-1e-9, 0.5, 0.5), 0.5669548758305609),
        ];
        for (point, expected) in cases {
            assert!((cells_value(point) - expected).abs() < 1e-15, "{point}");
        }
    }

    #[test]
    fn crackle_distances_match_povray() {
        // Distance to the nearest feature point: crackle with form <1, 0, 0>, from POV-Ray.
        for (point, expected) in CRACKLE_NEAREST {
            let point = DVec3::from_array(point);
            let cube = point.floor();
            let mut nearest = f64::INFINITY;
            for dx in -2..=2 {
                for dy in -2..=2 {
                    for dz in -2..=2 {
                        let neighbour =
                            [cube.x as i64 + dx, cube.y as i64 + dy, cube.z as i64 + dz];
                        nearest = nearest.min(point.distance(crackle_feature_point(neighbour)));
                    }
                }
            }
            assert!((nearest - expected).abs() < 1e-12, "{point}");
        }
    }

    #[test]
    fn far_cubes_do_not_panic() {
        let _ = cells_value(DVec3::splat(f64::NAN));
        let _ = crackle_feature_point([i64::MAX, i64::MIN, 0]);
    }

    /// Points and POV-Ray's `crackle form <1, 0, 0>` values there.
    const CRACKLE_NEAREST: [([f64; 3], f64); 12] = [
        (
            [
                -2.6203537290810863,
                0.44229225295951835,
                -1.3004483345192073,
            ],
            0.6961371119164249,
        ),
        (
            [1.0392003859619443, 1.2572030410805404, -4.344711407601869],
            0.43878169024136954,
        ),
        (
            [-4.868320084451259, 3.3746908209646005, -2.4064598567199234],
            0.6331957729947439,
        ),
        (
            [-2.6566903895330363, 4.956448355104628, -0.2973649247755201],
            0.5238171185454392,
        ),
        (
            [3.364614512743888, -0.23646791300665093, 1.3906814054416197],
            0.6197922834061345,
        ),
        (
            [-3.4938357597647607, 1.3486065828518843, 3.680453071432968],
            0.7373891521445666,
        ),
        (
            [0.23181210383301298, 2.4125185620149026, 1.7141147536959256],
            0.6591093656330187,
        ),
        (
            [-4.359685617730027, 2.5823024628681734, 0.9109958293131761],
            0.7316404081904322,
        ),
        (
            [-1.9873234048428765, -4.6898824853025, 3.655272369789456],
            0.6913489931303022,
        ),
        (
            [-0.2725091133453317, 2.1882392406580307, 3.788128002554817],
            0.3673749918429251,
        ),
        (
            [2.141294836112025, 4.210986675838745, -1.0503659599925608],
            0.4567936607316582,
        ),
        (
            [3.009087709852283, -0.5537894394923937, 4.35586721704521],
            0.6953543152522155,
        ),
    ];
}
