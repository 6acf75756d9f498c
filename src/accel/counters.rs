//! Statistics counters: rays by kind and intersection tests, counted per thread.
//!
//! In: `add` calls from the hot paths (each adds to the calling thread's own counters, a
//! thread-local cell: no atomics, no sharing). Out: [`take`] returns and clears the calling
//! thread's counts; a render sums them over its worker threads. Holds: counting never
//! changes what is computed, so images stay the same with statistics on or off.

use std::cell::Cell;

/// What is counted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Counter {
    /// Rays from the camera.
    CameraRays,
    /// Rays towards lights.
    ShadowRays,
    /// Mirror-reflected rays.
    ReflectedRays,
    /// Refracted rays.
    RefractedRays,
    /// Radiosity's gathering rays.
    RadiosityRays,
    /// Photons shot from lights.
    PhotonRays,
    /// Ray-primitive intersection tests (through the hierarchy and against unbounded
    /// primitives).
    IntersectionTests,
    /// Radiosity samples gathered (not reused) at the first bounce.
    RadiositySamplesFirstBounce,
    /// Radiosity samples gathered at the second bounce.
    RadiositySamplesSecondBounce,
    /// Radiosity samples gathered at the third and deeper bounces.
    RadiositySamplesDeeper,
}

/// How many counters there are.
pub const COUNTERS: usize = 10;

/// One thread's (or a sum of threads') counts, indexed by [`Counter`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counts(pub [u64; COUNTERS]);

impl Counts {
    /// The count of one counter.
    pub fn get(&self, counter: Counter) -> u64 {
        self.0[counter as usize]
    }

    /// The sum of two sets of counts.
    pub fn plus(mut self, other: Counts) -> Counts {
        for (a, b) in self.0.iter_mut().zip(other.0) {
            *a = a.saturating_add(b);
        }
        self
    }
}

thread_local! {
    /// One cell per counter, so that adding to one does not copy them all (a single
    /// `Cell<[u64; N]>` copied the array out and back on every call).
    static COUNTS: [Cell<u64>; COUNTERS] = const { [const { Cell::new(0) }; COUNTERS] };
}

/// Adds `amount` to the calling thread's `counter`.
#[inline]
pub fn add(counter: Counter, amount: u64) {
    COUNTS.with(|counts| {
        let cell = &counts[counter as usize];
        cell.set(cell.get().wrapping_add(amount));
    });
}

/// The calling thread's counts since the last `take`, which starts them again from zero.
pub fn take() -> Counts {
    Counts(COUNTS.with(|counts| std::array::from_fn(|index| counts[index].replace(0))))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_per_thread_and_take_resets() {
        let _ = take();
        add(Counter::CameraRays, 2);
        add(Counter::IntersectionTests, 5);
        let other = std::thread::spawn(|| {
            add(Counter::CameraRays, 7);
            take()
        })
        .join()
        .unwrap();
        assert_eq!(other.get(Counter::CameraRays), 7);
        let mine = take();
        assert_eq!(mine.get(Counter::CameraRays), 2);
        assert_eq!(mine.plus(other).get(Counter::CameraRays), 9);
        assert_eq!(take(), Counts::default());
    }
}
