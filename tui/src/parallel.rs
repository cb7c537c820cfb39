//! Independent work on every core for the scriptable subcommands (issue 26): `rime curve`, `map`
//! and `compare` split their speeds into chunks that scoped threads take in turn. The chunks'
//! results come back in their order, so the output equals the sequential one byte for byte, and
//! the error reported is the sequential run's first.

use std::ops::Range;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

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
    let slots: Vec<Mutex<Option<T>>> = ranges.iter().map(|_| Mutex::new(None)).collect();
    let next = AtomicUsize::new(0);
    let work = || {
        loop {
            let k = next.fetch_add(1, Ordering::Relaxed);
            let Some(range) = ranges.get(k) else {
                return;
            };
            let out = f(range.clone());
            if let Ok(mut slot) = slots[k].lock() {
                *slot = Some(out);
            }
        }
    };
    std::thread::scope(|s| {
        let helpers: Vec<_> = (1..threads.min(ranges.len()))
            .map(|_| s.spawn(work))
            .collect();
        work();
        for h in helpers {
            if let Err(panic) = h.join() {
                std::panic::resume_unwind(panic);
            }
        }
    });
    slots
        .into_iter()
        .filter_map(|m| m.into_inner().ok().flatten())
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
    fn the_error_is_the_first_in_index_order() {
        for threads in [1, 2, 4] {
            let r = map(500, threads, |i| {
                if i == 123 || i == 400 { Err(i) } else { Ok(i) }
            });
            assert_eq!(r, Err(123), "{threads}");
        }
    }
}
