//! A bounding volume hierarchy built with the binned surface area heuristic.
//!
//! In: one finite, non-empty [`Aabb`] per primitive. Out: a [`Bvh`] (flat node array with
//! index links) plus the order in which the caller must store its primitives, and a
//! nearest-hit traversal calling back into the caller's primitive test.
//! Holds: every primitive appears in exactly one leaf; a leaf covers the contiguous range
//! `first .. first + count` of the reordered primitives; an interior node's left child directly
//! follows it in the array; the tree is at most [`MAX_DEPTH`] levels deep.

use super::aabb::Aabb;
use arrayvec::ArrayVec;
use glam::DVec3;

/// The deepest level the builder creates; deeper ranges become (large) leaves.
pub const MAX_DEPTH: usize = 100;

/// Room on the traversal stack; larger than [`MAX_DEPTH`] so it can never overflow.
const STACK_SIZE: usize = MAX_DEPTH + 8;

/// Number of centroid bins the builder evaluates per split.
const BIN_COUNT: usize = 16;

/// Ranges this small always become leaves.
const SMALL_LEAF: usize = 2;

/// Ranges larger than this are always split (when their centroids allow it).
const LARGE_LEAF: usize = 8;

/// Cost of visiting a node relative to testing one primitive.
const TRAVERSAL_COST: f64 = 1.0;

/// One node of the hierarchy.
#[derive(Clone, Copy, Debug)]
struct Node {
    /// Bounds of everything below the node.
    bounds: Aabb,
    /// A leaf's first primitive, or an interior node's right child.
    first: u32,
    /// A leaf's number of primitives; zero for an interior node.
    count: u32,
}

/// A bounding volume hierarchy over primitives known only by their bounds.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
}

impl Bvh {
    /// Builds the hierarchy over `bounds` (one box per primitive).
    ///
    /// Returns the tree and the primitive order: the caller must store primitive `order[i]`
    /// at position `i`, since the traversal reports positions in that order.
    ///
    /// Large ranges build their two halves in parallel; the result is the same whatever the
    /// number of threads.
    pub fn build(bounds: &[Aabb]) -> (Bvh, Vec<u32>) {
        // The builder reorders these records in place, so every pass over a range reads
        // memory in sequence instead of gathering boxes through an index.
        let mut records: Vec<Record> = bounds
            .iter()
            .enumerate()
            .map(|(index, bounds)| Record::new(bounds, index as u32))
            .collect();
        let mut nodes = if records.is_empty() {
            Vec::new()
        } else {
            let range = RangeBounds::of(&records);
            join_pieces(build_pieces(&mut records, range, 0, 0))
        };
        nodes.shrink_to_fit();
        // The records' boxes are slightly wide; the whole tree's box, which callers read
        // (`min_extent`), is the exact union.
        if let Some(root) = nodes.first_mut() {
            root.bounds = bounds.iter().fold(Aabb::EMPTY, |all, b| all.union(b));
        }
        let order = records.iter().map(|record| record.index).collect();
        (Bvh { nodes }, order)
    }

    /// Number of nodes (interior and leaf) in the tree.
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// Bounds of the whole tree, or `None` when it holds nothing.
    pub fn bounds(&self) -> Option<Aabb> {
        self.nodes.first().map(|node| node.bounds)
    }

    /// Finds the nearest hit of a ray among the primitives.
    ///
    /// `test(position, closest)` must return the primitive's nearest hit with a distance in
    /// `(min_distance, closest)`, plus any payload. Nodes are visited near to far and skipped
    /// once they lie beyond the closest hit so far.
    #[inline]
    pub fn nearest_hit<Payload>(
        &self,
        origin: DVec3,
        inverse_direction: DVec3,
        min_distance: f64,
        max_distance: f64,
        mut test: impl FnMut(usize, f64) -> Option<(f64, Payload)>,
    ) -> Option<(f64, Payload)> {
        let root = self.nodes.first()?;
        let mut closest = max_distance;
        let mut best = None;
        root.bounds
            .ray_entry(origin, inverse_direction, min_distance, closest)?;
        // Not zero-filled on every call (a plain array of this size was: 4-6% of a
        // radiosity render's time, measured with perf on radiosity/cornell.pov).
        let mut stack = ArrayVec::<(u32, f64), STACK_SIZE>::new();
        let mut current = 0usize;
        let mut tests = 0u64;
        let mut test = |position: usize, closest: f64| {
            tests += 1;
            test(position, closest)
        };
        let found = 'walk: loop {
            let node = &self.nodes[current];
            let mut next = None;
            if node.count > 0 {
                let first = node.first as usize;
                for position in first..first + node.count as usize {
                    if let Some((distance, payload)) = test(position, closest) {
                        if distance < closest && distance > min_distance {
                            closest = distance;
                            best = Some((distance, payload));
                        }
                    }
                }
            } else {
                let left = current + 1;
                let right = node.first as usize;
                let entry = |index: usize| {
                    self.nodes[index].bounds.ray_entry(
                        origin,
                        inverse_direction,
                        min_distance,
                        closest,
                    )
                };
                match (entry(left), entry(right)) {
                    (Some(left_entry), Some(right_entry)) => {
                        let (near, far, far_entry) = if left_entry <= right_entry {
                            (left, right, right_entry)
                        } else {
                            (right, left, left_entry)
                        };
                        // Never full: the tree is at most MAX_DEPTH deep.
                        let _ = stack.try_push((far as u32, far_entry));
                        next = Some(near);
                    }
                    (Some(_), None) => next = Some(left),
                    (None, Some(_)) => next = Some(right),
                    (None, None) => {}
                }
            }
            current = match next {
                Some(index) => index,
                None => loop {
                    let Some((index, entry)) = stack.pop() else {
                        break 'walk best;
                    };
                    if entry < closest {
                        break index as usize;
                    }
                },
            };
        };
        super::counters::add(super::counters::Counter::IntersectionTests, tests);
        found
    }
}

impl Bvh {
    /// Calls `visit(position)` for every primitive whose box the ray segment
    /// `(min_distance, max_distance)` enters, in no particular order. Primitives are visited
    /// leaf by leaf, so some near misses sharing a leaf with a hit are visited too: callers
    /// test the primitives themselves.
    pub fn for_each_on_ray(
        &self,
        origin: DVec3,
        inverse_direction: DVec3,
        min_distance: f64,
        max_distance: f64,
        mut visit: impl FnMut(usize),
    ) {
        let enters = |node: &Node| {
            node.bounds
                .ray_entry(origin, inverse_direction, min_distance, max_distance)
                .is_some()
        };
        self.walk(enters, |position| {
            visit(position);
            false
        });
    }

    /// True when `test(position)` holds for some primitive whose box contains `point`;
    /// stops at the first such primitive. As with [`Bvh::for_each_on_ray`], primitives sharing
    /// a leaf with one whose box contains the point may be tested too.
    pub fn any_containing(&self, point: DVec3, test: impl FnMut(usize) -> bool) -> bool {
        self.walk(|node: &Node| node.bounds.contains(point), test)
    }

    /// Depth-first walk over the nodes `admit` accepts, calling `leaf(position)` for each
    /// primitive of an admitted leaf until it returns true (then the walk returns true).
    fn walk(&self, admit: impl Fn(&Node) -> bool, mut leaf: impl FnMut(usize) -> bool) -> bool {
        let Some(root) = self.nodes.first() else {
            return false;
        };
        if !admit(root) {
            return false;
        }
        let mut stack = ArrayVec::<u32, STACK_SIZE>::new();
        let mut current = 0usize;
        loop {
            let node = &self.nodes[current];
            let mut next = None;
            if node.count > 0 {
                let first = node.first as usize;
                for position in first..first + node.count as usize {
                    if leaf(position) {
                        return true;
                    }
                }
            } else {
                let left = current + 1;
                let right = node.first as usize;
                let (take_left, take_right) = (admit(&self.nodes[left]), admit(&self.nodes[right]));
                if take_left && take_right {
                    let _ = stack.try_push(right as u32);
                }
                if take_left {
                    next = Some(left);
                } else if take_right {
                    next = Some(right);
                }
            }
            current = match next {
                Some(index) => index,
                None => match stack.pop() {
                    Some(index) => index as usize,
                    None => return false,
                },
            };
        }
    }
}

/// What every part of one build shares (read only, so subtrees can be built in parallel).
/// A box in single precision, as the builder bins them.
#[derive(Clone, Copy)]
struct Box32 {
    min: [f32; 3],
    max: [f32; 3],
}

impl Box32 {
    const EMPTY: Box32 = Box32 {
        min: [f32::INFINITY; 3],
        max: [f32::NEG_INFINITY; 3],
    };

    /// `bounds` rounded outwards, so the result still contains it.
    fn enclosing(bounds: &Aabb) -> Box32 {
        let down = |x: f64| {
            let rounded = x as f32;
            if f64::from(rounded) > x {
                rounded.next_down()
            } else {
                rounded
            }
        };
        let up = |x: f64| {
            let rounded = x as f32;
            if f64::from(rounded) < x {
                rounded.next_up()
            } else {
                rounded
            }
        };
        Box32 {
            min: bounds.min.to_array().map(down),
            max: bounds.max.to_array().map(up),
        }
    }

    // Plain comparisons rather than `f32::min`/`max`: the builder's boxes never hold NaN
    // (their sources are finite), and the NaN handling doubles the cost of these hot loops.
    fn union(&self, other: &Box32) -> Box32 {
        Box32 {
            min: std::array::from_fn(|i| lesser(self.min[i], other.min[i])),
            max: std::array::from_fn(|i| greater(self.max[i], other.max[i])),
        }
    }

    fn grown_to(&self, point: [f32; 3]) -> Box32 {
        Box32 {
            min: std::array::from_fn(|i| lesser(self.min[i], point[i])),
            max: std::array::from_fn(|i| greater(self.max[i], point[i])),
        }
    }

    fn centre(&self) -> [f32; 3] {
        std::array::from_fn(|i| (self.min[i] + self.max[i]) * 0.5)
    }

    fn to_aabb(self) -> Aabb {
        Aabb {
            min: DVec3::from_array(self.min.map(f64::from)),
            max: DVec3::from_array(self.max.map(f64::from)),
        }
    }
}

#[inline(always)]
fn lesser(a: f32, b: f32) -> f32 {
    if b < a {
        b
    } else {
        a
    }
}

#[inline(always)]
fn greater(a: f32, b: f32) -> f32 {
    if b > a {
        b
    } else {
        a
    }
}

/// The boxes of a range of records: around the records and around their centres.
#[derive(Clone, Copy)]
struct RangeBounds {
    boxes: Box32,
    centres: Box32,
}

impl RangeBounds {
    const EMPTY: RangeBounds = RangeBounds {
        boxes: Box32::EMPTY,
        centres: Box32::EMPTY,
    };

    /// The bounds of `records`, in one pass.
    fn of(records: &[Record]) -> RangeBounds {
        records
            .iter()
            .fold(RangeBounds::EMPTY, |all, record| all.with(&record.bounds))
    }

    fn with(&self, bounds: &Box32) -> RangeBounds {
        RangeBounds {
            boxes: self.boxes.union(bounds),
            centres: self.centres.grown_to(bounds.centre()),
        }
    }

    fn union(&self, other: &RangeBounds) -> RangeBounds {
        RangeBounds {
            boxes: self.boxes.union(&other.boxes),
            centres: self.centres.union(&other.centres),
        }
    }
}

/// A primitive as the builder sorts it: its box in single precision, rounded outwards so it
/// still contains the primitive (28 bytes, so large builds stream little memory), and the
/// caller's index.
#[derive(Clone, Copy)]
struct Record {
    bounds: Box32,
    index: u32,
}

impl Record {
    fn new(bounds: &Aabb, index: u32) -> Record {
        Record {
            bounds: Box32::enclosing(bounds),
            index,
        }
    }
}

/// Ranges at least this large build their two halves on parallel threads.
const PARALLEL_RANGE: usize = 16_384;

/// One bin of the SAH sweep.
#[derive(Clone, Copy)]
struct Bin {
    bounds: RangeBounds,
    count: usize,
}

/// How a range is split: the first `middle` records go left; each side's bounds.
struct Split {
    middle: usize,
    left: RangeBounds,
    right: RangeBounds,
}

/// Builds the subtree over `records` (at `offset` in the final order, with bounds `range`),
/// appending its nodes to `nodes`; returns the index of its root.
fn build_node(
    records: &mut [Record],
    range: RangeBounds,
    offset: usize,
    depth: usize,
    nodes: &mut Vec<Node>,
) -> usize {
    let node_index = nodes.len();
    let count = records.len();
    let bounds = range.boxes.to_aabb();
    nodes.push(Node {
        bounds,
        first: offset as u32,
        count: count as u32,
    });
    if count <= SMALL_LEAF || depth >= MAX_DEPTH {
        return node_index;
    }
    let Some(split) = choose_split(records, &bounds, &range.centres) else {
        return node_index;
    };
    let middle = split.middle;
    let (left, right) = records.split_at_mut(middle);
    build_node(left, split.left, offset, depth + 1, nodes);
    let right_index = build_node(right, split.right, offset + middle, depth + 1, nodes);
    nodes[node_index].first = right_index as u32;
    nodes[node_index].count = 0;
    node_index
}

/// A subtree built in pieces on several threads: chunks of nodes in their final order, each
/// with the amount to add to its interior nodes' right-child links, which count from the
/// subtree's root. Joining the pieces once at the end copies each node once, however many
/// levels were built in parallel.
struct Pieces {
    chunks: Vec<(u32, Vec<Node>)>,
    len: usize,
}

/// Builds the subtree over `records` like [`build_node`], building the two halves of large
/// ranges on parallel threads. The tree is the same whatever the number of threads.
fn build_pieces(records: &mut [Record], range: RangeBounds, offset: usize, depth: usize) -> Pieces {
    let count = records.len();
    let bounds = range.boxes.to_aabb();
    let split = if count < PARALLEL_RANGE || depth >= MAX_DEPTH {
        None
    } else {
        choose_split(records, &bounds, &range.centres)
    };
    let Some(split) = split else {
        let mut nodes = Vec::with_capacity(count);
        build_node(records, range, offset, depth, &mut nodes);
        return Pieces {
            len: nodes.len(),
            chunks: vec![(0, nodes)],
        };
    };
    let middle = split.middle;
    let (left, right) = records.split_at_mut(middle);
    let (left, right) = rayon::join(
        || build_pieces(left, split.left, offset, depth + 1),
        || build_pieces(right, split.right, offset + middle, depth + 1),
    );
    let parent = Node {
        bounds,
        first: (1 + left.len) as u32,
        count: 0,
    };
    let mut chunks = Vec::with_capacity(1 + left.chunks.len() + right.chunks.len());
    chunks.push((0, vec![parent]));
    let right_base = 1 + left.len as u32;
    chunks.extend(left.chunks.into_iter().map(|(bias, c)| (bias + 1, c)));
    chunks.extend(
        right
            .chunks
            .into_iter()
            .map(|(bias, c)| (bias + right_base, c)),
    );
    Pieces {
        chunks,
        len: 1 + left.len + right.len,
    }
}

/// Reorders `records` for the best split and returns it, or `None` when a leaf is better.
fn choose_split(records: &mut [Record], bounds: &Aabb, centroid_bounds: &Box32) -> Option<Split> {
    let count = records.len();
    let extent: [f32; 3] = std::array::from_fn(|i| centroid_bounds.max[i] - centroid_bounds.min[i]);
    let axis = if extent[0] >= extent[1] && extent[0] >= extent[2] {
        0
    } else if extent[1] >= extent[2] {
        1
    } else {
        2
    };
    let axis_min = centroid_bounds.min[axis];
    let axis_extent = extent[axis];
    if !(axis_extent > 0.0 && axis_extent.is_finite()) {
        // Every centroid coincides: bins cannot separate them, so halve large ranges.
        return (count > LARGE_LEAF).then(|| halves(records));
    }
    let scale = BIN_COUNT as f32 / axis_extent;
    let bin_of = |record: &Record| -> usize {
        let centre = (record.bounds.min[axis] + record.bounds.max[axis]) * 0.5;
        // NaN converts to 0 and overflow saturates, so the index always stays in range.
        (((centre - axis_min) * scale) as usize).min(BIN_COUNT - 1)
    };
    let mut bins = [Bin {
        bounds: RangeBounds::EMPTY,
        count: 0,
    }; BIN_COUNT];
    for record in records.iter() {
        let bin = &mut bins[bin_of(record)];
        bin.bounds = bin.bounds.with(&record.bounds);
        bin.count += 1;
    }
    // Sweep from the right to get the cost of every right-hand side.
    let mut right_bounds = [RangeBounds::EMPTY; BIN_COUNT];
    let mut right_count = [0usize; BIN_COUNT];
    let mut accumulated = RangeBounds::EMPTY;
    let mut accumulated_count = 0;
    for split in (1..BIN_COUNT).rev() {
        accumulated = accumulated.union(&bins[split].bounds);
        accumulated_count += bins[split].count;
        right_bounds[split] = accumulated;
        right_count[split] = accumulated_count;
    }
    let mut best_split = 0;
    let mut best_cost = f64::INFINITY;
    let mut best_left = RangeBounds::EMPTY;
    let mut left = RangeBounds::EMPTY;
    let mut left_count = 0;
    for split in 1..BIN_COUNT {
        left = left.union(&bins[split - 1].bounds);
        left_count += bins[split - 1].count;
        if left_count == 0 || right_count[split] == 0 {
            continue;
        }
        let cost = left.boxes.to_aabb().surface_area() * left_count as f64
            + right_bounds[split].boxes.to_aabb().surface_area() * right_count[split] as f64;
        if cost < best_cost {
            best_cost = cost;
            best_split = split;
            best_left = left;
        }
    }
    let area = bounds.surface_area();
    let leaf_cost = area * count as f64;
    let split_cost = TRAVERSAL_COST * area + best_cost;
    if best_split == 0 || (count <= LARGE_LEAF && leaf_cost <= split_cost) {
        return (count > LARGE_LEAF).then(|| halves(records));
    }
    // Two-ended partition: only records on the wrong side move.
    let goes_left = |record: &Record| bin_of(record) < best_split;
    let (mut low, mut high) = (0, count);
    loop {
        while low < high && goes_left(&records[low]) {
            low += 1;
        }
        while low < high && !goes_left(&records[high - 1]) {
            high -= 1;
        }
        if low >= high {
            break;
        }
        records.swap(low, high - 1);
        low += 1;
        high -= 1;
    }
    let boundary = low;
    if boundary == 0 || boundary == count {
        return Some(halves(records));
    }
    Some(Split {
        middle: boundary,
        left: best_left,
        right: right_bounds[best_split],
    })
}

/// Splits `records` in two halves as they stand.
fn halves(records: &[Record]) -> Split {
    let middle = records.len() / 2;
    Split {
        middle,
        left: RangeBounds::of(&records[..middle]),
        right: RangeBounds::of(&records[middle..]),
    }
}

/// Joins a tree's pieces into one array, moving interior nodes' right-child links to their
/// final positions.
fn join_pieces(pieces: Pieces) -> Vec<Node> {
    let mut nodes = Vec::with_capacity(pieces.len);
    for (bias, chunk) in pieces.chunks {
        nodes.extend(chunk.into_iter().map(|mut node| {
            if node.count == 0 {
                node.first += bias;
            }
            node
        }));
    }
    nodes
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A tiny deterministic random number generator for tests.
    struct Random(u64);

    impl Random {
        fn next(&mut self) -> f64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }
        fn vector(&mut self, scale: f64) -> DVec3 {
            DVec3::new(self.next() - 0.5, self.next() - 0.5, self.next() - 0.5) * 2.0 * scale
        }
        /// `count` boxes with centres within `spread` of the origin and sides up to `size`.
        fn boxes(&mut self, count: usize, spread: f64, size: f64) -> Vec<Aabb> {
            (0..count)
                .map(|_| {
                    let centre = self.vector(spread);
                    Aabb::from_corners(centre, centre + self.vector(size))
                })
                .collect()
        }
    }

    #[test]
    fn box_queries_match_brute_force() {
        let mut random = Random(0x5eed_0fb0_c5c5);
        let boxes = random.boxes(700, 10.0, 1.5);
        let (bvh, order) = Bvh::build(&boxes);
        for _ in 0..300 {
            let point = random.vector(10.0);
            let mut found: Vec<u32> = Vec::new();
            bvh.any_containing(point, |position| {
                found.push(order[position]);
                false
            });
            // Everything whose box holds the point, plus at most a few leaf mates.
            let expected: Vec<u32> = (0..boxes.len() as u32)
                .filter(|&i| boxes[i as usize].contains(point))
                .collect();
            assert!(
                expected.iter().all(|i| found.contains(i)),
                "{found:?} {expected:?}"
            );
            assert!(found.len() <= expected.len() * LARGE_LEAF + LARGE_LEAF);
            let origin = random.vector(12.0);
            let inverse_direction = random.vector(1.0).recip();
            let mut crossed: Vec<u32> = Vec::new();
            bvh.for_each_on_ray(origin, inverse_direction, 0.0, 8.0, |position| {
                crossed.push(order[position])
            });
            let expected: Vec<u32> = (0..boxes.len() as u32)
                .filter(|&i| {
                    boxes[i as usize]
                        .ray_entry(origin, inverse_direction, 0.0, 8.0)
                        .is_some()
                })
                .collect();
            assert!(expected.iter().all(|i| crossed.contains(i)));
            assert!(crossed.len() <= expected.len() * LARGE_LEAF + LARGE_LEAF);
        }
        assert!(!bvh.any_containing(DVec3::splat(1e9), |_| true));
    }

    #[test]
    fn parallel_build_equals_serial_build() {
        let mut random = Random(0x0ddb_a11f_00d5_eed5);
        let boxes = random.boxes(3 * PARALLEL_RANGE, 100.0, 1.0);
        let (parallel, parallel_order) = Bvh::build(&boxes);
        let (serial, serial_order) = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .unwrap()
            .install(|| Bvh::build(&boxes));
        assert_eq!(parallel_order, serial_order);
        assert_eq!(parallel.nodes.len(), serial.nodes.len());
        for (a, b) in parallel.nodes.iter().zip(&serial.nodes) {
            assert_eq!((a.bounds, a.first, a.count), (b.bounds, b.first, b.count));
        }
        // Links point forward and leaves cover the whole order exactly once.
        let mut covered = vec![false; boxes.len()];
        for (index, node) in parallel.nodes.iter().enumerate() {
            if node.count == 0 {
                assert!(node.first as usize > index + 1);
            } else {
                for position in node.first..node.first + node.count {
                    assert!(!std::mem::replace(&mut covered[position as usize], true));
                }
            }
        }
        assert!(covered.iter().all(|&c| c));
    }

    #[test]
    fn every_primitive_in_exactly_one_leaf() {
        let mut random = Random(0x1234_5678_9abc_def1);
        let boxes = random.boxes(5000, 100.0, 2.0);
        let (bvh, order) = Bvh::build(&boxes);
        let mut seen = vec![0; boxes.len()];
        for node in &bvh.nodes {
            if node.count > 0 {
                for position in node.first..node.first + node.count {
                    seen[order[position as usize] as usize] += 1;
                    assert!(node
                        .bounds
                        .contains(boxes[order[position as usize] as usize].min));
                }
            }
        }
        assert!(seen.iter().all(|&times| times == 1));
    }

    #[test]
    fn nearest_box_matches_brute_force() {
        let mut random = Random(0x9e37_79b9_7f4a_7c15);
        let boxes = random.boxes(2000, 50.0, 3.0);
        let (bvh, order) = Bvh::build(&boxes);
        for _ in 0..2000 {
            let origin = random.vector(80.0);
            let direction = random.vector(1.0).normalize();
            let inverse = DVec3::ONE / direction;
            let brute = boxes
                .iter()
                .filter_map(|b| b.ray_entry(origin, inverse, 0.0, f64::INFINITY))
                .filter(|&distance| distance > 0.0)
                .fold(f64::INFINITY, f64::min);
            let found = bvh.nearest_hit(origin, inverse, 0.0, f64::INFINITY, |position, _| {
                let b = boxes[order[position] as usize];
                b.ray_entry(origin, inverse, 0.0, f64::INFINITY)
                    .filter(|&distance| distance > 0.0)
                    .map(|distance| (distance, position))
            });
            assert_eq!(
                found.map(|(distance, _)| distance).unwrap_or(f64::INFINITY),
                brute
            );
        }
    }

    #[test]
    fn coincident_and_empty_inputs() {
        let (bvh, order) = Bvh::build(&[]);
        assert_eq!(bvh.node_count(), 0);
        assert!(order.is_empty());
        let same = vec![Aabb::from_corners(DVec3::ZERO, DVec3::ONE); 1000];
        let (bvh, order) = Bvh::build(&same);
        assert_eq!(order.len(), 1000);
        assert!(bvh.node_count() > 1);
    }
}
