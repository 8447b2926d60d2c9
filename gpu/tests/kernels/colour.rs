//! The observer's weights, the XYZ sum and XYZ → RGB.

use speclab::color::{RgbSpace, Xyz};
use speclab::sampling::Domain;
use speclab::spectrum::DenseSpectrum;

use crate::common::{Rng, map, unit_inputs, worst};

#[test]
fn weights_and_xyz_are_the_cpus() {
    let u = unit_inputs(20_000);
    let input: Vec<[u32; 1]> = u.iter().map(|v| [v.to_bits()]).collect();
    let body = "    let h = speclab_hero_uniform(inf(0u), 0u, 470u);
    let w = speclab_weights(h);
    let xyz = speclab_xyz(w, speclab_dense(0u, h.nearest));
    for (var j = 0u; j < 4u; j++) { outf(j, w[j].y); }
    outf(4u, xyz.x); outf(5u, xyz.y); outf(6u, xyz.z);";
    let gpu = map::<1, 7>(body, &input);
    let d65 = DenseSpectrum::new(RgbSpace::srgb().illuminant());
    let (mut weights, mut sums) = (vec![], vec![]);
    for (&u, g) in u.iter().zip(&gpu) {
        let h = Domain::UNIFORM_VISIBLE.hero::<4, f32>(u);
        let y = h.y_weights().values;
        weights.extend((0..4).map(|j| (f32::from_bits(g[j]), y[j])));
        let Xyz { x, y, z } = h.to_xyz(d65.sample(&h));
        sums.extend([(g[4], x), (g[5], y), (g[6], z)].map(|(g, c)| (f32::from_bits(g), c as f32)));
    }
    let (w, s) = (worst(weights), worst(sums));
    eprintln!("weights: {} ULP; XYZ sums: {} ULP ({} vs {})", w.0, s.0, s.1, s.2);
    assert_eq!(w.0, 0, "{w:?}");
    assert!(s.0 <= 4, "{s:?}");
}

#[test]
fn xyz_to_rgb_is_within_four_ulp_of_its_terms_in_each_space() {
    let mut rng = Rng(5);
    let xyz: Vec<[f32; 3]> = (0..10_000).map(|_| [0, 1, 2].map(|_| rng.next() * 1.2)).collect();
    let input: Vec<[u32; 3]> = xyz.iter().map(|v| v.map(f32::to_bits)).collect();
    for space in RgbSpace::all() {
        let name = speclab_gpu::shader::wgsl_name(space.name());
        let body = format!(
            "    let rgb = SPECLAB_XYZ_TO_{name} * vec3<f32>(inf(0u), inf(1u), inf(2u));
    outf(0u, rgb.x); outf(1u, rgb.y); outf(2u, rgb.z);"
        );
        let gpu = map::<3, 3>(&body, &input);
        let m = space.to_rgb_matrix().map(|row| row.map(|v| v as f32));
        let pairs = xyz.iter().zip(&gpu).flat_map(|(v, g)| {
            // The f32 product, summed as a renderer's CPU code would.
            (0..3).map(move |i| (f32::from_bits(g[i]), m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2]))
        });
        let (w, a, b) = worst(pairs.collect::<Vec<_>>());
        eprintln!("XYZ → {}: {w} ULP ({a} vs {b})", space.name());
        // Three products summed: a different order or a fused step moves the
        // result by an ulp of the largest term, many ulps of a small result.
        let relative = (a - b).abs() / (m[0][0].abs() * 1.2 * 3.0);
        assert!(relative <= 4.0 * f32::EPSILON, "{w} ULP, {relative:e} of the terms: {a} vs {b}");
    }
}
