//! The display pipeline allocates nothing per pixel: a counting global
//! allocator records allocations made by this thread while a block runs
//! (as the core's `tests/api/alloc.rs` does for the per-sample path).

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::hint::black_box;

use speclab::data;

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

/// The display pipeline, per pixel: exposure, both gamut maps, encoding,
/// 8 bits.
#[test]
fn display_pipeline_does_not_allocate() {
    use speclab_study::display::{Exposure, GamutMap, PixelPipeline};
    let white = speclab::sampling::reference::white(&data::lights::F11);
    let colours = [white, speclab::sampling::reference::xyz(&data::lights::F11, &data::patches::G4)]
        .map(|x| x.to_linear_srgb());
    let count = allocations(|| {
        for gamut in GamutMap::ALL {
            for exposure in [Exposure::for_white(white), Exposure::fit_white(white), Exposure::new(1e-3)] {
                for rgb in colours {
                    black_box(PixelPipeline::new(exposure, gamut).pixel(black_box(rgb)));
                }
            }
        }
    });
    assert_eq!(count, 0, "allocated {count} times");
}
