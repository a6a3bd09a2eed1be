//! # jobs — one work queue for everything that runs side by side
//!
//! The Verilated model's C++ objects, the formal proofs, the campaign's
//! cases and the block tests' tool runs are each a list of independent
//! jobs run on a few threads. [`run`] is that queue, once: `jobs` threads
//! take the next item from one shared counter (so a long item never holds
//! back the short ones behind it), and the results come back in the items'
//! order whatever order they finished in.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Mutex;

/// Runs `f` on every item on `jobs` threads (at least 1, at most one per
/// item) and returns the results in the items' order. Once an item fails,
/// no further item is started (those running finish) and the error of the
/// first failed item in the items' order is returned.
pub fn run<T: Sync, R: Send>(
    items: &[T],
    jobs: usize,
    f: impl Fn(&T) -> Result<R, String> + Sync,
) -> Result<Vec<R>, String> {
    let next = AtomicUsize::new(0);
    let failed = AtomicBool::new(false);
    let results: Mutex<Vec<Option<Result<R, String>>>> =
        Mutex::new((0..items.len()).map(|_| None).collect());
    std::thread::scope(|s| {
        for _ in 0..jobs.clamp(1, items.len().max(1)) {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                if i >= items.len() || failed.load(Ordering::Relaxed) {
                    break;
                }
                let r = f(&items[i]);
                if r.is_err() {
                    failed.store(true, Ordering::Relaxed);
                }
                results.lock().unwrap_or_else(|e| e.into_inner())[i] = Some(r);
            });
        }
    });
    let results = results.into_inner().unwrap_or_else(|e| e.into_inner());
    if let Some(e) = results.iter().flatten().find_map(|r| r.as_ref().err()) {
        return Err(e.clone());
    }
    Ok(results.into_iter().flatten().flatten().collect())
}

/// The machine's cores (2 when it cannot tell): the default `jobs`.
pub fn cores() -> usize {
    std::thread::available_parallelism().map_or(2, |n| n.get())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn results_come_back_in_order_and_every_item_runs_once() {
        let items: Vec<u64> = (0..50).collect();
        let calls = AtomicUsize::new(0);
        let out = run(&items, 3, |&x| {
            calls.fetch_add(1, Ordering::Relaxed);
            // Uneven work, so that items finish out of order.
            std::thread::sleep(std::time::Duration::from_micros((50 - x) * 20));
            Ok(x * x)
        })
        .unwrap();
        assert_eq!(out, items.iter().map(|x| x * x).collect::<Vec<_>>());
        assert_eq!(calls.load(Ordering::Relaxed), 50);
    }

    #[test]
    fn a_failure_stops_the_queue_and_names_the_first_failed_item() {
        let items: Vec<u32> = (0..1000).collect();
        let calls = AtomicUsize::new(0);
        let e = run(&items, 2, |&x| {
            calls.fetch_add(1, Ordering::Relaxed);
            if x == 3 || x == 5 {
                Err(format!("item {x}"))
            } else {
                Ok(x)
            }
        })
        .unwrap_err();
        assert!(e == "item 3" || e == "item 5", "{e}");
        assert!(calls.load(Ordering::Relaxed) < 1000);
    }

    #[test]
    fn no_items_and_one_job_are_fine() {
        assert_eq!(run(&[] as &[u8], 4, |_| Ok(())).unwrap().len(), 0);
        assert_eq!(run(&[7u8], 0, |&x| Ok(x)).unwrap(), vec![7]);
    }
}
