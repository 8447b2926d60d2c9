//! Side-by-side timing on a shared, noisy machine: every round times each
//! case once, in turn, so a burst of load from elsewhere falls on all cases
//! alike; a case's figure is the median over rounds of the time per unit
//! (per wavelength, per spectrum, per call).

use std::time::Instant;

/// A timed case: its name, and a batch that returns how many units it did.
pub struct Case<'a> {
    pub name: &'static str,
    pub batch: Box<dyn FnMut() -> usize + 'a>,
}

impl<'a> Case<'a> {
    pub fn new(name: &'static str, batch: impl FnMut() -> usize + 'a) -> Self {
        Case { name, batch: Box::new(batch) }
    }
}

/// Nanoseconds per unit for each case: warm-up, then `rounds` interleaved
/// rounds of batches repeated to last about `target_ms` each; medians.
pub fn measure(cases: &mut [Case], rounds: usize, target_ms: f64) -> Vec<f64> {
    // Warm up and calibrate how many batches make one timing.
    let repeats: Vec<usize> = cases
        .iter_mut()
        .map(|c| {
            for _ in 0..3 {
                (c.batch)();
            }
            let start = Instant::now();
            (c.batch)();
            let once = start.elapsed().as_secs_f64() * 1e3;
            ((target_ms / once.max(1e-6)).ceil() as usize).clamp(1, 1_000_000)
        })
        .collect();
    let mut samples = vec![Vec::with_capacity(rounds); cases.len()];
    for _ in 0..rounds {
        for ((c, &r), s) in cases.iter_mut().zip(&repeats).zip(&mut samples) {
            let start = Instant::now();
            let mut units = 0;
            for _ in 0..r {
                units += (c.batch)();
            }
            s.push(start.elapsed().as_secs_f64() * 1e9 / units as f64);
        }
    }
    samples.into_iter().map(median).collect()
}

/// The median of `v` (the mean of the middle two for even lengths).
pub fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n == 0 {
        f64::NAN
    } else if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}
