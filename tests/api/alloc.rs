//! Nothing on the per-sample path allocates. A counting global allocator
//! records allocations made by this thread while a block runs; every
//! per-sample operation a renderer calls runs inside such a block.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::hint::black_box;

use speclab::{BoxAverage, HeroSample, RegularSpectrum, Role, SampledSpectrum, TabulatedSpectrum, data};

struct Counting;

thread_local! {
    static ARMED: Cell<bool> = const { Cell::new(false) };
    static COUNT: Cell<usize> = const { Cell::new(0) };
}

// SAFETY: forwards to the system allocator; only counts.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if ARMED.with(Cell::get) {
            COUNT.with(|c| c.set(c.get() + 1));
        }
        // SAFETY: the caller upholds `alloc`'s contract.
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: the caller upholds `dealloc`'s contract.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Allocations made by `f` on this thread.
fn allocations(f: impl FnOnce()) -> usize {
    COUNT.with(|c| c.set(0));
    ARMED.with(|a| a.set(true));
    f();
    ARMED.with(|a| a.set(false));
    COUNT.with(Cell::get)
}

#[test]
fn the_counter_sees_allocations() {
    assert!(allocations(|| drop(black_box(vec![1u8; 16]))) >= 1);
}

#[test]
fn per_sample_path_does_not_allocate() {
    // A loaded, non-uniform spectrum takes the slower segment search.
    let uneven =
        TabulatedSpectrum::new(vec![380.0, 400.0, 550.0, 730.0], vec![0.2, 0.4, 0.9, 0.1], Role::Reflectance)
            .expect("valid");
    let (lb, sb) = (
        RegularSpectrum::<16, BoxAverage>::box_average(&data::lights::F11),
        RegularSpectrum::box_average(&uneven),
    );
    let count = allocations(|| {
        let mut pixel = speclab::Xyz::ZERO;
        for i in 0..1000 {
            let mut h = HeroSample::<4>::new(black_box(f64::from(i) * 0.618));
            let (le, albedo) = (data::lights::F11.sample(&h), uneven.sample(&h));
            let mut beta = SampledSpectrum::splat(1.0);
            let mut l = SampledSpectrum::zero();
            beta *= albedo;
            l += beta * le;
            l = l.safe_div(SampledSpectrum::new(h.pdf())) * h.pdf()[0] - l * 0.0 + 0.0;
            let _ = black_box((l.average(), l.max_value(), l.is_black(), l[2], h.y(l)));
            pixel += h.to_xyz(l);
            h.terminate_secondary();
            pixel += h.to_xyz(le);
            let own = HeroSample::from_wavelengths_with(
                *h.lambda(),
                [0.01; 4],
                &speclab::spectrum::DenseObserver::ASSIGNMENT,
            )
            .expect("valid");
            pixel += own.to_xyz(data::lights::A.sample(&own));
            pixel += (lb * sb).to_xyz();
        }
        black_box(pixel);
    });
    assert_eq!(count, 0, "the per-sample path allocated {count} times");
}

/// Drawing wavelengths from any of the library's pdfs allocates nothing
/// (the built-in lights' pdfs are static tables).
#[test]
fn pdfs_do_not_allocate() {
    use rand::{RngExt, SeedableRng};
    use speclab::sampling::pdf::{LightPdf, Visible};
    let (light, balanced) = (
        LightPdf::light(&data::lights::F11).expect("bright"),
        LightPdf::balanced(&data::lights::A).expect("bright"),
    );
    let binned = speclab::sampling::binned::BinnedPdf::new(&light, 256).expect("bins");
    let mut rng = rand::rngs::StdRng::seed_from_u64(5);
    let count = allocations(|| {
        let mut pixel = speclab::Xyz::ZERO;
        for _ in 0..192 {
            let u = rng.random::<f64>();
            let h = HeroSample::<4>::from_pdf_with(u, &light, &speclab::spectrum::DenseObserver::ASSIGNMENT)
                .unwrap();
            pixel += h.to_xyz(data::lights::F11.sample(&h) * data::patches::G4.sample(&h));
            let h = HeroSample::<4>::from_pdf_with(
                u,
                &Visible::ASSIGNMENT,
                &speclab::spectrum::DenseObserver::ASSIGNMENT,
            )
            .unwrap();
            pixel += h.to_xyz(data::lights::A.sample(&h));
            pixel +=
                HeroSample::<1>::from_pdf_with(u, &balanced, &speclab::spectrum::DenseObserver::ASSIGNMENT)
                    .unwrap()
                    .to_xyz(SampledSpectrum::splat(1.0));
            pixel +=
                HeroSample::<4>::from_pdf_with(u, &binned, &speclab::spectrum::DenseObserver::ASSIGNMENT)
                    .unwrap()
                    .to_xyz(SampledSpectrum::splat(1.0));
        }
        black_box(pixel);
    });
    assert_eq!(count, 0, "allocated {count} times");
}

/// Bucketing a spectrum, the fast exact reference (a prepared light's dot
/// product) and the batch allocate nothing either (the batch's scratch
/// buffer is only for cubics that overshoot [0, 1], which these patches'
/// do not). `reference::xyz` itself, integration piece by piece, gathers
/// its pieces in a buffer: it is not a per-sample call.
#[test]
fn bucketing_reference_and_batch_do_not_allocate() {
    let prepared = speclab::sampling::PreparedLight::for_grid(
        &data::lights::D65,
        data::patches::G4.lambda(),
        data::patches::G4.interpolation(),
    )
    .expect("valid grid");
    let samples: Vec<f64> =
        speclab::data::Patch::ALL.iter().flat_map(|p| p.spectrum().values().to_vec()).collect();
    let mut out = [speclab::Xyz::ZERO; 6];
    let count = allocations(|| {
        black_box(RegularSpectrum::<16, speclab::Center>::center(&data::lights::F11));
        black_box(RegularSpectrum::<16, BoxAverage>::box_average(&data::lights::F11));
        black_box(prepared.xyz(&data::patches::G4));
        prepared.batch(&samples, &mut out).expect("valid");
    });
    assert_eq!(count, 0, "allocated {count} times");
}
