//! A renderer's own material list, held the ways the docs recommend:
//! dense tables behind `Box<dyn Spectrum>` (mixed with other kinds), an
//! enum of the renderer's own, a slice of one kind. Each reaches the dense
//! table's lookup at the sample's nearest nanometres: the values are the
//! concrete table's, bit for bit, in `f32` and `f64`.

use speclab::color::RgbAlbedo;
use speclab::data::{lights, patches};
use speclab::spectrum::{DenseSpectrum, Float, Wavelengths};
use speclab::{HeroSample, LinearRgb, SampledSpectrum, Spectrum};

/// A renderer's own enum of materials.
enum Material {
    Table(DenseSpectrum),
    Rgb(RgbAlbedo),
}

impl Spectrum for Material {
    fn eval(&self, lambda: f64) -> f64 {
        match self {
            Material::Table(s) => s.eval(lambda),
            Material::Rgb(s) => s.eval(lambda),
        }
    }

    fn sample<const K: usize, T: Float>(&self, at: &impl Wavelengths<K, T>) -> SampledSpectrum<K, T> {
        match self {
            Material::Table(s) => s.sample(at),
            Material::Rgb(s) => s.sample(at),
        }
    }
}

fn check<T: Float>() {
    let tables = [&patches::G4, &patches::A1, &lights::F11].map(DenseSpectrum::new);
    let rgb = RgbAlbedo::new(LinearRgb::new(0.2, 0.5, 0.1)).expect("in gamut");
    let boxed: Vec<Box<dyn Spectrum + Send + Sync>> =
        vec![Box::new(tables[0].clone()), Box::new(tables[1].clone()), Box::new(rgb)];
    let own = [Material::Table(tables[0].clone()), Material::Table(tables[1].clone()), Material::Rgb(rgb)];
    for i in 0..500 {
        // 500 evenly spread samples (`samples_beside_the_halves` targets the
        // half nanometres, where rounding could differ).
        let h = HeroSample::<4, T>::new(T::from_f64((f64::from(i) + 0.5) / 500.0));
        for (t, table) in tables[..2].iter().enumerate() {
            let direct = table.sample(&h);
            assert_eq!(boxed[t].sample(&h), direct, "boxed, table {t}, {h:?}");
            let by_ref: &dyn Spectrum = &*boxed[t];
            assert_eq!(h.sample(&by_ref), direct, "&dyn, table {t}");
            // The enum forwards to the table's own `sample`: equal by
            // construction; the line keeps the documented form compiling.
            assert_eq!(own[t].sample(&h), direct, "enum, table {t}");
        }
        assert_eq!(boxed[2].sample(&h), rgb.sample(&h), "boxed RGB");
        // and both are the albedo's values (not only equal to each other):
        // in f32, computed in f32 (the polynomial's rounding, about
        // ε·Σ|cᵢ|, carried into the sigmoid, whose relative slope is at
        // most 1); in f64, the f64 value.
        let c = rgb.polynomial().coefficients();
        let epsilon = if size_of::<T>() == 4 { f64::from(f32::EPSILON) } else { f64::EPSILON };
        let bound = epsilon * 4.0 * (1.0 + c.iter().map(|v| v.abs()).sum::<f64>());
        for (v, l) in boxed[2].sample(&h).values.into_iter().zip(h.lambda()) {
            let eval = rgb.eval(l.to_f64());
            assert!(
                (v.to_f64() - eval).abs() <= bound * eval.max(1e-3),
                "RGB at {l:?}: {v:?} against {eval}"
            );
        }
        assert_eq!(own[2].sample(&h), rgb.sample(&h), "enum RGB");
        // Scaled (a light at another intensity) keeps it too.
        let scaled: Box<dyn Spectrum> = Box::new(&tables[2] * 4.0);
        assert_eq!(scaled.sample(&h), tables[2].sample(&h) * T::from_f64(4.0));
    }
}

/// `f32` samples whose wavelengths, rounded to `f32`, fall on the other
/// side of a half nanometre than the sample's own (fixed-point) nearest
/// nanometres: there a lookup that found them again from the wavelength
/// would read the neighbouring entry.
fn samples_beside_the_halves() -> Vec<HeroSample<4, f32>> {
    (0..2_000_000_u32)
        .map(|i| HeroSample::<4, f32>::new(i as f32 / 2_000_000.0))
        .filter(|h| Wavelengths::nearest_nm(h) != Wavelengths::nearest_nm(h.lambda()))
        .take(50)
        .collect()
}

#[test]
fn the_lookup_uses_the_samples_own_nearest_nanometres() {
    let table = DenseSpectrum::new(&patches::G4);
    let boxed: Box<dyn Spectrum> = Box::new(table.clone());
    let beside = samples_beside_the_halves();
    assert!(!beside.is_empty(), "no sample beside a half nanometre");
    for h in &beside {
        assert_eq!(boxed.sample(h), table.sample(h), "{h:?}");
    }
}

#[test]
fn dense_tables_keep_their_lookup_behind_any_holder() {
    check::<f32>();
    check::<f64>();
}
