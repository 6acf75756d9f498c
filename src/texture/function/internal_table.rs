//! The internal functions durer implements: each one's name, POV-Ray's number for it
//! (`internal(N)`) and its number of arguments.
//!
//! In: a number from `function { internal(N) }`. Out: the [`Internal`] it names, if durer
//! implements it. Holds: [`FUNCTIONS`] is in POV-Ray's order, the order of the enum.

/// One implemented internal function, named after its functions.inc declaration, in the
/// order of POV-Ray's numbers (the order of [`FUNCTIONS`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Internal {
    /// 0, `f_algbr_cyl1(x,y,z, strength, limit, sor switch, sor offset, sor angle)`.
    AlgebraicCylinder1,
    /// 1, `f_algbr_cyl2, the same parameters`.
    AlgebraicCylinder2,
    /// 2, `f_algbr_cyl3, the same parameters`.
    AlgebraicCylinder3,
    /// 3, `f_algbr_cyl4, the same parameters`.
    AlgebraicCylinder4,
    /// 4, `f_bicorn(x,y,z, strength, scale)`.
    Bicorn,
    /// 5, `f_bifolia(x,y,z, strength, scale)`.
    Bifolia,
    /// 6, `f_blob(x,y,z, separation, strength1, inverse radius1, strength2, inverse radius2)`.
    Blob,
    /// 7, `f_blob2(x,y,z, separation, inverse size, strength, threshold)`.
    Blob2,
    /// 8, `f_boy_surface(x,y,z, strength, scale)`.
    BoySurface,
    /// 9, `f_comma(x,y,z, scale)`.
    Comma,
    /// 10, `f_cross_ellipsoids(x,y,z, eccentricity, inverse size, diameter, threshold)`.
    CrossEllipsoids,
    /// 11, `f_crossed_trough(x,y,z, strength)`.
    CrossedTrough,
    /// 12, `f_cubic_saddle(x,y,z, strength)`.
    CubicSaddle,
    /// 13, `f_cushion(x,y,z, strength)`.
    Cushion,
    /// 14, `f_devils_curve(x,y,z, strength)`.
    DevilsCurve,
    /// 15, `f_devils_curve_2d(x,y,z, strength, x factor, y factor, sor switch, sor offset, sor angle)`.
    DevilsCurve2d,
    /// 16, `f_dupin_cyclid(x,y,z, strength, major, minor, x shift, y shift, inversion radius)`.
    DupinCyclid,
    /// 17, `f_ellipsoid(x,y,z, sx, sy, sz): |(sx x, sy y, sz z)|`.
    Ellipsoid,
    /// 18, `f_enneper(x,y,z, strength)`.
    Enneper,
    /// 19, `f_flange_cover(x,y,z, spikiness, inverse size, flange, threshold)`.
    FlangeCover,
    /// 20, `f_folium_surface(x,y,z, strength, neck, divergence)`.
    FoliumSurface,
    /// 21, `f_folium_surface_2d(x,y,z, strength, neck, divergence, sor switch, sor offset, sor angle)`.
    FoliumSurface2d,
    /// 22, `f_glob(x,y,z, strength)`.
    Glob,
    /// 23, `f_heart(x,y,z, strength)`.
    Heart,
    /// 24, `f_helical_torus(x,y,z, major, loops, twist, fatness, threshold, inner, winding
    /// fatness, groove period, groove amplitude, groove phase)`.
    HelicalTorus,
    /// 25, `f_helix1(x,y,z, count, period, minor, major, shape, section, section angle)`.
    Helix1,
    /// 26, `f_helix2(x,y,z, unused, period, minor, major, unused, section, unused angle)`.
    Helix2,
    /// 27, `f_hex_x(x,y,z, unused)`.
    HexagonalPrisms,
    /// 28, `f_hex_y(x,y,z, unused)`.
    HexagonalLines,
    /// 29, `f_hetero_mf(x,y,z, H, lacunarity, octaves, offset, T, generator)`.
    HeteroMultifractal,
    /// 30, `f_hunt_surface(x,y,z, strength)`.
    HuntSurface,
    /// 31, `f_hyperbolic_torus(x,y,z, strength, major, minor)`.
    HyperbolicTorus,
    /// 32, `f_isect_ellipsoids(x,y,z, eccentricity, inverse size, diameter, threshold)`.
    IsectEllipsoids,
    /// 33, `f_kampyle_of_eudoxus(x,y,z, strength, dimple, closeness)`.
    KampyleOfEudoxus,
    /// 34, `f_kampyle_of_eudoxus_2d(x,y,z, strength, dimple, closeness, sor switch, sor offset, sor angle)`.
    KampyleOfEudoxus2d,
    /// 35, `f_klein_bottle(x,y,z, strength)`.
    KleinBottle,
    /// 36, `f_kummer_surface_v1(x,y,z, strength)`.
    KummerSurface1,
    /// 37, `f_kummer_surface_v2(x,y,z, strength, rod width, divergence, rod length)`.
    KummerSurface2,
    /// 38, `f_lemniscate_of_gerono(x,y,z, strength)`.
    LemniscateOfGerono,
    /// 39, `f_lemniscate_of_gerono_2d(x,y,z, strength, size, width, sor switch, sor offset, sor angle)`.
    LemniscateOfGerono2d,
    /// 40, `f_mesh1(x,y,z, x spacing, z spacing, thickness, amplitude, y thickness)`.
    Mesh1,
    /// 41, `f_mitre(x,y,z, strength)`.
    Mitre,
    /// 42, `f_nodal_cubic(x,y,z, strength)`.
    NodalCubic,
    /// 43, `f_odd(x,y,z, strength)`.
    Odd,
    /// 44, `f_ovals_of_cassini(x,y,z, strength, major, filling, thickness)`.
    OvalsOfCassini,
    /// 45, `f_paraboloid(x,y,z, strength): strength (y - x² - z²)`.
    Paraboloid,
    /// 46, `f_parabolic_torus(x,y,z, strength, major, minor)`.
    ParabolicTorus,
    /// 47, `f_ph(x,y,z): the angle from the +y axis`.
    Phi,
    /// 48, `f_pillow(x,y,z, strength)`.
    Pillow,
    /// 49, `f_piriform(x,y,z, strength)`.
    Piriform,
    /// 50, `f_piriform_2d(x,y,z, strength, size1, size2, fatness, sor switch, sor offset, sor angle)`.
    Piriform2d,
    /// 51, `f_poly4(x,y,z, c0, c1, c2, c3, c4): the quartic in y revolved around the y axis`.
    Poly4,
    /// 52, `f_polytubes(x,y,z, count, c0, c1, c2, c3, c4)`.
    Polytubes,
    /// 53, `f_quantum(x,y,z, unused)`.
    Quantum,
    /// 54, `f_quartic_paraboloid(x,y,z, strength)`.
    QuarticParaboloid,
    /// 55, `f_quartic_saddle(x,y,z, strength)`.
    QuarticSaddle,
    /// 56, `f_quartic_cylinder(x,y,z, strength, diameter, width)`.
    QuarticCylinder,
    /// 57, `f_r(x,y,z): the distance from the origin`.
    Radius,
    /// 58, `f_ridge(x,y,z, lambda, octaves, omega, offset, ridge, generator)`.
    Ridge,
    /// 59, `f_ridged_mf(x,y,z, H, lacunarity, octaves, offset, gain, generator)`.
    RidgedMultifractal,
    /// 60, `f_rounded_box(x,y,z, radius, sx, sy, sz)`.
    RoundedBox,
    /// 61, `f_sphere(x,y,z, radius)`.
    Sphere,
    /// 62, `f_spikes(x,y,z, spikiness, hollowness, size, roundness, fatness)`.
    Spikes,
    /// 63, `f_spikes_2d(x,y,z, height, x frequency, z frequency, rate)`.
    Spikes2d,
    /// 64, `f_spiral(x,y,z, spacing, thickness, outer radius, -, -, section)`.
    Spiral,
    /// 65, `f_steiners_roman(x,y,z, strength)`.
    SteinersRoman,
    /// 66, `f_strophoid(x,y,z, strength, bulb, sharpness, fatness)`.
    Strophoid,
    /// 67, `f_strophoid_2d(x,y,z, strength, bulb, sharpness, fatness, sor switch, sor offset, sor angle)`.
    Strophoid2d,
    /// 68, `f_superellipsoid(x,y,z, e, n): 1 minus the superellipsoid's radius`.
    Superellipsoid,
    /// 69, `f_th(x,y,z): the angle around the y axis, atan2(x, z)`.
    Theta,
    /// 70, `f_torus(x,y,z, major, minor)`.
    Torus,
    /// 71, `f_torus2(x,y,z, strength, major, minor): the quartic torus field`.
    Torus2,
    /// 72, `f_torus_gumdrop(x,y,z, strength)`.
    TorusGumdrop,
    /// 73, `f_umbrella(x,y,z, strength)`.
    Umbrella,
    /// 74, `f_witch_of_agnesi(x,y,z, strength, width)`.
    WitchOfAgnesi,
    /// 75, `f_witch_of_agnesi_2d(x,y,z, strength, size, height, sor switch, sor offset, sor angle)`.
    WitchOfAgnesi2d,
    /// 76, `f_noise3d(x,y,z)`: solid noise in [0, 1]; compiled as `Node::SceneNoise`, which
    /// follows the scene's generator (evaluated here, it uses the default one).
    Noise3d,
    /// 78, `f_noise_generator(x,y,z, generator)`.
    NoiseGenerator,
}

/// Each implemented function with POV-Ray's number and its number of arguments (`x, y, z`
/// included), in the order of [`Internal`]'s variants.
const FUNCTIONS: [(Internal, u8, usize); 78] = [
    (Internal::AlgebraicCylinder1, 0, 8),
    (Internal::AlgebraicCylinder2, 1, 8),
    (Internal::AlgebraicCylinder3, 2, 8),
    (Internal::AlgebraicCylinder4, 3, 8),
    (Internal::Bicorn, 4, 5),
    (Internal::Bifolia, 5, 5),
    (Internal::Blob, 6, 8),
    (Internal::Blob2, 7, 7),
    (Internal::BoySurface, 8, 5),
    (Internal::Comma, 9, 4),
    (Internal::CrossEllipsoids, 10, 7),
    (Internal::CrossedTrough, 11, 4),
    (Internal::CubicSaddle, 12, 4),
    (Internal::Cushion, 13, 4),
    (Internal::DevilsCurve, 14, 4),
    (Internal::DevilsCurve2d, 15, 9),
    (Internal::DupinCyclid, 16, 9),
    (Internal::Ellipsoid, 17, 6),
    (Internal::Enneper, 18, 4),
    (Internal::FlangeCover, 19, 7),
    (Internal::FoliumSurface, 20, 6),
    (Internal::FoliumSurface2d, 21, 9),
    (Internal::Glob, 22, 4),
    (Internal::Heart, 23, 4),
    (Internal::HelicalTorus, 24, 13),
    (Internal::Helix1, 25, 10),
    (Internal::Helix2, 26, 10),
    (Internal::HexagonalPrisms, 27, 4),
    (Internal::HexagonalLines, 28, 4),
    (Internal::HeteroMultifractal, 29, 9),
    (Internal::HuntSurface, 30, 4),
    (Internal::HyperbolicTorus, 31, 6),
    (Internal::IsectEllipsoids, 32, 7),
    (Internal::KampyleOfEudoxus, 33, 6),
    (Internal::KampyleOfEudoxus2d, 34, 9),
    (Internal::KleinBottle, 35, 4),
    (Internal::KummerSurface1, 36, 4),
    (Internal::KummerSurface2, 37, 7),
    (Internal::LemniscateOfGerono, 38, 4),
    (Internal::LemniscateOfGerono2d, 39, 9),
    (Internal::Mesh1, 40, 8),
    (Internal::Mitre, 41, 4),
    (Internal::NodalCubic, 42, 4),
    (Internal::Odd, 43, 4),
    (Internal::OvalsOfCassini, 44, 7),
    (Internal::Paraboloid, 45, 4),
    (Internal::ParabolicTorus, 46, 6),
    (Internal::Phi, 47, 3),
    (Internal::Pillow, 48, 4),
    (Internal::Piriform, 49, 4),
    (Internal::Piriform2d, 50, 10),
    (Internal::Poly4, 51, 8),
    (Internal::Polytubes, 52, 9),
    (Internal::Quantum, 53, 4),
    (Internal::QuarticParaboloid, 54, 4),
    (Internal::QuarticSaddle, 55, 4),
    (Internal::QuarticCylinder, 56, 6),
    (Internal::Radius, 57, 3),
    (Internal::Ridge, 58, 9),
    (Internal::RidgedMultifractal, 59, 9),
    (Internal::RoundedBox, 60, 7),
    (Internal::Sphere, 61, 4),
    (Internal::Spikes, 62, 8),
    (Internal::Spikes2d, 63, 7),
    (Internal::Spiral, 64, 9),
    (Internal::SteinersRoman, 65, 4),
    (Internal::Strophoid, 66, 7),
    (Internal::Strophoid2d, 67, 10),
    (Internal::Superellipsoid, 68, 5),
    (Internal::Theta, 69, 3),
    (Internal::Torus, 70, 5),
    (Internal::Torus2, 71, 6),
    (Internal::TorusGumdrop, 72, 4),
    (Internal::Umbrella, 73, 4),
    (Internal::WitchOfAgnesi, 74, 5),
    (Internal::WitchOfAgnesi2d, 75, 9),
    (Internal::Noise3d, 76, 3),
    (Internal::NoiseGenerator, 78, 4),
];

impl Internal {
    /// The internal function with POV-Ray's number, when durer implements it.
    pub fn from_number(number: f64) -> Option<Internal> {
        if number.fract() != 0.0 || !(0.0..=255.0).contains(&number) {
            return None;
        }
        FUNCTIONS
            .iter()
            .find(|(_, known, _)| f64::from(*known) == number)
            .map(|(function, _, _)| *function)
    }

    /// POV-Ray's number for the function.
    pub fn number(self) -> u8 {
        FUNCTIONS[self as usize].1
    }

    /// Number of arguments, `x, y, z` included.
    pub fn arity(self) -> usize {
        FUNCTIONS[self as usize].2
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The table is in the variants' order, and every number leads back to its function.
    #[test]
    fn the_table_follows_the_variants() {
        for (index, (function, number, arity)) in FUNCTIONS.iter().enumerate() {
            assert_eq!(*function as usize, index);
            assert_eq!(Internal::from_number(f64::from(*number)), Some(*function));
            assert_eq!(function.number(), *number);
            assert!((3..=13).contains(arity));
        }
        assert_eq!(Internal::from_number(77.0), None);
        assert_eq!(Internal::from_number(79.0), None);
        assert_eq!(Internal::from_number(61.5), None);
    }
}
