//! Wall-clock measurement for the report and the side-by-side: medians of repeated runs.

use std::time::Instant;

/// The median of some measurements (the upper one of an even count).
pub fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// Median wall time of `reps` runs of `work`, in nanoseconds.
pub fn median_ns(reps: usize, mut work: impl FnMut()) -> f64 {
    median(
        (0..reps)
            .map(|_| {
                let start = Instant::now();
                work();
                start.elapsed().as_nanos() as f64
            })
            .collect(),
    )
}
