//! Wall-clock measurement for the report and the side-by-side: medians of repeated runs, and
//! the spread of a ratio measured over interleaved rounds.

use std::time::Instant;

/// Returns the median of some measurements (the upper one of an even count).
pub fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// Times `reps` runs of `work` and returns their median wall time, in nanoseconds.
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

/// The median of values and the quartiles around it.
///
/// They tell how far apart runs of one measurement lie.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spread {
    pub median: f64,
    /// The first and third quartiles.
    pub q1: f64,
    pub q3: f64,
}

impl Spread {
    /// Computes the median and quartiles of `values` (nearest rank); NaN for none.
    pub fn of(mut values: Vec<f64>) -> Self {
        if values.is_empty() {
            return Self {
                median: f64::NAN,
                q1: f64::NAN,
                q3: f64::NAN,
            };
        }
        values.sort_by(f64::total_cmp);
        let at = |fraction: f64| values[((values.len() - 1) as f64 * fraction).round() as usize];
        Self {
            median: at(0.5),
            q1: at(0.25),
            q3: at(0.75),
        }
    }

    /// Formats the spread as "1.02 (0.98-1.05)": the median, the interquartile range in brackets.
    pub fn describe(&self) -> String {
        format!("{:.2} ({:.2}-{:.2})", self.median, self.q1, self.q3)
    }
}
