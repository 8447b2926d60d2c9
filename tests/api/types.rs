//! What the per-sample types are: K wavelengths with their nearest whole
//! nanometres and a row of four weights each, K values, nothing more, in
//! either precision; `Copy`, `Send` and `Sync`. Checked when this file
//! compiles (`static_assertions`); there is nothing left to check at run
//! time.

use speclab::{
    BoxAverage, Center, HeroSample, LinearRgb, RegularSpectrum, SampledSpectrum, TabulatedSpectrum, Xyz,
};
use static_assertions::{assert_eq_size, assert_impl_all};

// λ, then the nearest whole nanometres (u16, padded), then [w_X, w_Y, w_Z, w₀].
assert_eq_size!(HeroSample<1>, [f64; 1 + 1 + 4]);
assert_eq_size!(HeroSample<4>, [f64; 4 + 1 + 16]);
assert_eq_size!(HeroSample<8>, [f64; 8 + 2 + 32]);
assert_eq_size!(HeroSample<4, f32>, [f32; 4 + 2 + 16]);
assert_eq_size!(SampledSpectrum<1>, f64);
assert_eq_size!(SampledSpectrum<4>, [f64; 4]);
assert_eq_size!(SampledSpectrum<4, f32>, [f32; 4]);
assert_eq_size!(RegularSpectrum<16, Center>, [f64; 16]);
assert_eq_size!(RegularSpectrum<16, Center, f32>, [f32; 16]);
assert_eq_size!(RegularSpectrum<45, BoxAverage>, [f64; 45]);
assert_eq_size!(Xyz, [f64; 3]);

assert_impl_all!(HeroSample<4>: Copy, Send, Sync);
assert_impl_all!(HeroSample<1>: Copy, Send, Sync);
assert_impl_all!(HeroSample<4, f32>: Copy, Send, Sync);
assert_impl_all!(SampledSpectrum<4, f32>: Copy, Send, Sync, Default);
assert_impl_all!(SampledSpectrum<4>: Copy, Send, Sync, Default);
assert_impl_all!(RegularSpectrum<16>: Copy, Send, Sync);
assert_impl_all!(RegularSpectrum<16, BoxAverage>: Copy, Send, Sync);
assert_impl_all!(Xyz: Copy, Send, Sync, Default, std::iter::Sum);
assert_impl_all!(LinearRgb: Copy, Send, Sync);
assert_impl_all!(TabulatedSpectrum: Send, Sync);
assert_impl_all!(speclab::Error: Send, Sync, std::error::Error);
