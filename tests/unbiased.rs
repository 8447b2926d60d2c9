//! Statistics: random and hero estimates are unbiased.
//!
//! For every cell, `TRIALS` independent estimates (each of `N` samples, each
//! with its own seed) are averaged; the mean must lie within `Z_MAX`
//! standard errors of the exact reference in X, Y and Z, with the standard
//! error derived from the spread of the estimates. With 18 cells × 2 methods
//! × 3 channels = 108 checks, a correct estimator fails one at 4.5σ with
//! probability below 1e-3; the seeds are fixed, so the run is repeatable.
#![cfg(feature = "study")]

use std::num::NonZeroUsize;

use speclab::data::{Light, Patch};
use speclab::sampling::reference;
use speclab::study::method::{Method, derive_seed};

const TRIALS: usize = 2000;
const N: usize = 8;
const Z_MAX: f64 = 4.5;

#[test]
fn random_and_hero_are_unbiased() {
    let n = NonZeroUsize::new(N).expect("N > 0");
    let mut worst = 0.0f64;
    for light in Light::ALL {
        for patch in Patch::ALL {
            let exact = reference::xyz(light.spectrum(), patch.spectrum()).to_array();
            for method in [Method::RANDOM, Method::HERO] {
                let estimates: Vec<[f64; 3]> = (0..TRIALS as u64)
                    .map(|t| {
                        let seed = derive_seed(0xB1A5, t);
                        let xyz = method.xyz(light.spectrum(), patch.spectrum(), n, seed).expect("xyz");
                        xyz.to_array()
                    })
                    .collect();
                for c in 0..3 {
                    let (mean, sd) = mean_sd(estimates.iter().map(|e| e[c]));
                    let se = sd / (TRIALS as f64).sqrt();
                    let z = (mean - exact[c]) / se;
                    worst = worst.max(z.abs());
                    assert!(z.abs() < Z_MAX, "{light:?} {patch:?} {method:?} channel {c}: z = {z:.2}");
                }
            }
        }
    }
    eprintln!("largest |z| over 108 checks: {worst:.2}");
}

/// Mean and sample standard deviation.
fn mean_sd(xs: impl Iterator<Item = f64> + Clone) -> (f64, f64) {
    let n = xs.clone().count() as f64;
    let mean = xs.clone().sum::<f64>() / n;
    let var = xs.map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, var.sqrt())
}

/// Every pdf × strata, for K = 1 and K = 4: the mean of `TRIALS` estimates
/// of `N` samples lies within `Z_MAX` standard errors of the reference on
/// every channel of every cell (1,296 checks; at 4.5σ a correct estimator
/// fails one with probability about 1 %, and the seeds are fixed).
#[test]
fn every_pdf_and_strata_is_unbiased() {
    use speclab::study::sampling::Sampling;
    let n = NonZeroUsize::new(N).expect("N > 0");
    let mut worst = (0.0f64, String::new());
    for sampling in Sampling::all() {
        for method in [Method::RANDOM, Method::HERO].map(|m| m.with_sampling(sampling)) {
            for (c, (light, patch)) in Light::ALL.iter().flat_map(|l| Patch::ALL.map(|p| (*l, p))).enumerate()
            {
                let (l, s) = (light.spectrum(), patch.spectrum());
                let prepared = method.prepare(l).expect("bright lights");
                let exact = reference::xyz(l, s).to_array();
                let estimates: Vec<[f64; 3]> = (0..TRIALS as u64)
                    .map(|t| prepared.xyz(s, n, derive_seed(0x5A_3D + c as u64, t)).expect("xyz").to_array())
                    .collect();
                for ch in 0..3 {
                    let (mean, sd) = mean_sd(estimates.iter().map(|e| e[ch]));
                    let z = (mean - exact[ch]) / (sd / (TRIALS as f64).sqrt());
                    if z.abs() > worst.0 {
                        worst =
                            (z.abs(), format!("{} {sampling} {light:?} {patch:?} ch {ch}", method.name()));
                    }
                    assert!(
                        z.abs() < Z_MAX,
                        "{} {sampling} {light:?} {patch:?} channel {ch}: z = {z:.2}",
                        method.name()
                    );
                }
            }
        }
    }
    eprintln!("largest |z| over 1,296 checks: {:.2} ({})", worst.0, worst.1);
}
