//! Thread safety where there is shared state: a light computes its exact
//! reference weights on first use and keeps them (a `OnceLock`). Many
//! threads meeting a fresh light at once all get the exact colours, and
//! the grid computed from several threads at once, over shared lights,
//! equals the grid computed on one.
#![cfg(feature = "study")]

use speclab::data::{Light, Patch};
use speclab::sampling::reference;
use speclab::study::evaluate::scene::{builtin_lights, builtin_surfaces};
use speclab::study::experiments::grid::{GridOptions, GridRow};
use speclab::{TabulatedSpectrum, Xyz};
use static_assertions::assert_impl_all;

assert_impl_all!(TabulatedSpectrum: Send, Sync);
assert_impl_all!(GridRow<'static>: Send, Sync);

/// Rounding only: the weights' dot product and integration piece by piece
/// sum the same exact integrals in different orders.
const ROUNDING: f64 = 1e-12;

#[test]
fn a_fresh_light_shared_by_threads_gives_exact_colours() {
    for light in Light::APPENDIX {
        // Scaled copies start with no weights; every thread races to make them.
        let fresh = light.spectrum().scaled(1.5).expect("finite");
        let exact: Vec<Xyz> =
            Patch::ALL.iter().map(|p| reference::xyz_of_product(&[&fresh, p.spectrum()])).collect();
        std::thread::scope(|scope| {
            let handles: Vec<_> = (0..4)
                .map(|_| scope.spawn(|| Patch::ALL.map(|p| reference::xyz(&fresh, p.spectrum()))))
                .collect();
            for handle in handles {
                for (got, want) in handle.join().expect("no panic").iter().zip(&exact) {
                    let gap = (*got - *want).to_array().iter().fold(0.0f64, |m, d| m.max(d.abs()));
                    assert!(gap <= ROUNDING * want.y, "{light}: {got:?} vs {want:?}");
                }
            }
        });
    }
}

#[test]
fn grid_from_many_threads_matches_one() {
    let grid = GridOptions { seed: 7, ..GridOptions::default() };
    let (lights, surfaces) = (builtin_lights(), builtin_surfaces());
    let fresh = builtin_lights();
    let serial = grid.rows(&fresh, &surfaces).expect("grid");
    std::thread::scope(|scope| {
        // The same lights (and their kept weights) for every thread.
        let handles: Vec<_> =
            (0..4).map(|_| scope.spawn(|| grid.rows(&lights, &surfaces).expect("grid"))).collect();
        for handle in handles {
            let rows = handle.join().expect("no panic");
            let xyz = |rows: &[GridRow]| rows.iter().map(|r| r.xyz).collect::<Vec<_>>();
            assert_eq!(xyz(&rows), xyz(&serial));
        }
    });
}
