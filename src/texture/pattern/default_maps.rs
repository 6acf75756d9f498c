//! The colour maps POV-Ray 3.7 builds into some patterns, used when a pigment names such a
//! pattern without a `color_map` (or `pigment_map`).
//!
//! In: the keyword the pattern was written with. Out: the map's (key, rgb) entries, sorted,
//! or an empty slice for the plain black-to-white ramp. Holds: static data only.
//!
//! Every map was measured against POV-Ray 3.7 by evaluating `function { pattern { P } }`
//! and `function { pigment { P } }` at the same points and fitting the colours as a
//! piecewise linear function of the value. A repeated key is a sharp step; with durer's map
//! lookup the earlier entry wins at the key itself. `spotted`, `julia` and `magnet` have no
//! map of their own (they use the grey ramp), unlike `bozo` and `mandel`.

/// A built-in colour map: (key, rgb) entries with non-decreasing keys.
pub type DefaultColourMap = &'static [(f64, [f64; 3])];

const WHITE: [f64; 3] = [1.0, 1.0, 1.0];
const BLACK: [f64; 3] = [0.0, 0.0, 0.0];
const RED: [f64; 3] = [1.0, 0.0, 0.0];
const GREEN: [f64; 3] = [0.0, 1.0, 0.0];
const BLUE: [f64; 3] = [0.0, 0.0, 1.0];
const CYAN: [f64; 3] = [0.0, 1.0, 1.0];
const YELLOW: [f64; 3] = [1.0, 1.0, 0.0];
const MAGENTA: [f64; 3] = [1.0, 0.0, 1.0];

/// `agate`: white fading to brown with two small steps.
const AGATE: DefaultColourMap = &[
    (0.0, WHITE),
    (0.5, [0.95, 0.75, 0.5]),
    (0.5, [0.9, 0.7, 0.5]),
    (0.6, [0.9, 0.7, 0.4]),
    (0.6, [1.0, 0.7, 0.4]),
    (1.0, [0.6, 0.3, 0.0]),
];

/// `bozo`: white, green, blue and red bands with sharp edges.
const BOZO: DefaultColourMap = &[
    (0.0, WHITE),
    (0.4, WHITE),
    (0.4, GREEN),
    (0.6, GREEN),
    (0.6, BLUE),
    (0.8, BLUE),
    (0.8, RED),
    (1.0, RED),
];

/// `mandel`: black inside, then cyan, yellow, magenta and back to cyan within the first
/// tenth.
const MANDEL: DefaultColourMap = &[
    (0.0, BLACK),
    (0.001, BLACK),
    (0.001, CYAN),
    (0.012, YELLOW),
    (0.015, MAGENTA),
    (0.1, CYAN),
    (1.0, CYAN),
];

/// `marble`: pale pink to red veins, then black.
const MARBLE: DefaultColourMap = &[
    (0.0, [0.9, 0.8, 0.8]),
    (0.9, [0.9, 0.08, 0.08]),
    (0.9, BLACK),
    (1.0, BLACK),
];

/// `radial`: cyan, yellow, magenta, cyan.
const RADIAL: DefaultColourMap = &[(0.0, CYAN), (0.333, YELLOW), (0.666, MAGENTA), (1.0, CYAN)];

/// `wood`: two browns with a sharp edge.
const WOOD: DefaultColourMap = &[
    (0.0, [0.666, 0.312, 0.2]),
    (0.6, [0.666, 0.312, 0.2]),
    (0.6, [0.4, 0.1333, 0.066]),
    (1.0, [0.4, 0.1333, 0.066]),
];

/// The built-in colour map of the pattern written as `keyword`; empty for the grey ramp.
pub fn default_colour_map(keyword: &str) -> DefaultColourMap {
    match keyword {
        "agate" => AGATE,
        "bozo" => BOZO,
        "mandel" => MANDEL,
        "marble" => MARBLE,
        "radial" => RADIAL,
        "wood" => WOOD,
        _ => &[],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn maps_are_sorted_and_span_zero_to_one() {
        for keyword in ["agate", "bozo", "mandel", "marble", "radial", "wood"] {
            let map = default_colour_map(keyword);
            assert_eq!(map.first().map(|entry| entry.0), Some(0.0));
            assert_eq!(map.last().map(|entry| entry.0), Some(1.0));
            assert!(map.windows(2).all(|pair| pair[0].0 <= pair[1].0));
        }
        assert!(default_colour_map("spotted").is_empty());
    }
}
