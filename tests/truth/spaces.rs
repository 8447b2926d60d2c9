//! RGB working spaces against their standards: each matrix derived from
//! the primaries and white point reproduces the matrix or the luminance
//! coefficients its standard publishes (to the digits published), and maps
//! each primary and the white to their published chromaticities.

use speclab::Error;
use speclab::color::LinearRgb;
use speclab::color::matrix::{Matrix, inverse};
use speclab::color::space::RgbSpace;

/// `|a − b| ≤ tolerance`, entry by entry.
fn matches(a: &Matrix, b: &Matrix, tolerance: f64) -> bool {
    a.iter().flatten().zip(b.iter().flatten()).all(|(x, y)| (x - y).abs() <= tolerance)
}

/// IEC 61966-2-1:1999, the sRGB matrices as published (four decimals):
/// the RGB → XYZ matrix is the derived one rounded; the published XYZ → RGB
/// matrix is the inverse of that rounded matrix (not of the exact one,
/// from which it differs by up to 3.7e-4), itself rounded.
#[test]
fn srgb_is_iec_61966_2_1() {
    let to_xyz = [[0.4124, 0.3576, 0.1805], [0.2126, 0.7152, 0.0722], [0.0193, 0.1192, 0.9505]];
    let to_rgb = [[3.2406, -1.5372, -0.4986], [-0.9689, 1.8758, 0.0415], [0.0557, -0.2040, 1.0570]];
    let s = RgbSpace::srgb();
    assert!(matches(s.to_xyz_matrix(), &to_xyz, 0.5e-4), "{:?}", s.to_xyz_matrix());
    assert!(matches(&inverse(&to_xyz), &to_rgb, 0.5e-4));
    assert!(matches(s.to_rgb_matrix(), &inverse(s.to_xyz_matrix()), 0.0));
    assert!(!matches(s.to_rgb_matrix(), &to_rgb, 0.5e-4), "derived from the primaries, not typed in");
}

/// ITU-R BT.2020-2, Table 4: Y = 0.2627 R + 0.6780 G + 0.0593 B.
#[test]
fn rec2020_luminance_is_bt2020() {
    let y = RgbSpace::rec2020().to_xyz_matrix()[1];
    for (got, want) in y.iter().zip([0.2627, 0.6780, 0.0593]) {
        assert!((got - want).abs() <= 0.5e-4, "{y:?}");
    }
}

/// SMPTE ST 2065-1:2012 (ACES2065-1, AP0) and ACES S-2014-004 (ACEScg,
/// AP1): the normalised primary matrices as published (ten decimals).
#[test]
fn aces_matrices_are_smpte_st_2065_1_and_s_2014_004() {
    let ap0 = [
        [0.952_552_395_9, 0.0, 0.000_093_678_6],
        [0.343_966_449_8, 0.728_166_096_6, -0.072_132_546_4],
        [0.0, 0.0, 1.008_825_184_4],
    ];
    let ap1 = [
        [0.662_454_181_1, 0.134_004_206_5, 0.156_187_687_0],
        [0.272_228_716_8, 0.674_081_765_8, 0.053_689_517_4],
        [-0.005_574_649_5, 0.004_060_733_5, 1.010_339_100_3],
    ];
    let (a0, a1) = (RgbSpace::aces2065_1().to_xyz_matrix(), RgbSpace::acescg().to_xyz_matrix());
    assert!(matches(a0, &ap0, 0.5e-10), "{a0:?}");
    assert!(matches(a1, &ap1, 0.5e-10), "{a1:?}");
}

/// Every space: each primary at full strength has its published
/// chromaticity, and `(1, 1, 1)` is the white point with Y = 1 (for Display
/// P3, SMPTE EG 432-1's primaries with D65, this is the published truth).
#[test]
fn primaries_and_white_have_their_chromaticities() {
    let xy = |xyz: speclab::Xyz| {
        let sum = xyz.x + xyz.y + xyz.z;
        [xyz.x / sum, xyz.y / sum]
    };
    for space in RgbSpace::all() {
        let unit =
            [LinearRgb::new(1.0, 0.0, 0.0), LinearRgb::new(0.0, 1.0, 0.0), LinearRgb::new(0.0, 0.0, 1.0)];
        for (rgb, want) in unit.into_iter().zip(space.primaries()) {
            let got = xy(space.xyz(rgb));
            assert!((got[0] - want[0]).abs() < 1e-12 && (got[1] - want[1]).abs() < 1e-12, "{}", space.name());
        }
        let white = space.xyz(LinearRgb::splat(1.0));
        let got = xy(white);
        assert!(
            (white.y - 1.0).abs() < 1e-12 && (got[0] - space.white_point()[0]).abs() < 1e-12,
            "{}",
            space.name()
        );
        assert!((got[1] - space.white_point()[1]).abs() < 1e-12, "{}", space.name());
    }
    assert_eq!(RgbSpace::display_p3().primaries(), [[0.680, 0.320], [0.265, 0.690], [0.150, 0.060]]);
}

/// Chromaticities that make no space are an error, not a panic.
#[test]
fn degenerate_primaries_are_errors() {
    let d65 = RgbSpace::srgb().illuminant();
    let good = [[0.64, 0.33], [0.30, 0.60], [0.15, 0.06]];
    assert!(RgbSpace::new("mine", good, [0.3127, 0.3290], d65).is_ok());
    let collinear = [[0.2, 0.2], [0.3, 0.3], [0.4, 0.4]];
    for (p, w) in [(collinear, [0.3127, 0.329]), (good, [0.3, 0.0]), (good, [f64::NAN, 0.3])] {
        let err = RgbSpace::new("bad", p, w, d65).unwrap_err();
        assert!(matches!(err, Error::Primaries), "{err}");
    }
}
