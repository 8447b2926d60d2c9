//! The CIE 1931 2° standard observer: x̄, ȳ, z̄ at any wavelength.
//!
//! The matching functions are the 5 nm table of Appendix 1, part C,
//! interpolated by the four-point cubic and clamped at zero (the raw cubic
//! of z̄ dips to −6.4e-6 at 632.1 nm, where z̄ reaches zero; a matching
//! function is never negative, and the clamp keeps every sample's Y
//! non-negative).
//!
//! Values are plain `[x̄, ȳ, z̄]` arrays at this floor; `speclab::Xyz`
//! (one floor up, in `color`) takes them with `Xyz::from`.
//!
//! ```
//! let [x, y, z] = speclab::spectrum::observer::xyz_bar(555.0);
//! assert_eq!(y, 1.0);
//! assert!(x > 0.5 && z < 0.01);
//! ```

use crate::spectrum::data::cie1931::{X_BAR, Y_BAR, Z_BAR};
use crate::spectrum::data::observers;
use crate::spectrum::data::{CIE_X_COEFFS, CIE_Y_BREAKS, CIE_Y_COEFFS, CIE_Y_LAMBDA, CIE_Z_COEFFS};
use crate::spectrum::float::Float;
use crate::spectrum::interp;
use crate::spectrum::lookup::{DENSE_ENTRIES, DENSE_RANGE, DENSE_VALUES, UniformLookup, entry};
use crate::spectrum::piecewise::View;
use crate::spectrum::range::WavelengthRange;
use crate::spectrum::sampled::Wavelengths;
use crate::spectrum::tabulated::TabulatedSpectrum;
use crate::spectrum::{LAMBDA_MAX, LAMBDA_MIN};
use wide::{CmpGe, f64x4};

/// `∫ ȳ dλ` over 380–730 nm, in nm: the Y of a spectrum that is 1
/// everywhere (the 5 nm table of Appendix 1, interpolated by the clamped
/// cubic as everywhere here; computed at compile time). Dividing a Y by it
/// gives the luminance in the units of the spectrum's values. It differs
/// from pbrt-v4's 106.856895 and Mitsuba's 106.7502594, which integrate
/// other tables over 360–830 nm.
pub const Y_BAR_INTEGRAL: f64 = interp::integral(
    &CIE_Y_LAMBDA,
    &CIE_Y_COEFFS,
    &CIE_Y_BREAKS,
    [0.0, f64::INFINITY],
    LAMBDA_MIN,
    LAMBDA_MAX,
);

/// x̄, ȳ and z̄ as spectra, in that order.
pub static CMFS: [&TabulatedSpectrum; 3] = [&X_BAR, &Y_BAR, &Z_BAR];

/// x̄, ȳ and z̄'s tables, for exact integration.
pub(crate) fn views() -> [View<'static>; 3] {
    CMFS.map(|s| s.view())
}

/// One row per 5 nm segment: the coefficients of x̄, ȳ and z̄ together
/// (`[x0..x3, y0..y3, z0..z3]`, in `t = λ − λₖ`), so that one lookup serves
/// all three. 80 rows of 96 bytes.
pub(crate) const ROWS: [[f64; 12]; SEGMENTS] = rows();

const SEGMENTS: usize = CIE_Y_LAMBDA.len() - 1;

const fn rows() -> [[f64; 12]; SEGMENTS] {
    let mut out = [[0.0; 12]; SEGMENTS];
    let mut k = 0;
    while k < SEGMENTS {
        let mut i = 0;
        while i < 4 {
            out[k][i] = CIE_X_COEFFS[k][i];
            out[k][4 + i] = CIE_Y_COEFFS[k][i];
            out[k][8 + i] = CIE_Z_COEFFS[k][i];
            i += 1;
        }
        k += 1;
    }
    out
}

/// The same coefficients with the channels across the lanes: per segment,
/// the vectors `[xᵢ, yᵢ, zᵢ, eᵢ]` for i = 0..3, where `e = [1, 0, 0, 0]` is
/// the constant 1. Horner's rule on these four vectors evaluates x̄, ȳ, z̄
/// and 1 at once, in the order of the scalar rule (the same bits), and
/// gives the row `[x̄, ȳ, z̄, 1]` a drawn sample scales by its weight. 80
/// segments of 128 bytes, each two cache lines.
static CHANNELS: Channels = Channels(channels());

#[repr(C, align(64))]
struct Channels([[f64x4; 4]; SEGMENTS]);

const fn channels() -> [[f64x4; 4]; SEGMENTS] {
    let mut out = [[f64x4::ZERO; 4]; SEGMENTS];
    let mut k = 0;
    while k < SEGMENTS {
        let mut i = 0;
        while i < 4 {
            out[k][i] =
                f64x4::new([ROWS[k][i], ROWS[k][4 + i], ROWS[k][8 + i], if i == 0 { 1.0 } else { 0.0 }]);
            i += 1;
        }
        k += 1;
    }
    out
}

/// Colour matching functions x̄, ȳ, z̄ at K wavelengths at once: the exact
/// interpolated CIE 1931 observer, [`AssignmentObserver`], or a dense table
/// (`DenseObserver`). A hero sample takes its weights from one when it is
/// drawn.
pub trait Observer {
    /// `[x̄, ȳ, z̄, 1]` at each wavelength of `at`, in its precision (a
    /// sample scales the row by the pdf's weight `1/(K·pdf)` in one
    /// four-lane multiplication, and the fourth column becomes that
    /// weight; a sample sets it itself, so what an implementation puts
    /// there does not change the pdf).
    fn xyz_bar_at<const K: usize, T: Float>(&self, at: &impl Wavelengths<K, T>) -> [[T; 4]; K];

    /// The range its data cover: outside it every weight is 0, so a
    /// density drawing there would lose those wavelengths (checked by
    /// [`HeroSample::from_pdf_with`](crate::HeroSample::from_pdf_with) and
    /// `from_wavelengths_with`).
    fn data_range(&self) -> WavelengthRange;

    /// `∫ȳ` over `range` as this observer weighs wavelengths drawn there
    /// (its table's own interpolation; zero outside its data): the `Y` a
    /// constant 1 has, what a renderer divides by.
    fn y_integral(&self, range: WavelengthRange) -> f64;
}

/// The CIE 1931 2° observer of Appendix 1, interpolated by the clamped
/// cubic: the exact one.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct AssignmentObserver;

impl Observer for AssignmentObserver {
    /// Evaluated in `f64` at each wavelength (one segment lookup for all
    /// three) and rounded to `T`: for four wavelengths or more, Horner's
    /// rule on `[x̄, ȳ, z̄, 1]` side by side in one `f64x4`, from
    /// coefficients stored in that layout; for fewer, the scalar rule (one
    /// wavelength is one chain of dependent steps, shorter in scalar code).
    /// The same bits either way.
    #[inline(always)]
    fn xyz_bar_at<const K: usize, T: Float>(&self, at: &impl Wavelengths<K, T>) -> [[T; 4]; K] {
        let lambda = at.lambda();
        let mut rows = [[T::ZERO; 4]; K];
        for (row, l) in rows.iter_mut().zip(lambda) {
            let l = l.to_f64();
            *row = if K < 4 { lone_row(l) } else { xyz_bar_row(l) }.map(T::from_f64);
        }
        rows
    }

    /// 380–780 nm, the assignment's table.
    fn data_range(&self) -> WavelengthRange {
        WavelengthRange::ASSIGNMENT.with_max(780.0)
    }

    /// The cubic's exact integral (0 past its data).
    fn y_integral(&self, range: WavelengthRange) -> f64 {
        interp::integral(
            &CIE_Y_LAMBDA,
            &CIE_Y_COEFFS,
            &CIE_Y_BREAKS,
            [0.0, f64::INFINITY],
            range.min(),
            range.max(),
        )
    }
}

/// `[x̄, ȳ, z̄]` at `lambda` nm; zero outside 380–780 nm.
///
/// The three tables share one wavelength grid (checked in the tests), so the
/// segment is found once for all three, in one multiplication, and its row
/// holds all twelve coefficients.
#[inline(always)]
#[must_use]
pub fn xyz_bar(lambda: f64) -> [f64; 3] {
    const FIRST: f64 = CIE_Y_LAMBDA[0];
    const LAST: f64 = CIE_Y_LAMBDA[SEGMENTS];
    let (r, knot) = LOOKUP.row(&ROWS, &CIE_Y_LAMBDA, lambda);
    let t = lambda - knot;
    let at = |i: usize| {
        let p = interp::segment_value([r[i], r[i + 1], r[i + 2], r[i + 3]], t);
        if p > 0.0 { p } else { 0.0 }
    };
    // FIRST ≤ λ ≤ LAST in one comparison (NaN compares false).
    let inside = (lambda - FIRST) * (LAST - lambda) >= 0.0;
    if inside { [at(0), at(4), at(8)] } else { [0.0; 3] }
}

/// [`xyz_bar`] with a fourth column of 1 (which a sample replaces by its
/// weight).
#[inline(always)]
fn lone_row(lambda: f64) -> [f64; 4] {
    let [x, y, z] = xyz_bar(lambda);
    [x, y, z, 1.0]
}

/// `[x̄, ȳ, z̄, 1]` at `lambda` nm, x̄, ȳ, z̄ zero outside 380–780 nm (and
/// for NaN): four Horner steps on the lanes of [`CHANNELS`] (the fourth
/// lane's coefficients are `[1, 0, 0, 0]`), clamped at zero as the scalar
/// rule clamps (`p > 0 ? p : 0`, what SSE, AVX and NEON's maximum does;
/// the support's mask discards whatever a NaN gave), and no branch.
#[inline(always)]
pub(crate) fn xyz_bar_row(lambda: f64) -> [f64; 4] {
    const FIRST: f64 = CIE_Y_LAMBDA[0];
    const LAST: f64 = CIE_Y_LAMBDA[SEGMENTS];
    let (c, knot) = LOOKUP.row(&CHANNELS.0, &CIE_Y_LAMBDA, lambda);
    let t = f64x4::splat(lambda - knot);
    let [c0, c1, c2, c3] = c;
    let p = (c0 + t * (c1 + t * (c2 + t * c3))).fast_max(f64x4::ZERO);
    // FIRST ≤ λ ≤ LAST in one comparison (NaN compares false), as a mask;
    // the fourth lane is 1 either way, as the scalar rule's.
    let inside = f64x4::splat((lambda - FIRST) * (LAST - lambda)).cmp_ge(f64x4::ZERO);
    ((p & inside) | f64x4::new([0.0, 0.0, 0.0, 1.0])).to_array()
}

/// [`xyz_bar`] as a `const fn` (the same values, found by the table's
/// own evaluation), for tables computed at compile time.
pub(crate) const fn xyz_bar_const(lambda: f64) -> [f64; 3] {
    const BOUNDS: [f64; 2] = [0.0, f64::INFINITY];
    [
        interp::eval(&CIE_Y_LAMBDA, &CIE_X_COEFFS, BOUNDS, lambda),
        interp::eval(&CIE_Y_LAMBDA, &CIE_Y_COEFFS, BOUNDS, lambda),
        interp::eval(&CIE_Y_LAMBDA, &CIE_Z_COEFFS, BOUNDS, lambda),
    ]
}

/// The observer's 5 nm grid, made for [`ROWS`].
const LOOKUP: UniformLookup = match UniformLookup::for_table(&CIE_Y_LAMBDA, SEGMENTS) {
    Some(g) => g,
    None => panic!("the CIE tables are equidistant"),
};

/// An observer at every whole nanometre from 360 to 830 nm, in `f32` and
/// `f64`: one row `[x̄, ȳ, z̄, 1]` per nanometre, computed at compile time,
/// looked up at the nearest one in the wavelengths' precision (a
/// reference to static rows). [`DenseObserver::ASSIGNMENT`] (the default,
/// [`DenseObserver::new`]) is the assignment's cubic at whole nanometres,
/// zero outside 380–780 nm; [`DenseObserver::CIE_1931`] and
/// [`DenseObserver::CIE_1964`] are the CIE's 1 nm tables as they are
/// (`StandardObserver::dense` gives each observer's).
#[derive(Clone, Copy)]
pub struct DenseObserver {
    rows: &'static DenseRows,
}

/// The rows of a dense observer, then `[0, 0, 0, 1]` outside.
struct DenseRows {
    name: &'static str,
    /// Where the table holds data (zeros elsewhere).
    data: WavelengthRange,
    f64: [[f64; 4]; DENSE_ENTRIES],
    f32: [[f32; 4]; DENSE_ENTRIES],
}

impl DenseObserver {
    /// The assignment's 5 nm CIE 1931 table, cubic, at every whole nanometre.
    pub const ASSIGNMENT: DenseObserver = DenseObserver { rows: &ASSIGNMENT_ROWS };
    /// The CIE 1931 2° observer's 1 nm table.
    pub const CIE_1931: DenseObserver = DenseObserver { rows: &CIE_1931_ROWS };
    /// The CIE 1964 10° observer's 1 nm table.
    pub const CIE_1964: DenseObserver = DenseObserver { rows: &CIE_1964_ROWS };
    /// The CIE 2015 2° observer's 1 nm table (CIE 170-2), 390–830 nm.
    pub const CIE_2015_2: DenseObserver = DenseObserver { rows: &CIE_2015_2_ROWS };
    /// The CIE 2015 10° observer's 1 nm table (CIE 170-2), 390–830 nm.
    pub const CIE_2015_10: DenseObserver = DenseObserver { rows: &CIE_2015_10_ROWS };

    /// [`DenseObserver::ASSIGNMENT`] (nothing to build: its rows are static).
    #[must_use]
    pub const fn new() -> Self {
        Self::ASSIGNMENT
    }

    /// The rows `[x̄, ȳ, z̄, 1]` at 360, 361, …, 830 nm in precision `T`
    /// (`[0, 0, 0, 1]` outside the observer's data): what a sample's
    /// nearest nanometre reads, and what a shader's observer buffer holds.
    #[must_use]
    pub fn rows<T: Float>(&self) -> &'static [[T; 4]; DENSE_VALUES] {
        let all = T::choose(&self.rows.f32, &self.rows.f64);
        all.first_chunk().expect("471 of 472 rows")
    }
}

impl Default for DenseObserver {
    fn default() -> Self {
        Self::ASSIGNMENT
    }
}

impl PartialEq for DenseObserver {
    fn eq(&self, other: &Self) -> bool {
        std::ptr::eq(self.rows, other.rows)
    }
}

impl Eq for DenseObserver {}

impl std::fmt::Debug for DenseObserver {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "DenseObserver({})", self.rows.name)
    }
}

impl Observer for DenseObserver {
    #[inline(always)]
    fn xyz_bar_at<const K: usize, T: Float>(&self, at: &impl Wavelengths<K, T>) -> [[T; 4]; K] {
        let (nearest, rows) = (at.nearest_nm(), T::choose(&self.rows.f32, &self.rows.f64));
        std::array::from_fn(|j| entry(rows, nearest[j]))
    }

    fn data_range(&self) -> WavelengthRange {
        self.rows.data
    }

    /// Each whole nanometre's `ȳ` over its cell (a wavelength reads its
    /// nearest), the cells cut to `range`: exactly what a sample drawn
    /// over `range` weighs on average.
    fn y_integral(&self, range: WavelengthRange) -> f64 {
        cells_integral(&self.rows.f64, 1, range)
    }
}

impl DenseObserver {
    /// [`Observer::y_integral`] at compile time.
    #[must_use]
    pub const fn y_integral_const(&self, range: WavelengthRange) -> f64 {
        cells_integral(&self.rows.f64, 1, range)
    }
}

/// `Σ rows[i][column]·|[λᵢ − ½, λᵢ + ½] ∩ range|`, `λᵢ = 360 + i` nm: the
/// integral of a 1 nm table read at the nearest whole nanometre.
pub(crate) const fn cells_integral<const N: usize>(
    rows: &[[f64; N]; DENSE_ENTRIES],
    column: usize,
    range: WavelengthRange,
) -> f64 {
    let mut sum = 0.0;
    let mut i = 0;
    while i < DENSE_VALUES {
        let lambda = DENSE_RANGE.min() + i as f64;
        let (a, b) = (lambda - 0.5, lambda + 0.5);
        let a = if a > range.min() { a } else { range.min() };
        let b = if b < range.max() { b } else { range.max() };
        if b > a {
            sum += rows[i][column] * (b - a);
        }
        i += 1;
    }
    sum
}

static ASSIGNMENT_ROWS: DenseRows =
    dense_rows("assignment", WavelengthRange::ASSIGNMENT.with_max(780.0), &assignment_rows());
static CIE_1931_ROWS: DenseRows =
    dense_rows("CIE 1931 2°", WavelengthRange::VISIBLE, &table_rows(&observers::CIE_1931_2));
static CIE_1964_ROWS: DenseRows =
    dense_rows("CIE 1964 10°", WavelengthRange::VISIBLE, &table_rows(&observers::CIE_1964_10));
static CIE_2015_2_ROWS: DenseRows =
    dense_rows("CIE 2015 2°", CIE_2015_DATA, &table_rows(&observers::CIE_2015_2));
static CIE_2015_10_ROWS: DenseRows =
    dense_rows("CIE 2015 10°", CIE_2015_DATA, &table_rows(&observers::CIE_2015_10));

/// Where the CIE 2015 observers' data lie, nm.
pub(crate) const CIE_2015_DATA: WavelengthRange = WavelengthRange::VISIBLE.with_min(390.0);

/// Both precisions of `f64` rows.
const fn dense_rows(name: &'static str, data: WavelengthRange, f64: &[[f64; 4]; DENSE_ENTRIES]) -> DenseRows {
    DenseRows { name, data, f64: *f64, f32: crate::spectrum::float::rounded(f64) }
}

/// `[x̄, ȳ, z̄, 1]` of the assignment's cubic per whole nanometre, and
/// `[0, 0, 0, 1]` outside (a wavelength outside weighs nothing but keeps
/// its pdf).
const fn assignment_rows() -> [[f64; 4]; DENSE_ENTRIES] {
    let mut out = [[0.0, 0.0, 0.0, 1.0]; DENSE_ENTRIES];
    let mut i = 0;
    while i < DENSE_VALUES {
        let [x, y, z] = xyz_bar_const(DENSE_RANGE.min() + i as f64);
        out[i] = [x, y, z, 1.0];
        i += 1;
    }
    out
}

/// A 1 nm table over 360–830 nm as rows, then `[0, 0, 0, 1]`.
const fn table_rows(table: &[[f64; 3]; DENSE_VALUES]) -> [[f64; 4]; DENSE_ENTRIES] {
    let mut out = [[0.0, 0.0, 0.0, 1.0]; DENSE_ENTRIES];
    let mut i = 0;
    while i < DENSE_VALUES {
        out[i] = [table[i][0], table[i][1], table[i][2], 1.0];
        i += 1;
    }
    out
}

#[cfg(test)]
#[path = "observer_tests.rs"]
mod tests;
