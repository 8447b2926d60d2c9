//! Thread safety where there is shared state: a light's `Named` prepares
//! its pdfs and fitted rules on first use and keeps them (`OnceLock`s),
//! shared by its clones. Many threads meeting a fresh light at once all
//! get the same values, kept once, and the grid computed from several
//! threads at once, over shared lights, equals the grid computed on one.

use speclab::TabulatedSpectrum;
use speclab::data::Light;
use speclab_study::evaluate::Named;
use speclab_study::evaluate::scene::{builtin_lights, builtin_surfaces};
use speclab_study::experiments::grid::{GridOptions, GridRow};
use speclab_study::sampling::choice::{ChosenPdf, PdfKind};
use static_assertions::assert_impl_all;

assert_impl_all!(TabulatedSpectrum: Send, Sync);
assert_impl_all!(Named: Send, Sync);
assert_impl_all!(GridRow<'static>: Send, Sync);

#[test]
fn a_fresh_light_shared_by_threads_prepares_once() {
    for light in Light::APPENDIX {
        let fresh = Named::from(light);
        let clone = fresh.clone(); // shares what is prepared
        let tables: Vec<ChosenPdf> = std::thread::scope(|scope| {
            let handles: Vec<_> =
                (0..4).map(|_| scope.spawn(|| fresh.pdf(PdfKind::Light).expect("bright"))).collect();
            handles.into_iter().map(|h| h.join().expect("no panic")).collect()
        });
        let kept = clone.pdf(PdfKind::Light).expect("bright");
        for table in &tables {
            let (ChosenPdf::Table(a), ChosenPdf::Table(b)) = (table, &kept) else { panic!("a table") };
            assert!(std::sync::Arc::ptr_eq(a, b), "{light}: one table, kept once");
        }
        let other = clone.pdf(PdfKind::Balanced).expect("bright");
        assert_ne!(other, kept, "one table per kind");
        let rules = fresh.rules().expect("bright");
        assert!(std::ptr::eq(rules.rule(8).expect("M"), clone.rules().expect("kept").rule(8).expect("M")));
        // A new Named of the same light starts afresh.
        let afresh = Named::from(light).rules().expect("bright");
        assert!(!std::ptr::eq(rules.rule(8).expect("M"), afresh.rule(8).expect("M")));
        assert_eq!(rules.rule(8).expect("M"), afresh.rule(8).expect("M"), "and fits the same rule");
    }
}

#[test]
fn grid_from_many_threads_matches_one() {
    let grid = GridOptions { seed: 7, ..GridOptions::default() };
    let (lights, surfaces) = (builtin_lights(), builtin_surfaces());
    let fresh = builtin_lights();
    let serial = grid.rows(&fresh, &surfaces).expect("grid");
    std::thread::scope(|scope| {
        // The same lights (and what they prepared) for every thread.
        let handles: Vec<_> =
            (0..4).map(|_| scope.spawn(|| grid.rows(&lights, &surfaces).expect("grid"))).collect();
        for handle in handles {
            let rows = handle.join().expect("no panic");
            let xyz = |rows: &[GridRow]| rows.iter().map(|r| r.xyz).collect::<Vec<_>>();
            assert_eq!(xyz(&rows), xyz(&serial));
        }
    });
}
