//! Runs on up to two threads: families of simulations, sweeps and the continuation's
//! start points share one scoped-thread map.

/// Runs `f` on every item on up to [`THREADS`] scoped threads, calling `progress(done)` after
/// each item; results in input order.
pub(crate) fn parallel_map<T: Sync, R: Send>(
    items: &[T],
    f: impl Fn(&T) -> R + Sync,
    progress: &(dyn Fn(usize) + Sync),
) -> Vec<R> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let done = AtomicUsize::new(0);
    let step = |x: &T| {
        let r = f(x);
        progress(done.fetch_add(1, Ordering::Relaxed) + 1);
        r
    };
    let threads = THREADS.min(items.len()).max(1);
    if threads == 1 {
        return items.iter().map(step).collect();
    }
    let step = &step;
    let mut out: Vec<Option<R>> = (0..items.len()).map(|_| None).collect();
    std::thread::scope(|scope| {
        let handles: Vec<_> = (0..threads)
            .map(|k| {
                scope.spawn(move || {
                    items
                        .iter()
                        .enumerate()
                        .skip(k)
                        .step_by(threads)
                        .map(|(i, x)| (i, step(x)))
                        .collect::<Vec<(usize, R)>>()
                })
            })
            .collect();
        for h in handles {
            // A panicking worker re-panics here (there is no panic in the simulation code).
            let part = match h.join() {
                Ok(part) => part,
                Err(e) => std::panic::resume_unwind(e),
            };
            for (i, r) in part {
                out[i] = Some(r);
            }
        }
    });
    out.into_iter().flatten().collect()
}

/// Worker threads for families and sweeps (the target machine has two cores).
pub const THREADS: usize = 2;
