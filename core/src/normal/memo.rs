//! Outcomes of the literal layer reading kept between frames (issue 26).
//!
//! The literal reading of Eq. (8) has no table: every impact speed is an integration (~80 µs on
//! the frost layer at `precise`). Its outcome is a pure function of five numbers — the damping δ,
//! the layer drag λ and thickness d in the scales of the impact speed, the contact's end and the
//! integrator's tolerance — so an explorer that keeps the outcomes of one frame answers the next
//! edit at once wherever those numbers did not change. An edit of adhesion, friction, overlays,
//! the family or the chart's range leaves them unchanged (adhesion acts after the layer, Eq. (17));
//! an edit of A, the radii, the density, the moduli or the layer changes them.
//!
//! A kept outcome is the very value the integration returned, so a frame computed with a memo is
//! bit for bit the frame computed without one (tested): the memo trades memory for time only.

use super::layer::LiteralOutcome;
use crate::scene::ContactEnd;

/// The inputs of one literal-reading integration, by their bits (two inputs are equal when they
/// are the same numbers, so a kept outcome is exactly the one the integration would give).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct LiteralKey([u64; 5]);

impl LiteralKey {
    /// The key of [`super::layer::literal`]`(delta, lambda, d, end, rtol)`.
    pub fn new(delta: f64, lambda: f64, d: f64, end: ContactEnd, rtol: f64) -> LiteralKey {
        let end = match end {
            ContactEnd::ForceZero => 0,
            ContactEnd::ZeroOverlap => 1,
        };
        LiteralKey([
            delta.to_bits(),
            lambda.to_bits(),
            d.to_bits(),
            end,
            rtol.to_bits(),
        ])
    }
}

/// Where literal-reading outcomes are kept between calls. `Sync`: the units of one frame may run
/// on several threads and share it.
pub trait LayerMemo: Sync {
    /// The kept outcome for `key`, if any.
    fn get(&self, key: &LiteralKey) -> Option<LiteralOutcome>;
    /// Keeps `outcome` for `key` (a memo may drop it, or older ones, to bound its size).
    fn put(&self, key: LiteralKey, outcome: LiteralOutcome);
}

/// Keeps nothing: every call integrates (the library's default).
#[derive(Debug, Clone, Copy, Default)]
pub struct NoMemo;

impl LayerMemo for NoMemo {
    fn get(&self, _key: &LiteralKey) -> Option<LiteralOutcome> {
        None
    }

    fn put(&self, _key: LiteralKey, _outcome: LiteralOutcome) {}
}

#[cfg(feature = "std")]
pub use shared::SharedLayerMemo;

#[cfg(feature = "std")]
mod shared {
    use super::{LayerMemo, LiteralKey, LiteralOutcome};
    use alloc::collections::BTreeMap;
    use core::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::Mutex;

    /// Two generations of outcomes: lookups read both, new outcomes go to the recent one, and when
    /// it is full it becomes the older one (the outcomes of the frames before last are dropped).
    #[derive(Debug)]
    struct Generations {
        recent: BTreeMap<LiteralKey, LiteralOutcome>,
        older: BTreeMap<LiteralKey, LiteralOutcome>,
    }

    /// A memo shared by threads, bounded to about `2 × capacity` outcomes (80 bytes each with the
    /// map's overhead: the default, 16 384, holds ~30 frames of the literal reading in ~2.6 MB).
    #[derive(Debug)]
    pub struct SharedLayerMemo {
        generations: Mutex<Generations>,
        capacity: usize,
        hits: AtomicUsize,
        misses: AtomicUsize,
    }

    impl Default for SharedLayerMemo {
        fn default() -> Self {
            SharedLayerMemo::new()
        }
    }

    impl SharedLayerMemo {
        /// Outcomes per generation of [`SharedLayerMemo::new`].
        pub const CAPACITY: usize = 16_384;

        /// An empty memo of [`Self::CAPACITY`] outcomes per generation (`const`: it may be a
        /// `static`).
        pub const fn new() -> SharedLayerMemo {
            SharedLayerMemo::with_capacity(Self::CAPACITY)
        }

        /// An empty memo of `capacity` outcomes per generation (at least 1).
        pub const fn with_capacity(capacity: usize) -> SharedLayerMemo {
            SharedLayerMemo {
                generations: Mutex::new(Generations {
                    recent: BTreeMap::new(),
                    older: BTreeMap::new(),
                }),
                capacity: if capacity == 0 { 1 } else { capacity },
                hits: AtomicUsize::new(0),
                misses: AtomicUsize::new(0),
            }
        }

        /// Lookups answered and not answered so far.
        pub fn hits_and_misses(&self) -> (usize, usize) {
            (
                self.hits.load(Ordering::Relaxed),
                self.misses.load(Ordering::Relaxed),
            )
        }

        /// Outcomes kept now.
        pub fn len(&self) -> usize {
            self.generations
                .lock()
                .map_or(0, |g| g.recent.len() + g.older.len())
        }

        /// Whether nothing is kept.
        pub fn is_empty(&self) -> bool {
            self.len() == 0
        }
    }

    impl LayerMemo for SharedLayerMemo {
        fn get(&self, key: &LiteralKey) -> Option<LiteralOutcome> {
            // A poisoned lock (a panic elsewhere while holding it) only costs the memo.
            let found = self
                .generations
                .lock()
                .ok()
                .and_then(|g| g.recent.get(key).or_else(|| g.older.get(key)).copied());
            let counter = if found.is_some() {
                &self.hits
            } else {
                &self.misses
            };
            counter.fetch_add(1, Ordering::Relaxed);
            found
        }

        fn put(&self, key: LiteralKey, outcome: LiteralOutcome) {
            if let Ok(mut g) = self.generations.lock() {
                if g.recent.len() >= self.capacity {
                    g.older = core::mem::take(&mut g.recent);
                }
                g.recent.insert(key, outcome);
            }
        }
    }
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::*;

    fn outcome(eps: f64) -> LiteralOutcome {
        LiteralOutcome {
            eps,
            stuck: false,
            s_c: 1.0,
            x_max: 1.0,
            rhs_evaluations: 7,
        }
    }

    #[test]
    fn keys_tell_apart_every_input() {
        let base = LiteralKey::new(1.0, 2.0, 3.0, ContactEnd::ForceZero, 1e-10);
        let others = [
            LiteralKey::new(1.0 + f64::EPSILON, 2.0, 3.0, ContactEnd::ForceZero, 1e-10),
            LiteralKey::new(
                1.0,
                2.0 + 4.0 * f64::EPSILON,
                3.0,
                ContactEnd::ForceZero,
                1e-10,
            ),
            LiteralKey::new(
                1.0,
                2.0,
                3.0 + 4.0 * f64::EPSILON,
                ContactEnd::ForceZero,
                1e-10,
            ),
            LiteralKey::new(1.0, 2.0, 3.0, ContactEnd::ZeroOverlap, 1e-10),
            LiteralKey::new(1.0, 2.0, 3.0, ContactEnd::ForceZero, 1e-6),
        ];
        for k in others {
            assert_ne!(k, base);
        }
        assert_eq!(
            base,
            LiteralKey::new(1.0, 2.0, 3.0, ContactEnd::ForceZero, 1e-10)
        );
    }

    #[test]
    fn a_full_generation_ages_and_the_one_before_is_dropped() {
        let memo = SharedLayerMemo::with_capacity(2);
        let key = |i: u32| LiteralKey::new(f64::from(i), 0.0, 0.0, ContactEnd::ForceZero, 1e-10);
        for i in 0..2 {
            memo.put(key(i), outcome(f64::from(i)));
        }
        // The third outcome moves the first two to the older generation; both still answer.
        memo.put(key(2), outcome(2.0));
        assert_eq!(memo.len(), 3);
        assert_eq!(memo.get(&key(0)).map(|o| o.eps), Some(0.0));
        memo.put(key(3), outcome(3.0));
        // The fifth drops the first two.
        memo.put(key(4), outcome(4.0));
        assert_eq!(memo.get(&key(0)), None);
        assert_eq!(memo.get(&key(4)).map(|o| o.eps), Some(4.0));
        assert_eq!(memo.get(&key(3)).map(|o| o.eps), Some(3.0));
        assert_eq!(memo.len(), 3);
        assert_eq!(memo.hits_and_misses(), (3, 1));
    }

    #[test]
    fn no_memo_keeps_nothing() {
        let k = LiteralKey::new(1.0, 1.0, 1.0, ContactEnd::ForceZero, 1e-10);
        NoMemo.put(k, outcome(0.5));
        assert_eq!(NoMemo.get(&k), None);
    }
}
