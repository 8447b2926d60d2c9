//! Determinism and thread safety: the same seed gives bit-identical results,
//! and the grid computed from several threads at once equals the grid
//! computed on one.
#![cfg(feature = "study")]

use std::num::NonZeroUsize;

use rand::SeedableRng;
use rand::rngs::StdRng;
use speclab::data;
use speclab::sampling::hero;
use speclab::study::grid::Grid;
use speclab::study::scene::{builtin_lights, builtin_surfaces};
use static_assertions::assert_impl_all;

assert_impl_all!(speclab::TabulatedSpectrum: Send, Sync);
assert_impl_all!(speclab::study::grid::Row<'static>: Send, Sync);

#[test]
fn same_seed_same_bits() {
    let n = NonZeroUsize::new(1000).expect("non-zero");
    let run = |seed| hero::estimate::<4, _>(&data::F11, &data::H4, n, &mut StdRng::seed_from_u64(seed));
    let (a, b) = (run(42), run(42));
    assert_eq!(a.to_array().map(f64::to_bits), b.to_array().map(f64::to_bits));
    assert_ne!(a, run(43));
}

#[test]
fn grid_from_many_threads_matches_one() {
    let grid = Grid { seed: 7, ..Grid::default() };
    let (lights, surfaces) = (builtin_lights(), builtin_surfaces());
    let serial = grid.rows(&lights, &surfaces).expect("grid");
    std::thread::scope(|scope| {
        let handles: Vec<_> =
            (0..4).map(|_| scope.spawn(|| grid.rows(&lights, &surfaces).expect("grid"))).collect();
        for handle in handles {
            let rows = handle.join().expect("no panic");
            assert_eq!(rows, serial);
        }
    });
}
