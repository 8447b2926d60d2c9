//! The table's lookup, as `const fn`s over the table file's bytes: the
//! same arithmetic at compile time (`RgbTable::const_albedo`) and at run
//! time, in `f32`, with no search and no allocation.
//!
//! The largest component `z` has its nodes at `g(k/(n − 1))`, `g` the
//! smoothstep `3t² − 2t³` taken twice (pbrt-v4's placement: dense near 0
//! and 1, where the fits change fastest). Its interval is read from a
//! table of guesses keyed by the exponent and first mantissa bits of the
//! distance to the nearer end (`z` or `1 − z`), put right by one
//! comparison on each side: no search, no square root, the same at
//! compile time and at run time. The other two components are fractions
//! of `z` on a regular grid. Eight coefficient triples are interpolated
//! trilinearly, linearly in `z` between its nodes: four lanes at a time
//! at run time, the same operations in the same order, so the same bits.

use speclab_tables::rgb_file::HEADER_LEN;

use wide::f32x4;

/// The node `k` of `n` of the largest component, in `f32` (computed in
/// `f64`, then rounded: the fits are made at exactly these values).
#[must_use]
pub const fn node(k: usize, n: usize) -> f32 {
    if n < 2 || k >= n {
        return if k == 0 { 0.0 } else { 1.0 };
    }
    let t = k as f64 / (n - 1) as f64;
    let s = t * t * (3.0 - 2.0 * t);
    (s * s * (3.0 - 2.0 * s)) as f32
}

/// The most nodes a table has per axis.
pub(crate) const MAX_NODES: usize = speclab_tables::rgb_file::MAX_RESOLUTION as usize;

/// The `n` nodes of the largest component, computed once per table.
pub(crate) const fn nodes(n: usize) -> [f32; MAX_NODES] {
    let mut out = [0.0; MAX_NODES];
    let mut k = 0;
    while k < n {
        out[k] = node(k, n);
        k += 1;
    }
    out
}

/// The interval of `z` in (0, 1], `k` in `0..n − 1` with
/// `nodes[k] ≤ z < nodes[k + 1]` (the last interval closed), from a first
/// guess `k` at most one off.
#[inline(always)]
const fn settle(z: f32, guess: usize, nodes: &[f32; MAX_NODES], n: usize) -> usize {
    let mut k = if guess > n - 2 { n - 2 } else { guess };
    if k > 0 && z < nodes[k] {
        k -= 1;
    } else if k < n - 2 && z >= nodes[k + 1] {
        k += 1;
    }
    k
}

/// [`settle`]'s interval found by walking the nodes: what the guesses are
/// made of (and tested against).
pub(crate) const fn interval_walked(z: f32, nodes: &[f32; MAX_NODES], n: usize) -> usize {
    let mut k = 0;
    while k < n - 2 && z >= nodes[k + 1] {
        k += 1;
    }
    k
}

/// Mantissa bits in a key: a key's cell is at most 1/128 of its value
/// wide, narrower than the nodes' relative spacing below ½ (at least 1/57
/// at 256 nodes), so a cell holds at most one node.
const KEY_BITS: u32 = 7;
/// The biased exponent of 2⁻³⁰: distances below it share the first key
/// (the first node above 0 is above it up to 256 nodes).
const LOW_EXPONENT: u32 = 97;
/// Keys: 30 binary orders of magnitude of 128 cells.
pub(crate) const KEYS: usize = ((127 - LOW_EXPONENT) << KEY_BITS) as usize;

/// The key of a distance `d` in [0, ½]: its exponent and first mantissa
/// bits, from 2⁻³⁰ up.
#[inline(always)]
const fn key(d: f32) -> usize {
    let bits = d.to_bits() >> (23 - KEY_BITS);
    let low = LOW_EXPONENT << KEY_BITS;
    if bits < low {
        0
    } else if (bits - low) as usize >= KEYS {
        KEYS - 1
    } else {
        (bits - low) as usize
    }
}

/// For each key, the interval of the smallest distance in its cell (by
/// walking the nodes): the guess of the interval of any distance in it,
/// at most one low. Computed once per table.
pub(crate) const fn guesses(nodes: &[f32; MAX_NODES], n: usize) -> [u8; KEYS] {
    let mut out = [0; KEYS];
    let mut c = 1;
    while c < KEYS {
        let d = f32::from_bits(((c as u32) + (LOW_EXPONENT << KEY_BITS)) << (23 - KEY_BITS));
        out[c] = interval_walked(d, nodes, n) as u8;
        c += 1;
    }
    out
}

/// [`settle`]'s interval of `z` in (0, 1] by the table of guesses: the
/// distance to the nearer end, `z` or `1 − z` (exact), looked up, mirrored
/// above ½ (the nodes are symmetric), and put right by one comparison on
/// each side. No search, no square root: the same at compile time and at
/// run time.
#[inline(always)]
pub(crate) const fn interval(z: f32, nodes: &[f32; MAX_NODES], guesses: &[u8; KEYS], n: usize) -> usize {
    let upper = z > 0.5;
    let d = if upper { 1.0 - z } else { z };
    let low = guesses[key(d)] as usize;
    let guess = if upper { n - 2 - if low > n - 2 { n - 2 } else { low } } else { low };
    settle(z, guess, nodes, n)
}

/// The case (which component is largest: 0, 1, 2, the first of equals
/// after red, as pbrt-v4 chooses) and that component.
#[inline]
pub(crate) const fn case_of(rgb: [f32; 3]) -> (usize, f32) {
    let case = if rgb[0] > rgb[1] {
        if rgb[0] > rgb[2] { 0 } else { 2 }
    } else if rgb[1] > rgb[2] {
        1
    } else {
        2
    };
    (case, rgb[case])
}

/// Where `rgb` (in [0, 1]³, not a grey: `z > 0`) falls in a table with
/// these `nodes`, `n` per axis, given the case and the interval `k`: its
/// first corner's triple, and the fractions `[dx, dy, dz]` along the
/// three axes.
#[inline(always)]
const fn corner(
    nodes: &[f32; MAX_NODES],
    n: usize,
    rgb: [f32; 3],
    case: usize,
    k: usize,
) -> (usize, [f32; 3]) {
    let (z, last) = (rgb[case], (n - 1) as f32);
    // Each ratio first (at most 1): `last / z` overflows for z below 1e-37.
    let (x, y) = (rgb[(case + 1) % 3] / z * last, rgb[(case + 2) % 3] / z * last);
    let (xi, yi) = (index(x, n), index(y, n));
    let (z0, z1) = (nodes[k], nodes[k + 1]);
    (((case * n + k) * n + yi) * n + xi, [x - xi as f32, y - yi as f32, (z - z0) / (z1 - z0)])
}

/// The coefficients of `rgb` in the table `bytes` (as [`corner`]).
#[inline(always)]
pub(crate) const fn interpolate(
    bytes: &[u8],
    nodes: &[f32; MAX_NODES],
    n: usize,
    rgb: [f32; 3],
    case: usize,
    k: usize,
) -> [f32; 3] {
    let (at, [dx, dy, dz]) = corner(nodes, n, rgb, case, k);
    let low = plane(bytes, n, at, dx, dy);
    let high = plane(bytes, n, at + n * n, dx, dy);
    lerp(low, high, dz)
}

/// [`interpolate`] at run time: the same operations in the same order on
/// four lanes at once (each corner's triple and the next table entry's
/// first coefficient, which is dropped), so the same bits, and faster.
#[inline(always)]
pub(crate) fn interpolate_lanes(
    bytes: &[u8],
    nodes: &[f32; MAX_NODES],
    n: usize,
    rgb: [f32; 3],
    case: usize,
    k: usize,
) -> [f32; 3] {
    let (first, [dx, dy, dz]) = corner(nodes, n, rgb, case, k);
    let [dx, dy, dz] = [dx, dy, dz].map(f32x4::splat);
    let (at, row, slice) = (HEADER_LEN + 12 * first, 12 * n, 12 * n * n);
    let load = |at: usize| {
        let b = bytes.get(at..).and_then(<[u8]>::first_chunk::<16>).copied().unwrap_or([0; 16]);
        f32x4::from(std::array::from_fn::<f32, 4, _>(|i| {
            f32::from_le_bytes([b[4 * i], b[4 * i + 1], b[4 * i + 2], b[4 * i + 3]])
        }))
    };
    let lerp = |a: f32x4, b: f32x4, t: f32x4| a + t * (b - a);
    let plane = |at: usize| {
        lerp(lerp(load(at), load(at + 12), dx), lerp(load(at + row), load(at + row + 12), dx), dy)
    };
    let c = lerp(plane(at), plane(at + slice), dz).to_array();
    [c[0], c[1], c[2]]
}

/// `floor(v)`, at most `n − 2`.
const fn index(v: f32, n: usize) -> usize {
    let i = v as usize;
    if i > n - 2 { n - 2 } else { i }
}

/// One plane of four triples from `at` (x, x + 1, and the row above),
/// bilinearly.
#[inline(always)]
const fn plane(bytes: &[u8], n: usize, at: usize, dx: f32, dy: f32) -> [f32; 3] {
    let low = lerp(triple(bytes, at), triple(bytes, at + 1), dx);
    let high = lerp(triple(bytes, at + n), triple(bytes, at + n + 1), dx);
    lerp(low, high, dy)
}

/// `a + t(b − a)`, each component.
#[inline(always)]
const fn lerp(a: [f32; 3], b: [f32; 3], t: f32) -> [f32; 3] {
    [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])]
}

/// The coefficient triple number `i` (zeros past the end, which a checked
/// table never reaches): one bounds check for twelve bytes.
#[inline(always)]
const fn triple(bytes: &[u8], i: usize) -> [f32; 3] {
    let at = HEADER_LEN + 12 * i;
    if at > bytes.len() {
        return [0.0; 3];
    }
    let Some(b) = bytes.split_at(at).1.first_chunk::<12>() else { return [0.0; 3] };
    [
        f32::from_le_bytes([b[0], b[1], b[2], b[3]]),
        f32::from_le_bytes([b[4], b[5], b[6], b[7]]),
        f32::from_le_bytes([b[8], b[9], b[10], b[11]]),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The interval by the guesses is the interval by walking on every
    /// node, the floats next to it on each side, and a sweep of 100,000
    /// values, from 2 nodes to 256.
    #[test]
    fn the_interval_by_guesses_is_the_interval_by_walking() {
        for n in [2, 3, 8, 64, 256] {
            let mut zs: Vec<f32> = (0..100_000).map(|i| (i as f32 + 0.5) / 100_000.0).collect();
            for k in 1..n {
                let z = node(k, n);
                zs.extend([z, f32::from_bits(z.to_bits() - 1), f32::from_bits(z.to_bits() + 1).min(1.0)]);
            }
            let all = nodes(n);
            let table = guesses(&all, n);
            for z in zs {
                let k = interval(z, &all, &table, n);
                assert_eq!(k, interval_walked(z, &all, n), "z = {z:e}, n = {n}");
                assert!(node(k, n) <= z && (z < node(k + 1, n) || k == n - 2), "z = {z:e}: {k}");
            }
        }
    }

    /// The nodes of pbrt-v4's placement, rising from 0 to 1, symmetric.
    #[test]
    fn nodes_rise_from_zero_to_one_symmetrically() {
        let n = 64;
        assert_eq!((node(0, n), node(n - 1, n)), (0.0, 1.0));
        assert!((1..n).all(|k| node(k, n) > node(k - 1, n)));
        assert!((0..n).all(|k| (node(k, n) + node(n - 1 - k, n) - 1.0).abs() < 1e-7));
        let s = |t: f64| t * t * (3.0 - 2.0 * t);
        assert_eq!(node(7, n), s(s(7.0 / 63.0)) as f32);
        assert_eq!(nodes(n)[..n], (0..n).map(|k| node(k, n)).collect::<Vec<_>>()[..]);
    }

    /// Keys rise with the distance, cover 2⁻³⁰ to ½, and each cell holds
    /// at most one node at 256 nodes (the densest table).
    #[test]
    fn keys_cover_the_distances() {
        assert_eq!((key(0.0), key(1e-12), key(0.5)), (0, 0, KEYS - 128));
        assert!(key(2f32.powi(-30)) == 0 && key(2f32.powi(-29)) == 128);
        let all = nodes(256);
        let keys: Vec<usize> = all[1..128].iter().map(|&z| key(z)).collect();
        assert!(keys.windows(2).all(|w| w[0] < w[1]), "two nodes share a key: {keys:?}");
    }
}
