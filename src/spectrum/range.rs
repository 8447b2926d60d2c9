//! A wavelength range, in nanometres: where a renderer samples and an
//! integral runs.
//!
//! Two ranges have names: [`WavelengthRange::VISIBLE`], 360–830 nm, the
//! CIE's tables and the range of pbrt-v4 and Mitsuba 3, and
//! [`WavelengthRange::ASSIGNMENT`], 380–730 nm, the common support of the
//! assignment's data (Appendix 2 and the study). Any other is checked when
//! made: finite, positive, `min < max`; whether an observer has data over
//! it is the observer's question ([`crate::spectrum::StandardObserver::check`]).
//!
//! ```
//! use speclab::spectrum::WavelengthRange;
//! assert_eq!(WavelengthRange::VISIBLE.width(), 470.0);
//! let uv = WavelengthRange::new(300.0, 830.0)?;
//! assert!(uv.contains(300.0) && !uv.contains(299.0));
//! assert!(WavelengthRange::new(700.0, 400.0).is_err());
//! # Ok::<(), speclab::Error>(())
//! ```

use crate::error::Error;
use crate::spectrum::{LAMBDA_MAX, LAMBDA_MIN};

/// `[min, max]` in nm, `0 < min < max`, both finite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WavelengthRange {
    min: f64,
    max: f64,
}

impl WavelengthRange {
    /// 360–830 nm: the CIE's 1 nm tables, pbrt-v4's and Mitsuba 3's range.
    pub const VISIBLE: WavelengthRange = WavelengthRange { min: 360.0, max: 830.0 };
    /// 380–730 nm: the assignment's range (Appendix 2, the study).
    pub const ASSIGNMENT: WavelengthRange = WavelengthRange { min: LAMBDA_MIN, max: LAMBDA_MAX };

    /// The range `[min, max]` nm; an error unless `0 < min < max`, finite.
    pub fn new(min: f64, max: f64) -> Result<Self, Error> {
        if min.is_finite() && max.is_finite() && 0.0 < min && min < max {
            Ok(WavelengthRange { min, max })
        } else {
            Err(Error::Range { min, max })
        }
    }

    /// The same range starting at `min` (for constants; unchecked).
    pub(crate) const fn with_min(self, min: f64) -> Self {
        WavelengthRange { min, ..self }
    }

    /// The same range ending at `max` (for constants; unchecked).
    pub(crate) const fn with_max(self, max: f64) -> Self {
        WavelengthRange { max, ..self }
    }

    /// The lower end, nm.
    #[must_use]
    pub const fn min(self) -> f64 {
        self.min
    }

    /// The upper end, nm.
    #[must_use]
    pub const fn max(self) -> f64 {
        self.max
    }

    /// `max − min`, nm.
    #[must_use]
    pub const fn width(self) -> f64 {
        self.max - self.min
    }

    /// Whether `lambda` lies in `[min, max]` (NaN does not).
    #[must_use]
    pub fn contains(self, lambda: f64) -> bool {
        (self.min..=self.max).contains(&lambda)
    }

    /// Whether this range lies within `outer`.
    #[must_use]
    pub fn within(self, outer: WavelengthRange) -> bool {
        outer.min <= self.min && self.max <= outer.max
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_are_checked_when_made() {
        assert_eq!(WavelengthRange::new(380.0, 730.0).unwrap(), WavelengthRange::ASSIGNMENT);
        for (a, b) in [(400.0, 400.0), (0.0, 10.0), (-1.0, 10.0), (f64::NAN, 700.0), (400.0, f64::INFINITY)] {
            assert!(matches!(WavelengthRange::new(a, b), Err(Error::Range { .. })), "{a}–{b}");
        }
        let r = WavelengthRange::new(1e-3, 2e-3).unwrap();
        assert_eq!((r.min(), r.max()), (1e-3, 2e-3));
    }

    #[test]
    fn containment() {
        let (v, a) = (WavelengthRange::VISIBLE, WavelengthRange::ASSIGNMENT);
        assert!(a.within(v) && !v.within(a) && v.within(v));
        assert!(v.contains(360.0) && v.contains(830.0) && !v.contains(830.000_001) && !v.contains(f64::NAN));
        assert!(!WavelengthRange::new(300.0, 700.0).unwrap().within(v));
    }
}
