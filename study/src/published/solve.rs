//! Small dense linear systems, by Gaussian elimination with partial
//! pivoting: the node polynomial of Borges's rules and interpolatory
//! weights (at most 64 unknowns), and the minimax weights (3·M, at
//! most 192).
//!
//! ```
//! use speclab_study::published::solve::solve;
//! let x = solve(vec![vec![2.0, 1.0], vec![1.0, 3.0]], vec![3.0, 5.0]).unwrap();
//! assert!((x[0] - 0.8).abs() < 1e-15 && (x[1] - 1.4).abs() < 1e-15);
//! assert!(solve(vec![vec![1.0, 2.0], vec![2.0, 4.0]], vec![1.0, 2.0]).is_none());
//! ```

/// `x` with `a·x = b` (`a` given by rows, square, as long as `b`); `None`
/// for a singular (or numerically singular) or mis-shaped system.
#[must_use]
pub fn solve(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Option<Vec<f64>> {
    let n = b.len();
    if a.len() != n || a.iter().any(|row| row.len() != n) {
        return None;
    }
    let scale = a.iter().flatten().fold(0.0_f64, |m, v| m.max(v.abs()));
    for k in 0..n {
        let pivot = (k..n).max_by(|&i, &j| a[i][k].abs().total_cmp(&a[j][k].abs()))?;
        if a[pivot][k].is_nan() || a[pivot][k].abs() <= 1e-13 * scale {
            return None;
        }
        a.swap(k, pivot);
        b.swap(k, pivot);
        for i in k + 1..n {
            let f = a[i][k] / a[k][k];
            let (top, rest) = a.split_at_mut(i);
            rest[0].iter_mut().zip(&top[k]).skip(k).for_each(|(x, p)| *x -= f * p);
            b[i] -= f * b[k];
        }
    }
    let mut x = vec![0.0; n];
    for k in (0..n).rev() {
        let tail: f64 = (k + 1..n).map(|j| a[k][j] * x[j]).sum();
        x[k] = (b[k] - tail) / a[k][k];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

#[cfg(test)]
mod tests {
    use super::solve;

    /// A 3 × 3 system whose answer is known, rows given out of pivot order.
    #[test]
    fn solves_a_known_system() {
        let a = vec![vec![1.0, 2.0, 3.0], vec![4.0, 5.0, 6.0], vec![7.0, 8.0, 10.0]];
        let x = [1.0, -2.0, 3.0];
        let b = a.iter().map(|r: &Vec<f64>| r.iter().zip(&x).map(|(a, x)| a * x).sum()).collect();
        let got = solve(a, b).unwrap();
        for (g, w) in got.iter().zip(x) {
            assert!((g - w).abs() < 1e-12, "{got:?}");
        }
    }

    /// Mis-shaped systems, and pivots below 1e-13 of the largest entry
    /// (whatever the matrix's scale), give `None`.
    #[test]
    fn refuses_mis_shaped_and_singular_systems() {
        assert!(solve(vec![vec![1.0, 2.0, 3.0], vec![4.0, 5.0, 6.0]], vec![1.0, 2.0]).is_none());
        assert!(solve(vec![vec![1.0, 2.0]], vec![1.0, 2.0]).is_none());
        assert!(solve(vec![vec![1.0, 1.0], vec![1.0, 1.0 + 1e-15]], vec![1.0, 2.0]).is_none());
        let big = vec![vec![1e3, 1e3], vec![1e3, 1e3 + 1e-11]];
        assert!(solve(big, vec![1.0, 2.0]).is_none());
        let fine = vec![vec![1e3, 1e3], vec![1e3, 1e3 + 1e-6]];
        assert!(solve(fine, vec![1.0, 2.0]).is_some());
    }
}
