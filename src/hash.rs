//! A fast, non-cryptographic hasher for the evaluator's symbol tables and the geometry
//! builder's material table.
//!
//! In: keys (short identifier names, small integers). Out: 64-bit hashes (FNV-1a). Holds:
//! deterministic across runs; keys are not chosen by an attacker in a way that matters for a
//! local renderer, so SipHash's protection is not worth its cost here.

use std::hash::{BuildHasherDefault, Hasher};

/// FNV-1a over the bytes written.
#[derive(Default)]
pub struct FastHasher(u64);

/// A `HashMap` builder using [`FastHasher`].
pub type FastHash = BuildHasherDefault<FastHasher>;

impl Hasher for FastHasher {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        let mut hash = if self.0 == 0 {
            0xcbf2_9ce4_8422_2325
        } else {
            self.0
        };
        for byte in bytes {
            hash ^= u64::from(*byte);
            hash = hash.wrapping_mul(0x0100_0000_01b3);
        }
        self.0 = hash;
    }
}
