//! Independent work on every core, one queue ([`in_turn`]) for the explorer's frames and the
//! scriptable subcommands (issue 26): `rime curve`, `map` and `compare` split their speeds into
//! chunks that scoped threads take in turn. The chunks'
//! results come back in their order, so the output equals the sequential one byte for byte, and
//! the error reported is the sequential run's first.

use std::ops::Range;
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// Items per chunk below which cheap work is not split further (an ε_N from a table costs ~0.1 µs:
/// a chunk must outweigh handing it out).
pub const MIN_CHUNK: usize = 16;

/// Chunks per thread: small enough that a slow chunk (an integration near a threshold) does not
/// leave the other cores idle at the end.
const CHUNKS_PER_THREAD: usize = 8;

/// Threads the subcommands use: the cores this process may use.
pub fn threads() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

/// `f` over `0..n` in chunks of at least `min_chunk` items on `threads` threads (1: in this thread,
/// in order); the chunks' results in the order of their ranges.
pub fn chunks<T: Send>(
    n: usize,
    threads: usize,
    min_chunk: usize,
    f: impl Fn(Range<usize>) -> T + Sync,
) -> Vec<T> {
    let threads = threads.max(1);
    let size = n
        .div_ceil(threads * CHUNKS_PER_THREAD)
        .max(min_chunk.max(1));
    let ranges: Vec<Range<usize>> = (0..n.div_ceil(size).max(1))
        .map(|k| k * size..((k + 1) * size).min(n))
        .collect();
    if threads == 1 || ranges.len() == 1 {
        return ranges.into_iter().map(f).collect();
    }
    in_turn(ranges.len(), threads, None, |k| Some(f(ranges[k].clone()))).unwrap_or_default()
}

/// The one work queue of the terminal crate: tasks `0..n` taken in turn by `threads` scoped threads
/// (this one included); their results in task order. A task that returns `None` stops the others
/// at their next task, and the whole run returns `None` (the explorer's cancelled frame). With
/// `spawn_after`, the other threads start only once this one has worked that long (a cheap frame
/// then never waits for a busy machine's scheduler to hand a new thread a core).
pub fn in_turn<T: Send>(
    n: usize,
    threads: usize,
    spawn_after: Option<Duration>,
    task: impl Fn(usize) -> Option<T> + Sync,
) -> Option<Vec<T>> {
    let slots: Vec<Mutex<Option<T>>> = (0..n).map(|_| Mutex::new(None)).collect();
    let next = AtomicUsize::new(0);
    let stop = AtomicBool::new(false);
    // Takes the next task and runs it; `false` when none is left or a task stopped the run.
    let step = || {
        if stop.load(Ordering::Relaxed) {
            return false;
        }
        let k = next.fetch_add(1, Ordering::Relaxed);
        if k >= n {
            return false;
        }
        match task(k) {
            Some(out) => {
                if let Ok(mut slot) = slots[k].lock() {
                    *slot = Some(out);
                }
                true
            }
            None => {
                stop.store(true, Ordering::Relaxed);
                false
            }
        }
    };
    let helpers_wanted = threads.max(1).min(n.max(1)) - 1;
    std::thread::scope(|s| {
        let start = Instant::now();
        let mut helpers = Vec::new();
        let spawn = |helpers: &mut Vec<_>| {
            *helpers = (0..helpers_wanted)
                .map(|_| s.spawn(|| while step() {}))
                .collect();
        };
        if spawn_after.is_none() {
            spawn(&mut helpers);
        }
        while step() {
            if helpers.is_empty() && spawn_after.is_some_and(|after| start.elapsed() >= after) {
                spawn(&mut helpers);
            }
        }
        for h in helpers {
            if let Err(panic) = h.join() {
                std::panic::resume_unwind(panic);
            }
        }
    });
    if stop.load(Ordering::Relaxed) {
        return None;
    }
    slots
        .into_iter()
        .map(|m| m.into_inner().ok().flatten())
        .collect()
}

/// `f` at every index of `0..n`, on `threads` threads, in index order (`min_chunk`: 1 for a few
/// expensive items, [`MIN_CHUNK`] for many cheap ones).
pub fn each<T: Send>(
    n: usize,
    threads: usize,
    min_chunk: usize,
    f: impl Fn(usize) -> T + Sync,
) -> Vec<T> {
    chunks(n, threads, min_chunk, |range| {
        range.map(&f).collect::<Vec<T>>()
    })
    .into_iter()
    .flatten()
    .collect()
}

/// `f` at every index of `0..n`, on `threads` threads, in index order; the first error in index
/// order (the one a sequential loop would stop at) if any.
pub fn map<T: Send, E: Send>(
    n: usize,
    threads: usize,
    f: impl Fn(usize) -> Result<T, E> + Sync,
) -> Result<Vec<T>, E> {
    let parts = chunks(n, threads, MIN_CHUNK, |range| {
        range.map(&f).collect::<Result<Vec<T>, E>>()
    });
    let mut out = Vec::with_capacity(n);
    for part in parts {
        out.extend(part?);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_index_once_in_order_on_any_thread_count() {
        for n in [0, 1, 15, 16, 17, 100, 1001] {
            for threads in [1, 2, 3, 8] {
                let out: Vec<usize> = map(n, threads, |i| Ok::<_, ()>(i * i)).unwrap();
                assert_eq!(
                    out,
                    (0..n).map(|i| i * i).collect::<Vec<_>>(),
                    "{n} {threads}"
                );
            }
        }
    }

    #[test]
    fn few_expensive_items_are_each_their_own_chunk() {
        let parts = chunks(5, 2, 1, |r| r);
        assert_eq!(parts, (0..5).map(|i| i..i + 1).collect::<Vec<_>>());
        assert_eq!(each(5, 2, 1, |i| 2 * i), vec![0, 2, 4, 6, 8]);
    }

    #[test]
    fn a_task_that_stops_stops_the_run_on_any_thread_count() {
        for threads in [1, 2, 4] {
            for after in [None, Some(Duration::ZERO)] {
                let all = in_turn(50, threads, after, Some);
                assert_eq!(all, Some((0..50).collect()), "{threads} {after:?}");
                let stopped = in_turn(50, threads, after, |k| (k != 7).then_some(k));
                assert_eq!(stopped, None, "{threads} {after:?}");
            }
        }
        assert_eq!(in_turn(0, 3, None, Some), Some(Vec::<usize>::new()));
    }

    #[test]
    fn the_error_is_the_first_in_index_order() {
        for threads in [1, 2, 4] {
            let r = map(500, threads, |i| {
                if i == 123 || i == 400 { Err(i) } else { Ok(i) }
            });
            assert_eq!(r, Err(123), "{threads}");
        }
    }
}
