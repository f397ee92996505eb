//! The same calls on several threads at once (included by path): for the tests that a law's
//! answer does not depend on the thread it runs on.

/// `f` of every item, the items cut into chunks of `chunk`, each chunk on a thread of its own;
/// the results in the items' order.
pub fn map_on_threads<T: Sync, R: Send>(
    items: &[T],
    chunk: usize,
    f: impl Fn(&T) -> R + Sync,
) -> Vec<R> {
    let f = &f;
    std::thread::scope(|s| {
        let handles: Vec<_> = items
            .chunks(chunk)
            .map(|c| s.spawn(move || c.iter().map(f).collect::<Vec<_>>()))
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().expect("a worker thread panicked"))
            .collect()
    })
}
