//! Fitting a table: every node's colour fitted by the space's
//! Gauss–Newton fit (`upsample`), each starting from its neighbour's
//! coefficients, the three cases on three threads.

use crate::color::rgb_table::lookup::node;
use crate::color::upsample::Fit;

/// The coefficients of all three cases, `[case][z][y][x]`, in `f32`.
pub(super) fn coefficients(fit: &Fit, n: usize) -> Vec<[f32; 3]> {
    let cases: Vec<Vec<[f32; 3]>> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..3).map(|case| scope.spawn(move || case_table(fit, n, case))).collect();
        handles.into_iter().map(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e))).collect()
    });
    cases.concat()
}

/// The coefficients of one case, `[z][y][x]`: every slice of `z`, from the
/// middle outwards, each fit starting from its neighbour in the slice
/// before (or, in the first, from the full fit).
fn case_table(fit: &Fit, n: usize, case: usize) -> Vec<[f32; 3]> {
    let mut out = vec![[0.0; 3]; n * n * n];
    let mut start = vec![None; n * n * n];
    let rgb = |k: usize, j: usize, i: usize| {
        let z = f64::from(node(k, n));
        let mut c = [0.0; 3];
        c[case] = z;
        c[(case + 1) % 3] = i as f64 / (n - 1) as f64 * z;
        c[(case + 2) % 3] = j as f64 / (n - 1) as f64 * z;
        c
    };
    let middle = n / 5;
    let order = std::iter::once((middle, None))
        .chain((middle + 1..n).map(|k| (k, Some(k - 1))))
        .chain((0..middle).rev().map(|k| (k, Some(k + 1))));
    for (k, from) in order {
        for j in 0..n {
            for i in 0..n {
                let guess = from.and_then(|f| start[(f * n + j) * n + i]);
                let c = fit.fit_from(rgb(k, j, i), guess).coefficients();
                start[(k * n + j) * n + i] = Some(c);
                out[(k * n + j) * n + i] = c.map(|v| v as f32);
            }
        }
    }
    out
}
