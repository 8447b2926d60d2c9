//! Where an error sequence drops below a threshold: the first count that is
//! below it, and the count from which it *stays* below.
//!
//! The two differ where a method is erratic: under F11, box buckets are
//! below ΔE00 1 at M = 22 but above it again at M = 23–25, 27, 29–31 and 38,
//! and stay below only from M = 39 on. A renderer that picks M = 22 is
//! within budget by luck.
//!
//! ```
//! use speclab_study::experiments::threshold::{Crossing, crossing};
//! let errors = [(1, 3.0), (2, 0.8), (3, 1.2), (4, 0.6), (5, 0.4)];
//! assert_eq!(crossing(&errors, 1.0), Crossing { first: Some(2), stable: Some(4) });
//! assert_eq!(crossing(&errors, 0.1), Crossing { first: None, stable: None });
//! ```

/// The counts at which a sequence crosses a threshold.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Crossing {
    /// The smallest count whose error is below the threshold.
    pub first: Option<usize>,
    /// The smallest count from which every error, up to the last count
    /// studied, is below the threshold.
    pub stable: Option<usize>,
}

/// Where `points`, `(count, error)` pairs in increasing count, drop below
/// `threshold` (strictly; a NaN error is not below).
#[must_use]
pub fn crossing(points: &[(usize, f64)], threshold: f64) -> Crossing {
    let below = |e: f64| e < threshold;
    let first = points.iter().find(|p| below(p.1)).map(|p| p.0);
    let tail = points.iter().rev().take_while(|p| below(p.1)).count();
    let stable = points.get(points.len() - tail).map(|p| p.0);
    Crossing { first, stable }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edges() {
        assert_eq!(crossing(&[], 1.0), Crossing { first: None, stable: None });
        assert_eq!(crossing(&[(1, 0.5)], 1.0), Crossing { first: Some(1), stable: Some(1) });
        assert_eq!(crossing(&[(1, 1.0)], 1.0), Crossing { first: None, stable: None }, "strictly below");
        let dips = [(1, 0.5), (2, 2.0), (3, f64::NAN), (4, 0.9)];
        assert_eq!(crossing(&dips, 1.0), Crossing { first: Some(1), stable: Some(4) });
        let ends_above = [(1, 0.5), (2, 0.5), (3, 2.0)];
        assert_eq!(crossing(&ends_above, 1.0), Crossing { first: Some(1), stable: None });
    }
}
