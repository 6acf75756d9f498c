//! The `pavement` pattern: the x-z plane paved with copies of one polyform tile (a shape
//! made of joined unit squares, equilateral triangles or hexagons), each tile shaded from 1
//! on its border to 0 half a cell inside.
//!
//! In: a pattern-space point (y is ignored) and the pavement settings. Out: the value in
//! [0, 1]. Holds: static tables of the measured pavings, no allocation.
//!
//! Measured against POV-Ray 3.7 (scripts/probe-pavement.py: `pigment { pavement .. }`
//! through a black-to-white colour map, sampled with `#debug`):
//! - The value is `1 - d / r`, clamped to [0, 1], where `r` is the basic polygon's inradius
//!   and `d` a distance to the tile's border measured in the part of the cell nearest to one
//!   of its corners (every border farther away gives a value of 0 anyway).
//!
//! Squares:
//! - Squares are the integer lattice. Each paving repeats over a rectangle of cells; the
//!   tables below give, for every cell of that rectangle, whether its bottom edge and its
//!   left edge are tile borders.
//! - The value is `1 - 2 d`, clamped to [0, 1], where `d` is a distance to the tile's border
//!   measured in the quarter of the cell around the point (every border farther away gives
//!   a value of 0 anyway). Along a border edge `d` is the distance to that edge.
//! - At a convex corner (both cell edges at the corner are borders) `exterior` shapes the
//!   corner: 0 square (`d` is the distance to the nearer edge), 1 cut by the line through
//!   the two half-edge midpoints (`d = u + w - 1/2`), 2 rounded about the cell's centre.
//! - At a concave corner (neither cell edge is a border but the corner is on the border)
//!   `interior` picks the distance to the corner point: 0 Chebyshev, 1 Manhattan,
//!   2 Euclidean.
//! - A cell where the tile turns (exactly two adjacent border edges, the opposite corner
//!   concave) follows `form` as a whole: 0 square inside and out (whatever `exterior` and
//!   `interior` say), 1 the middle line cut straight across the turn, 2 the middle line a
//!   quarter circle about the concave corner; 3 treats the cell like any other, so the
//!   corners follow `exterior` and `interior`.
//!
//! Triangles (side 1, one side along x, lattice points `(i + j/2, j √3/2)`): around a lattice
//! point the tile covers a run of `k` of the six triangles there, bounded by two border rays;
//! `d` measured from the point, with `ρ` the distance to it:
//! - `k` 1 (60°, `exterior`): 0 the distance to the nearer ray, 1 also cut by the line
//!   perpendicular to the corner's bisector at distance `r` from the corner, 2 rounded:
//!   `r - |p - incentre|`.
//! - `k` 2 (120°, `form`): 0 the distance to the nearer ray, 1 also `x / cos 30° - r` (`x`
//!   along the bisector), 2 also `cos 30° - |p - c|` (`c` the far end of the shared edge).
//! - `k` 3 to 5 (180° and concave, `interior`), besides the distance to a border edge of the
//!   triangle itself: 0 the larger distance to the two rays' lines (for `k` 5: `ρ cos δ`, `δ`
//!   the angle to the nearest direction 30° + 60°n), 1 `ρ cos 30° cos ε` (`ε` the angle to the
//!   nearest lattice direction), 2 `ρ cos 30°`.
//! - `form 3` is `form 0`.
//!
//! Hexagons (side 1, two sides along x): each hexagon is the six triangles around one point
//! of the same triangle lattice, so a hexagon paving is a paving of triangles and its values
//! follow the triangle rules (measured identical): the hexagon's centre has no border, so
//! the middle of every hexagon is 0; its 120° corners (`k` 2) follow `form`, its 240°
//! corners (`k` 4) `interior`; `exterior` never applies.
//!
//! Settings are truncated to integers and wrap like unsigned numbers: `form` modulo 4,
//! `exterior` and `interior` modulo 3 (so -1 gives 3 and 0).

/// The pavings of unit squares, by number of squares per tile (1 to 6) and pattern number
/// (from 1). Each paving is its repeating rectangle of cells, one string per row from
/// z = 0 upwards, one digit per cell from x = 0: bit 0 set when the cell's bottom edge is a
/// border, bit 1 when its left edge is.
#[rustfmt::skip]
const SQUARE_PAVINGS: [&[&[&str]]; 6] = [
    // 1 square
    &[
        &["3"],
    ],
    // 2 squares
    &[
        &["3", "2"],
    ],
    // 3 squares
    &[
        &["311"],
        &["331", "212"],
    ],
    // 4 squares
    &[
        &["3111"],
        &["3311", "2112"],
        &["3112", "1231"],
        &["31", "20"],
        &["13", "30", "31", "03"],
    ],
    // 5 squares
    &[
        &["31111"],
        &["33111", "21112"],
        &["13131", "30020", "31131", "20300", "31311", "00203", "11313", "03002", "13113", "02030"],
        &["31112", "11231", "23111", "11123", "12311"],
        &["30123", "12330", "33012", "01233", "23301"],
        &["3221131122", "2211311223", "2113112232", "1131122322", "1311223221", "3112232211", "1122322113", "1223221131", "2232211311", "2322113112"],
        &["2321213121", "3212131212", "2121312123", "1213121232", "2131212321", "1312123212", "3121232121", "1212321213", "2123212131", "1232121312"],
        &["3112323210", "2323210311", "3210311232", "0311232321", "1232321031", "2321031123", "1031123232", "1123232103", "3232103112", "2103112323"],
        &["32112", "21123", "11232", "12321", "23211"],
        &["33012", "21123", "12330", "23211", "30123", "11232", "23301", "32112", "01233", "12321"],
        &["13113", "30310", "31311", "03031", "13131", "10303", "11313", "31030", "31131", "03103"],
        &["3113012232", "3231130122", "2232311301", "0122323113", "1301223231"],
    ],
    // 6 squares
    &[
        &["311111"],
        &["311113", "231110"],
        &["311113", "123110"],
        &["311113", "112310"],
        &["303111", "130311", "113031", "111303", "311130", "031113"],
        &["311131", "203100"],
        &["131311", "300120"],
        &["310311", "131031", "113103", "311310", "031131", "103113"],
        &["131", "300"],
        &["311", "200"],
        &["3311", "2120", "2012"],
        &["311212", "112123", "121231", "212311", "123112", "231121"],
        &["3111", "3232", "2101"],
        &["311", "123", "221", "013"],
        &["310", "320", "031", "032", "103", "203"],
        &["330120", "012033", "203301"],
        &["301132", "323101", "011323", "231013", "113230", "310132", "132301", "101323", "323011", "013231", "230113", "132310"],
        &["323110", "211132", "231103", "111322", "311032", "113221", "110323", "132211", "103231", "322111", "032311", "221113"],
        &["321122", "211223", "112232", "122321", "223211", "232112"],
        &["231103", "323110", "032311", "103231", "110323", "311032"],
        &["223111", "122311", "112231", "111223", "311122", "231112"],
        &["3111", "2332", "1021"],
        &["2301", "2112", "3232"],
        &["313102", "321121", "023131", "213211", "310231", "112132"],
        &["31", "12", "21"],
        &["31", "20", "12"],
        &["31", "03", "21"],
        &["321121", "211213", "112132", "121321", "213211", "132112"],
        &["312321", "121031", "213123", "311210", "232131", "103112"],
        &["132112", "301231", "112132", "231301"],
        &["310132", "231103", "132310", "103231"],
        &["323101", "013231", "310132"],
        &["311", "312", "230", "211"],
        &["301132323110", "231103011323", "113232311030", "110301132323", "323231103011", "030113232311", "323110301132", "011323231103", "311030113232", "132323110301", "103011323231", "232311030113"],
        &["2310", "2112", "2332", "1023", "1221", "3223"],
    ],
];

/// The pavings of equilateral triangles, by number of triangles per tile (1 to 6) and
/// pattern number (from 1). Each paving is its repeating block of lattice points, one string
/// per row `j` from 0 upwards, one digit per point `i`: bit 0 set when the edge from P(i, j)
/// to P(i+1, j) is a border, bit 1 the edge to P(i, j+1), bit 2 the edge from P(i+1, j) to
/// P(i, j+1).
#[rustfmt::skip]
const TRIANGLE_PAVINGS: [&[&[&str]]; 6] = [
    // 1 triangle
    &[
        &["7"],
    ],
    // 2 triangles
    &[
        &["5"],
    ],
    // 3 triangles
    &[
        &["351", "135", "513"],
    ],
    // 4 triangles
    &[
        &["51", "15"],
        &["25", "52"],
        &["35", "60"],
    ],
    // 5 triangles
    &[
        &["31511", "11315", "15113", "13151", "51131"],
        &["31216", "16312", "12163", "63121", "21631"],
        &["51254", "54512", "12545", "45125", "25451"],
        &["31630", "63031", "03163", "16303", "30316"],
    ],
    // 6 triangles
    &[
        &["311"],
        &["611"],
        &["611", "161", "116"],
        &["315", "160", "531", "016", "153", "601"],
        &["313", "230", "331", "023", "133", "302"],
        &["331", "212", "313", "122", "133", "221"],
        &["31", "54", "12", "13", "45", "21"],
        &["31", "45", "03", "13", "54", "30"],
        &["351", "250", "135", "025", "513", "502"],
        &["341"],
        &["350", "035", "503"],
        &["241", "124", "412"],
    ],
];

/// The pavings of hexagons (side 1, two sides along x), by number of hexagons per tile (1 to
/// 5) and pattern number (from 1). Every hexagon is the six triangles of the triangle
/// lattice around one lattice point (the centres are P(1, 0) + a P(1, 1) + b P(3, 0)), so a
/// hexagon paving is a paving of triangles, written in the digits of [`TRIANGLE_PAVINGS`]
/// and valued the same way.
#[rustfmt::skip]
const HEXAGON_PAVINGS: [&[&[&str]]; 5] = [
    // 1 hexagon
    &[
        &["241", "124", "412"],
    ],
    // 2 hexagons
    &[
        &["241", "104", "412", "041", "124", "410"],
    ],
    // 3 hexagons
    &[
        &["241", "124", "402", "240", "024", "402"],
        &["241200201", "104124004", "002012412", "240041041", "124120020", "410412400", "200201241", "124004104", "012412002", "041041240", "120020124", "412400410", "201241200", "004104124", "412002012", "041240041", "020124120", "400410412"],
        &["241241001", "100124124", "412410012", "001241241", "124100124", "012412410", "241001241", "124124100", "410012412"],
    ],
    // 4 hexagons
    &[
        &["241", "124", "402", "240", "024", "402", "240", "024", "412", "241", "024", "402", "240", "024", "402", "240", "124", "412", "240", "024", "402", "240", "024", "402"],
        &["200041", "124100", "412000", "001241", "004120", "410012"],
        &["201001", "124124", "010012", "241241", "100120", "412412", "001201", "124124", "012010", "241241", "120100", "412412"],
        &["240240241041", "124024024104", "412402402410", "041240240241", "104124024024", "410412402402", "241041240240", "024104124024", "402410412402", "240241041240", "024024104124", "402402410412"],
        &["241040201240", "124104124120", "402410402012", "201241041241", "124024104020", "412012410412", "201240241040", "124120124104", "402012402410", "041241201241", "104020124024", "410412412012"],
        &["240241201200", "104024004124", "002402412012", "241040240041", "120024024120", "412410402400", "201200240241", "004124104024", "412012002402", "240041241040", "024120120024", "402400412410"],
        &["241241", "104020", "412412", "201040", "124124", "402010"],
    ],
    // 5 hexagons
    &[
        &["241", "124", "402", "240", "024", "402", "240", "024", "402", "240", "124", "412", "240", "024", "402", "240", "024", "402", "240", "024", "412", "241", "024", "402", "240", "024", "402", "240", "024", "402"],
        &["041240240240241", "104124024024024", "410412402402402", "241041240240240", "024104124024024", "402410412402402", "240241041240240", "024024104124024", "402402410412402", "240240241041240", "024024024104124", "402402402410412", "240240240241041", "124024024024104", "412402402402410"],
        &["241", "104", "002", "241", "024", "402", "240", "024", "012", "040", "124", "410", "200", "124", "402", "240", "024", "402", "201", "004", "412", "041", "020", "412", "240", "024", "402", "240", "120", "400"],
        &["240", "104", "002", "241", "024", "402", "201", "004", "412", "240", "024", "410", "200", "124", "402", "240", "120", "400", "241", "024", "402", "041", "020", "412", "240", "024", "012", "040", "124", "402"],
        &["040241240240241", "104024124024024", "410402412402402", "241040241240240", "024104024124024", "402410402412402", "240241040241240", "024024104024124", "402402410402412", "240240241040241", "124024024104024", "412402402410402", "241240240241040", "024124024024104", "402412402402410"],
        &["241", "104", "002", "040", "124", "402", "240", "104", "002", "040", "124", "410", "200", "004", "412", "240", "024", "410", "200", "004", "412", "041", "020", "400", "241", "024", "402", "041", "020", "400"],
        &["200", "124", "012", "040", "020", "400", "241", "104", "002", "040", "020", "412", "201", "004", "002", "040", "124", "410", "200", "004", "002", "241", "120", "400", "200", "004", "412", "041", "020", "400"],
        &["041241241040040201240200241041", "104104124124104004020124020024", "002410410412412410400402012402", "240200241041041241241040040201", "020124020024104104124124104004", "400402012402002410410412412410", "241040040201240200241041041241", "124124104004020124020024104104", "410412412410400402012402002410", "241041041241241040040201240200", "020024104104124124104004020124", "012402002410410412412410400402", "040201240200241041041241241040", "104004020124020024104104124124", "412410400402012402002410410412"],
        &["001201240240241", "120124024104124", "012402402410012", "240241041241201", "024024100120124", "410412412012402", "241001201240240", "124120124024104", "012012402402410", "201240241041241", "124024024100120", "402410412412012", "240241001201240", "104124120124024", "410012012402402", "241201240241041", "120124024024100", "012402410412412", "240240241001201", "024104124120124", "402410012012402", "041241201240241", "100120124024024", "412012402410412", "201240240241001", "124024104124120", "402402410012012", "241041241201240", "024100120124024", "412412012402410"],
        &["241241240241241", "104100104024100", "412412412402412", "001041001040241", "124124124124024", "410010410010402", "241241241241240", "024100104100104", "402412412412412", "040241001041001", "124024124124124", "010402410010410", "241240241241241", "100104024100104", "412412402412412", "041001040241001", "124124124024124", "010410010402410", "241241241240241", "100104100104024", "412412412412402", "241001041001040", "024124124124124", "402410010410010", "240241241241241", "104024100104100", "412402412412412", "001040241001041", "124124024124124", "410010402410010"],
        &["241200241241200", "104000120104004", "002412412002412", "001201040041040", "124120024120024", "010400410400012", "200241200241241", "004104000120104", "412002412412002", "040001201040041", "024124120024120", "012010400410400", "241200241200241", "104004104000120", "002412002412412", "041040001201040", "120024124120024", "400012010400410", "241241200241200", "120104004104000", "412002412002412", "040041040001201", "024120024124120", "410400012010400", "200241241200241", "000120104004104", "412412002412002", "201040041040001", "120024120024124", "400410400012010"],
        &["241201040000241", "104000024124120", "002412412010400"],
        &["201241240201241", "124020104124100", "402012412012412", "041241001240201", "120124124020124", "012402010412410", "240201241201241", "104124100124020", "412012412402012", "001240201041241", "124020124120124", "010412410012402", "241201241240201", "100124020104124", "412402012412012", "201041241001240", "124120124124020", "410012402010412", "241240201241201", "020104124100124", "012412012412402", "241001240201041", "124124020124120", "402010412410012", "201241201241240", "124100124020104", "012412402012412", "240201041241001", "020124120124124", "412410012402010"],
        &["241240201201240", "124020120124024", "402012012402412", "201201240241240", "120124024124020", "012402412402012", "240241240201201", "024124020120124", "412402012012402", "240201201240241", "020120124024124", "012012402412402", "201240241240201", "124024124020120", "402412402012012"],
        &["241240240201201", "124024020120124", "402402012012412", "240201201241240", "020120124124024", "012012412402402", "201241240240201", "124124024020120", "412402402012012", "240240201201241", "024020120124124", "402012012412402", "201201241240240", "120124124024020", "012412402402012"],
        &["201041240240001", "120024020124124", "412402400012010", "240201241241200", "024000120104124", "012412412002402", "001201041240240", "124120024020124", "010412402400012", "200240201241241", "124024000120104", "402012412412002", "240001201041240", "124124120024020", "012010412402400", "241200240201241", "104124024000120", "002402012412412", "240240001201041", "020124124120024", "400012010412402", "241241200240201", "120104124024000", "412002402012412", "041240240001201", "024020124124120", "402400012010412", "201241241200240", "000120104124024", "412412002402012"],
        &["041040241241240", "100020104124024", "412400410402412", "240241000201041", "024124124004104", "010412402410002"],
        &["241241240240241", "100124024020104", "412402402412412", "240240201041001", "024024124124124", "402010410012402", "241241241240240", "104100124024020", "412412402402412", "001240240201041", "124024024124124", "402402010410012", "240241241241240", "020104100124024", "412412412402402", "041001240240201", "124124024024124", "012402402010410", "240240241241241", "024020104100124", "402412412412402", "201041001240240", "124124124024024", "410012402402010", "241240240241241", "124024020104100", "402402412412412", "240201041001240", "024124124124024", "010410012402402"],
        &["241241240240241", "024024100120104", "402402412412412", "001201040240241", "124124124024024", "402402410012010", "240240241241241", "100120104024024", "412412412402402", "040240241001201", "124024024124124", "410012010402402", "241241241240240", "104024024100120", "412402402412412", "241001201040240", "024124124124024", "010402402410012", "241240240241241", "024100120104024", "402412412412402", "201040240241001", "124124024024124", "402410012010402", "240241241241240", "120104024024100", "412412402402412", "240241001201040", "024024124124124", "012010402402410"],
        &["241", "104", "002", "201", "124", "402", "240", "120", "012", "040", "124", "410", "200", "120", "412", "240", "024", "012", "201", "004", "412", "041", "020", "012", "241", "024", "402", "201", "120", "400"],
        &["241240201240201", "124020124020124", "402012402012412", "201240201241240", "124020124124020", "402012412402012", "201241240201240", "124124020124020", "412402012402012", "240201240201241", "020124020124124", "012402012412402", "240201241240201", "020124124020124", "012412402012402"],
        &["241241241240240", "120104024024100", "412412402402412", "040240241001201", "124024024124124", "402410012010402", "240241241241240", "100120104024024", "412412412402402", "201040240241001", "124124024024124", "402402410012010", "240240241241241", "024100120104024", "402412412412402", "001201040240241", "124124124024024", "010402402410012", "241240240241241", "024024100120104", "402402412412412", "241001201040240", "024124124124024", "012010402402410", "241241240240241", "104024024100120", "412402402412412", "240241001201040", "024024124124124", "410012010402402"],
    ],
];

/// The basic polygon a pavement tile is made of (`number_of_sides`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PavementPolygon {
    /// Equilateral triangles (`number_of_sides 3`, the default).
    Triangle,
    /// Unit squares (`number_of_sides 4`).
    Square,
    /// Hexagons (`number_of_sides 6`).
    Hexagon,
}

impl PavementPolygon {
    /// The polygon for a `number_of_sides` value; `None` for anything but 3, 4 or 6.
    pub fn from_sides(sides: f64) -> Option<Self> {
        match sides.trunc() {
            3.0 => Some(Self::Triangle),
            4.0 => Some(Self::Square),
            6.0 => Some(Self::Hexagon),
            _ => None,
        }
    }

    /// The largest `number_of_tiles` allowed: 6, or 5 for hexagons (not every tile of six
    /// hexagons paves the plane).
    pub fn max_tiles(self) -> u8 {
        match self {
            Self::Hexagon => 5,
            Self::Triangle | Self::Square => 6,
        }
    }

    /// How many patterns there are for tiles of `tiles` polygons (manual, "Pavement
    /// Pattern"); 0 when `tiles` is out of range.
    pub fn pattern_count(self, tiles: u8) -> u8 {
        let index = usize::from(tiles).wrapping_sub(1);
        match self {
            Self::Triangle => TRIANGLE_PAVINGS.get(index).map_or(0, |p| p.len() as u8),
            Self::Square => SQUARE_PAVINGS.get(index).map_or(0, |p| p.len() as u8),
            Self::Hexagon => HEXAGON_PAVINGS.get(index).map_or(0, |p| p.len() as u8),
        }
    }
}

/// The settings of one `pavement` pattern.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Pavement {
    /// `number_of_sides`.
    pub polygon: PavementPolygon,
    /// `number_of_tiles`: polygons per tile, 1 to [`PavementPolygon::max_tiles`].
    pub tiles: u8,
    /// `pattern`: which tile of that size, from 1 to [`PavementPolygon::pattern_count`].
    pub pattern: u8,
    /// `form`: how the tile turns (see the module header).
    pub form: u8,
    /// `exterior`: how convex corners look.
    pub exterior: u8,
    /// `interior`: how concave corners look.
    pub interior: u8,
}

impl Default for Pavement {
    /// POV-Ray's defaults: single triangles, everything else 0.
    fn default() -> Self {
        Self {
            polygon: PavementPolygon::Triangle,
            tiles: 1,
            pattern: 1,
            form: 0,
            exterior: 0,
            interior: 0,
        }
    }
}

/// A corner setting as POV-Ray reads it: truncated, wrapped like an unsigned 32-bit number,
/// then taken modulo `choices`.
pub fn corner_setting(value: f64, choices: u32) -> u8 {
    let truncated = if value.is_finite() {
        value.trunc()
    } else {
        0.0
    };
    ((truncated as i64 as u32) % choices) as u8
}

impl Pavement {
    /// The value in [0, 1] at pattern-space point `p`.
    pub fn value(&self, x: f64, z: f64) -> f64 {
        match self.polygon {
            PavementPolygon::Square => self.square_value(x, z),
            PavementPolygon::Triangle => {
                self.triangle_value(paving(&TRIANGLE_PAVINGS, self.tiles, self.pattern), x, z)
            }
            PavementPolygon::Hexagon => {
                self.triangle_value(paving(&HEXAGON_PAVINGS, self.tiles, self.pattern), x, z)
            }
        }
    }

    /// The value of a paving on the triangle lattice (triangles or hexagons), given as its
    /// rows of border digits (see [`TRIANGLE_PAVINGS`]); 0 without a paving.
    fn triangle_value(&self, rows: Option<&'static [&'static str]>, x: f64, z: f64) -> f64 {
        let Some(rows) = rows else {
            return 0.0;
        };
        let grid = TriangleGrid { rows };
        // Lattice coordinates: p = (i + f) (1, 0) + (j + g) (1/2, √3/2).
        let row_coordinate = z / ROW_HEIGHT;
        let column_coordinate = x - 0.5 * row_coordinate;
        let (i, j) = (column_coordinate.floor(), row_coordinate.floor());
        let (f, g) = (column_coordinate - i, row_coordinate - j);
        // The triangle's corners as lattice offsets from (i, j), each with the sector (of the
        // six around the corner, counter-clockwise from +x) the triangle fills there.
        let corners: [((u8, u8), usize); 3] = if f + g < 1.0 {
            [((0, 0), 0), ((1, 0), 2), ((0, 1), 4)]
        } else {
            [((1, 0), 1), ((1, 1), 3), ((0, 1), 5)]
        };
        let corner_point = |(di, dj): (u8, u8)| {
            let (ci, cj) = (i + f64::from(di), j + f64::from(dj));
            (ci + 0.5 * cj, cj * ROW_HEIGHT)
        };
        let distance_squared = |(cx, cz): (f64, f64)| (x - cx).powi(2) + (z - cz).powi(2);
        let mut nearest = corners[0];
        for corner in &corners[1..] {
            if distance_squared(corner_point(corner.0)) < distance_squared(corner_point(nearest.0))
            {
                nearest = *corner;
            }
        }
        let ((di, dj), sector) = nearest;
        let (vx, vz) = corner_point((di, dj));
        let column = (i + f64::from(di)).rem_euclid(grid.width() as f64) as usize % grid.width();
        let row = (j + f64::from(dj)).rem_euclid(grid.height() as f64) as usize % grid.height();
        let distance = self.triangle_distance(grid.star(column, row), sector, x - vx, z - vz);
        (1.0 - distance / TRIANGLE_INRADIUS).clamp(0.0, 1.0)
    }

    /// The distance `d` (see the module header) of the point (dx, dz) from a lattice point
    /// whose six edges (counter-clockwise from +x) are `borders`, for the triangle filling
    /// `sector` there.
    fn triangle_distance(&self, borders: [bool; 6], sector: usize, dx: f64, dz: f64) -> f64 {
        if !borders.contains(&true) {
            return f64::INFINITY;
        }
        // Signed distance from the line of lattice direction `n`, positive counter-clockwise.
        let line_distance = |n: usize| {
            let (cos, sin) = LATTICE_DIRECTIONS[n % 6];
            cos * dz - sin * dx
        };
        // The run of sectors the tile fills: from border edge `low` counter-clockwise to
        // border edge `high`.
        let before = (0..6).find(|&n| borders[(sector + 6 - n) % 6]).unwrap_or(0);
        let after = (0..6).find(|&n| borders[(sector + 1 + n) % 6]).unwrap_or(0);
        let (low, high) = ((sector + 6 - before) % 6, (sector + 1 + after) % 6);
        let run = before + after + 1;
        let (from_low, from_high) = (line_distance(low), -line_distance(high));
        let rho = dx.hypot(dz);
        let cos_30 = LATTICE_DIRECTIONS[1].1;
        match run {
            1 => {
                let pointy = from_low.min(from_high);
                match self.exterior {
                    0 => pointy,
                    1 => {
                        let (cos, sin) = SECTOR_CENTRES[sector];
                        pointy.min(cos * dx + sin * dz - TRIANGLE_INRADIUS)
                    }
                    _ => {
                        let (cos, sin) = SECTOR_CENTRES[sector];
                        let to_centre = 2.0 * TRIANGLE_INRADIUS;
                        let rounded =
                            TRIANGLE_INRADIUS - (dx - cos * to_centre).hypot(dz - sin * to_centre);
                        pointy.min(rounded)
                    }
                }
            }
            2 => {
                let pointy = from_low.min(from_high);
                let (cos, sin) = LATTICE_DIRECTIONS[(low + 1) % 6];
                match self.form {
                    1 => pointy.min((cos * dx + sin * dz) / cos_30 - TRIANGLE_INRADIUS),
                    2 => pointy.min(cos_30 - (dx - cos).hypot(dz - sin)),
                    _ => pointy,
                }
            }
            _ => {
                let angle = dz.atan2(dx).to_degrees();
                let corner = match self.interior {
                    0 if run == 5 => rho * angle_to_nearest(angle - 30.0).to_radians().cos(),
                    0 => from_low.max(from_high),
                    1 => rho * cos_30 * angle_to_nearest(angle).to_radians().cos(),
                    _ => rho * cos_30,
                };
                [sector, sector + 1]
                    .into_iter()
                    .filter(|&n| borders[n % 6])
                    .map(|n| line_distance(n).abs())
                    .fold(corner, f64::min)
            }
        }
    }

    /// The value of a square paving.
    fn square_value(&self, x: f64, z: f64) -> f64 {
        let Some(rows) = paving(&SQUARE_PAVINGS, self.tiles, self.pattern) else {
            return 0.0;
        };
        let grid = SquareGrid { rows };
        let (cell_x, cell_z) = (x.floor(), z.floor());
        let (u, w) = (x - cell_x, z - cell_z);
        let column = cell_x.rem_euclid(grid.width() as f64) as usize % grid.width();
        let row = cell_z.rem_euclid(grid.height() as f64) as usize % grid.height();
        let cell = grid.cell(column, row);
        if self.form != 3 {
            if let Some(value) = self.turn_value(&grid, &cell, u, w) {
                return value;
            }
        }
        // The quarter of the cell the point is in: its corner and the distances from it.
        let (right, du) = if u < 0.5 { (false, u) } else { (true, 1.0 - u) };
        let (top, dw) = if w < 0.5 { (false, w) } else { (true, 1.0 - w) };
        let horizontal_border = if top { cell.top } else { cell.bottom };
        let vertical_border = if right { cell.right } else { cell.left };
        let distance = match (horizontal_border, vertical_border) {
            (true, true) => match self.exterior {
                0 => du.min(dw),
                1 => (du + dw - 0.5).max(0.0),
                _ => (0.5 - (0.5 - du).hypot(0.5 - dw)).max(0.0),
            },
            (true, false) => dw,
            (false, true) => du,
            (false, false) if grid.corner_is_concave(column, row, right, top) => {
                match self.interior {
                    0 => du.max(dw),
                    1 => du + dw,
                    _ => du.hypot(dw),
                }
            }
            (false, false) => 0.5,
        };
        (1.0 - 2.0 * distance).clamp(0.0, 1.0)
    }

    /// In a cell where the tile turns (two adjacent border edges, the opposite corner
    /// concave), the value `form` 0, 1 or 2 gives; `None` for other cells.
    fn turn_value(&self, grid: &SquareGrid, cell: &SquareCell, u: f64, w: f64) -> Option<f64> {
        let borders = [cell.bottom, cell.top, cell.left, cell.right];
        if borders.iter().filter(|&&border| border).count() != 2
            || cell.bottom == cell.top
            || cell.left == cell.right
        {
            return None;
        }
        // s and t: distances from the two border edges; the concave candidate is (1, 1).
        let s = if cell.left { u } else { 1.0 - u };
        let t = if cell.bottom { w } else { 1.0 - w };
        if !grid.corner_is_concave(cell.column, cell.row, cell.left, cell.bottom) {
            return None;
        }
        let value = match self.form {
            1 => 2.0 * (s + t - 1.5).abs(),
            2 => 2.0 * ((1.0 - s).hypot(1.0 - t) - 0.5).abs(),
            _ => 1.0 - 2.0 * s.min(t).min((1.0 - s).max(1.0 - t)),
        };
        Some(value.clamp(0.0, 1.0))
    }
}

/// Height of a row of triangles, √3/2.
const ROW_HEIGHT: f64 = 0.866_025_403_784_438_6;

/// Inradius of the unit triangle, √3/6.
const TRIANGLE_INRADIUS: f64 = 0.288_675_134_594_812_9;

/// (cos, sin) of the lattice directions 0°, 60°, ... 300°.
const LATTICE_DIRECTIONS: [(f64, f64); 6] = [
    (1.0, 0.0),
    (0.5, ROW_HEIGHT),
    (-0.5, ROW_HEIGHT),
    (-1.0, 0.0),
    (-0.5, -ROW_HEIGHT),
    (0.5, -ROW_HEIGHT),
];

/// (cos, sin) of the directions 30°, 90°, ... 330°: from a lattice point to the centres of
/// the six triangles around it.
const SECTOR_CENTRES: [(f64, f64); 6] = [
    (ROW_HEIGHT, 0.5),
    (0.0, 1.0),
    (-ROW_HEIGHT, 0.5),
    (-ROW_HEIGHT, -0.5),
    (0.0, -1.0),
    (ROW_HEIGHT, -0.5),
];

/// The angle in degrees from `angle` to the nearest multiple of 60°, in [0, 30].
fn angle_to_nearest(angle: f64) -> f64 {
    let offset = angle.rem_euclid(60.0);
    offset.min(60.0 - offset)
}

/// The rows of paving `pattern` (from 1) for tiles of `tiles` polygons (from 1).
fn paving(
    table: &[&'static [&'static [&'static str]]],
    tiles: u8,
    pattern: u8,
) -> Option<&'static [&'static str]> {
    let pavings = table.get(usize::from(tiles).checked_sub(1)?)?;
    pavings.get(usize::from(pattern).checked_sub(1)?).copied()
}

/// One repeating block of a triangle paving.
struct TriangleGrid {
    /// The rows of border digits (see [`TRIANGLE_PAVINGS`]).
    rows: &'static [&'static str],
}

impl TriangleGrid {
    /// Lattice points along a row.
    fn width(&self) -> usize {
        self.rows[0].len()
    }

    /// Rows.
    fn height(&self) -> usize {
        self.rows.len()
    }

    /// Whether edge `bit` (0, 1 or 2, see [`TRIANGLE_PAVINGS`]) of lattice point (i, j) is a
    /// border, the coordinates wrapping around the block.
    fn edge(&self, i: usize, j: usize, bit: u8) -> bool {
        let row = self.rows[j % self.height()].as_bytes();
        (row[i % row.len()] - b'0') >> bit & 1 != 0
    }

    /// The six edges of lattice point (i, j) (both below the block's size),
    /// counter-clockwise from +x: whether each is a border.
    fn star(&self, i: usize, j: usize) -> [bool; 6] {
        let (left, down) = (i + self.width() - 1, j + self.height() - 1);
        [
            self.edge(i, j, 0),
            self.edge(i, j, 1),
            self.edge(left, j, 2),
            self.edge(left, j, 0),
            self.edge(i, down, 1),
            self.edge(i, down, 2),
        ]
    }
}

/// One repeating rectangle of a square paving.
struct SquareGrid {
    /// The rows of border digits (see [`SQUARE_PAVINGS`]).
    rows: &'static [&'static str],
}

/// Which edges of one cell are tile borders.
struct SquareCell {
    /// The cell's column in the grid.
    column: usize,
    /// The cell's row in the grid.
    row: usize,
    /// Edge at z = cell's bottom.
    bottom: bool,
    /// Edge at the cell's top.
    top: bool,
    /// Edge at x = cell's left.
    left: bool,
    /// Edge at the cell's right.
    right: bool,
}

impl SquareGrid {
    /// Cells across.
    fn width(&self) -> usize {
        self.rows[0].len()
    }

    /// Cells up.
    fn height(&self) -> usize {
        self.rows.len()
    }

    /// The border digit of a cell, the coordinates wrapping around the grid.
    fn digit(&self, column: usize, row: usize) -> u8 {
        let row = self.rows[row % self.height()].as_bytes();
        row[column % row.len()] - b'0'
    }

    /// Whether the bottom edge of a cell is a border.
    fn bottom_edge(&self, column: usize, row: usize) -> bool {
        self.digit(column, row) & 1 != 0
    }

    /// Whether the left edge of a cell is a border.
    fn left_edge(&self, column: usize, row: usize) -> bool {
        self.digit(column, row) & 2 != 0
    }

    /// The cell at (column, row), both below the grid's size.
    fn cell(&self, column: usize, row: usize) -> SquareCell {
        let (right_column, top_row) = (column + 1, row + 1);
        SquareCell {
            column,
            row,
            bottom: self.bottom_edge(column, row),
            top: self.bottom_edge(column, top_row),
            left: self.left_edge(column, row),
            right: self.left_edge(right_column, row),
        }
    }

    /// Whether the corner of cell (column, row) on the `right`/`top` side (else left /
    /// bottom) is on a border reached only by the two edges leading away from the cell: a
    /// concave corner of the cell's tile when neither cell edge there is a border.
    fn corner_is_concave(&self, column: usize, row: usize, right: bool, top: bool) -> bool {
        let (width, height) = (self.width(), self.height());
        let corner_column = if right { column + 1 } else { column };
        let corner_row = if top { row + 1 } else { row };
        // The horizontal edge leaving the corner away from the cell, and the vertical one.
        let away_column = if right {
            corner_column
        } else {
            corner_column + width - 1
        };
        let away_row = if top {
            corner_row
        } else {
            corner_row + height - 1
        };
        self.bottom_edge(away_column, corner_row) || self.left_edge(corner_column, away_row)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The pavement a line of `pavement_answers.txt` was measured with, and its point and
    /// value.
    fn answer(line: &str) -> (Pavement, f64, f64, f64) {
        let fields: Vec<f64> = line
            .split_whitespace()
            .map(|field| field.parse().unwrap())
            .collect();
        let pavement = Pavement {
            polygon: PavementPolygon::from_sides(fields[0]).unwrap(),
            tiles: fields[1] as u8,
            pattern: fields[2] as u8,
            form: fields[3] as u8,
            exterior: fields[4] as u8,
            interior: fields[5] as u8,
        };
        (pavement, fields[6], fields[7], fields[8])
    }

    #[test]
    fn pavements_match_povray_known_answers() {
        let table = include_str!("pavement_answers.txt");
        let mut checked = 0;
        for line in table.lines().filter(|line| !line.starts_with('#')) {
            let (pavement, x, z, expected) = answer(line);
            let ours = pavement.value(x, z);
            // povray's colours are single precision.
            assert!((ours - expected).abs() < 1e-6, "{line}: durer gives {ours}");
            checked += 1;
        }
        assert!(checked > 1000);
    }

    #[test]
    fn pattern_counts_follow_the_manual() {
        let counts = |polygon: PavementPolygon| -> Vec<u8> {
            (1..=polygon.max_tiles())
                .map(|tiles| polygon.pattern_count(tiles))
                .collect()
        };
        assert_eq!(counts(PavementPolygon::Square), [1, 1, 2, 5, 12, 35]);
        assert_eq!(counts(PavementPolygon::Triangle), [1, 1, 1, 3, 4, 12]);
        assert_eq!(counts(PavementPolygon::Hexagon), [1, 1, 3, 7, 22]);
        assert_eq!(PavementPolygon::Square.pattern_count(0), 0);
        assert_eq!(PavementPolygon::Square.pattern_count(7), 0);
    }

    #[test]
    fn corner_settings_wrap_like_unsigned_numbers() {
        // Measured: exterior -1 is 0, exterior 5 is 2, form -2 is 2, form 7 is 3.
        assert_eq!(corner_setting(-1.0, 3), 0);
        assert_eq!(corner_setting(5.0, 3), 2);
        assert_eq!(corner_setting(1.5, 3), 1);
        assert_eq!(corner_setting(-2.0, 4), 2);
        assert_eq!(corner_setting(7.0, 4), 3);
        assert_eq!(corner_setting(f64::NAN, 3), 0);
    }

    #[test]
    fn far_and_odd_points_stay_in_range() {
        for (polygon, pattern) in [
            (PavementPolygon::Square, 34),
            (PavementPolygon::Triangle, 11),
            (PavementPolygon::Hexagon, 4),
        ] {
            let pavement = Pavement {
                polygon,
                tiles: polygon.max_tiles(),
                pattern,
                form: 2,
                exterior: 2,
                interior: 1,
            };
            for (x, z) in [(1e300, -1e300), (-1e-300, 0.0), (-0.5, -7.25), (1e17, 3.5)] {
                let value = pavement.value(x, z);
                assert!((0.0..=1.0).contains(&value), "{x} {z}: {value}");
            }
        }
    }
}
