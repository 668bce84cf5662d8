//! A computation run on a thread of rayon's pool, its progress passed back to the calling
//! thread ([`on_pool`]).

/// Runs `work` on a thread of rayon's pool (at once when called from one), passing the
/// fractions it reports back to `progress` on this thread, which need not be `Send`. The
/// clearance's branch and bound forks each of its rounds (about half a millisecond of work,
/// thousands of rounds) with `rayon::join`: from outside the pool a fork hands the work in and
/// waits for it through a wake-up of a sleeping thread each way, about a tenth of the round's
/// time on the F-104's 15-coefficient box, while from inside the other thread steals it from
/// its neighbour's queue.
pub(super) fn on_pool<R: Send>(
    progress: &mut dyn FnMut(f64),
    work: impl FnOnce(&mut dyn FnMut(f64)) -> R + Send,
) -> R {
    if rayon::current_thread_index().is_some() {
        return work(progress);
    }
    let (tx, rx) = std::sync::mpsc::channel();
    let mut answer = None;
    rayon::in_place_scope(|s| {
        let answer = &mut answer;
        s.spawn(move |_| {
            // The sender goes with the work, so that the fractions end when it does.
            *answer = Some(work(&mut |f| {
                let _ = tx.send(f);
            }));
        });
        for f in rx {
            progress(f);
        }
    });
    answer.expect("the work ran to its end")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// From outside the pool the work runs on one of its threads and every fraction it reports
    /// reaches `progress`, in order; from inside, it runs on the caller's thread.
    #[test]
    fn the_work_runs_on_the_pool_and_its_progress_comes_back() {
        let mut seen = Vec::new();
        let on = on_pool(&mut |f| seen.push(f), |progress| {
            for f in [0.25, 0.5, 1.0] {
                progress(f);
            }
            rayon::current_thread_index()
        });
        assert!(on.is_some(), "on a thread of the pool");
        assert_eq!(seen, vec![0.25, 0.5, 1.0]);
        let inside = rayon::scope(|_| {
            let caller = rayon::current_thread_index();
            (
                caller,
                on_pool(&mut |_| {}, |_| rayon::current_thread_index()),
            )
        });
        assert_eq!(inside.0, inside.1, "on the caller's thread");
    }
}
