//! 3×3 matrices as plain data, row-major, acting on column vectors.
//!
//! ```
//! use speclab::color::matrix::{inverse, mul};
//! let m = [[2.0, 0.0, 0.0], [0.0, 4.0, 0.0], [0.0, 0.0, 8.0]];
//! assert_eq!(mul(&inverse(&m), [2.0, 4.0, 8.0]), [1.0, 1.0, 1.0]);
//! ```

/// A 3×3 matrix, row-major, acting on column vectors.
pub type Matrix = [[f64; 3]; 3];

/// `m · v`.
#[inline]
#[must_use]
pub fn mul(m: &Matrix, v: [f64; 3]) -> [f64; 3] {
    m.map(|row| row[0] * v[0] + row[1] * v[1] + row[2] * v[2])
}

/// `a · b`.
#[must_use]
pub fn product(a: &Matrix, b: &Matrix) -> Matrix {
    std::array::from_fn(|r| std::array::from_fn(|c| (0..3).map(|k| a[r][k] * b[k][c]).sum()))
}

/// The determinant of `m`.
#[must_use]
pub const fn determinant(m: &Matrix) -> f64 {
    m[0][0] * cofactor(m, 0, 0) + m[0][1] * cofactor(m, 0, 1) + m[0][2] * cofactor(m, 0, 2)
}

/// The inverse of `m` by cofactors (all zero if `m` is singular); a
/// `const fn`, so inverses of constant matrices are constants.
#[must_use]
pub const fn inverse(m: &Matrix) -> Matrix {
    let det = m[0][0] * cofactor(m, 0, 0) + m[0][1] * cofactor(m, 0, 1) + m[0][2] * cofactor(m, 0, 2);
    let scale = if det != 0.0 { 1.0 / det } else { 0.0 };
    let mut inv = [[0.0; 3]; 3];
    let mut r = 0;
    while r < 3 {
        let mut c = 0;
        while c < 3 {
            inv[r][c] = cofactor(m, c, r) * scale;
            c += 1;
        }
        r += 1;
    }
    inv
}

/// The cofactor of entry `(r, c)`: the signed minor, by cyclic indices.
const fn cofactor(m: &Matrix, r: usize, c: usize) -> f64 {
    let (r1, r2, c1, c2) = ((r + 1) % 3, (r + 2) % 3, (c + 1) % 3, (c + 2) % 3);
    m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::color::XYZ_TO_SRGB;

    #[test]
    fn inverse_inverts() {
        let m = XYZ_TO_SRGB;
        let inv = inverse(&m);
        for j in 0..3 {
            let e: [f64; 3] = std::array::from_fn(|i| f64::from(u8::from(i == j)));
            let back = mul(&m, mul(&inv, e));
            assert!((0..3).all(|i| (back[i] - e[i]).abs() < 1e-12), "{back:?} vs {e:?}");
        }
    }

    #[test]
    fn determinants_and_products() {
        // Each term of the cofactor expansion matters: every entry differs.
        let m = [[2.0, -3.0, 1.0], [2.0, 0.0, -1.0], [1.0, 4.0, 5.0]];
        assert_eq!(determinant(&m), 49.0);
        assert_eq!(determinant(&[[2.0, 0.0, 0.0], [0.0, 3.0, 0.0], [0.0, 0.0, 4.0]]), 24.0);
        let n = [[1.0, 2.0, 0.0], [0.0, 1.0, 3.0], [4.0, 0.0, 1.0]];
        assert_eq!(product(&m, &n), [[6.0, 1.0, -8.0], [-2.0, 4.0, -1.0], [21.0, 6.0, 17.0]]);
        assert_eq!(determinant(&product(&m, &n)), determinant(&m) * determinant(&n));
    }

    #[test]
    fn singular_inverse_is_zero() {
        let singular = [[1.0, 2.0, 3.0], [2.0, 4.0, 6.0], [0.0, 0.0, 1.0]];
        assert_eq!(inverse(&singular), [[0.0; 3]; 3]);
    }
}
