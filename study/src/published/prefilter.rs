//! Spectral prefiltering (Ward and Eydelberg-Vileshin, "Picture perfect
//! RGB rendering using spectral prefiltering and sharp color primaries",
//! EGWR 2002): three numbers per surface, computed once under the scene's
//! light, then rendered as RGB.
//!
//! In a space with matrix `A` (XYZ → the space), the light's colour is
//! `l = A·XYZ(L)` and a surface's prefiltered colour `s = A·XYZ(L·ρ) ⊘ l`
//! (exact integrals, channel by channel). A path of depth d renders
//! `A⁻¹·(l ⊙ s₁ ⊙ … ⊙ s_d)`: exact at depth 1 by construction, an
//! approximation from the second bounce on. The three spaces of the
//! paper's comparison: XYZ itself, linear sRGB (Appendix 1 part D) and a
//! sharpened RGB (the Bradford cone matrix of Lam 1985, sharper than
//! sRGB; the paper's own "sharp" primaries are of the same kind).
//!
//! ```
//! use speclab::data::{lights, patches};
//! use speclab::sampling::reference;
//! use speclab_study::published::prefilter::{Prefiltered, Space};
//! let p = Prefiltered::new(Space::Sharp, reference::white(&lights::F11))?;
//! let s = p.surface(reference::xyz(&lights::F11, &patches::G4));
//! let once = p.xyz(&[s]);
//! let exact = reference::xyz(&lights::F11, &patches::G4);
//! assert!((once.y - exact.y).abs() < 1e-9 * exact.y); // exact at depth 1
//! # Ok::<(), speclab::Error>(())
//! ```

use std::fmt;

use speclab::color::Xyz;
use speclab::color::adaptation::Cat;
use speclab::color::matrix::{Matrix, inverse, mul};
use speclab::color::srgb::XYZ_TO_SRGB;
use speclab::error::Error;

/// The space the three numbers are kept in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Space {
    /// XYZ itself.
    Xyz,
    /// Linear sRGB (Appendix 1 part D).
    Srgb,
    /// A sharpened RGB: the Bradford cone matrix.
    Sharp,
}

impl Space {
    /// Every space.
    pub const ALL: [Space; 3] = [Space::Xyz, Space::Srgb, Space::Sharp];

    /// The names, in [`Space::ALL`]'s order.
    pub const NAMES: [&str; 3] = ["xyz", "srgb", "sharp"];

    /// XYZ → the space.
    #[must_use]
    pub fn matrix(self) -> Matrix {
        match self {
            Space::Xyz => [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            Space::Srgb => XYZ_TO_SRGB,
            Space::Sharp => Cat::Bradford.cones(),
        }
    }
}

impl fmt::Display for Space {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let i = Space::ALL.iter().position(|s| s == self).unwrap_or(0);
        f.write_str(Space::NAMES[i])
    }
}

/// A light's prefiltering in one space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Prefiltered {
    to_space: Matrix,
    from_space: Matrix,
    light: [f64; 3],
}

impl Prefiltered {
    /// Prefiltering in `space` for the light whose exact XYZ (its perfect
    /// white) is `white`. An [`Error::NoMass`] if a channel of the light's
    /// colour is not finite and non-zero (nothing to divide by).
    pub fn new(space: Space, white: Xyz) -> Result<Prefiltered, Error> {
        let to_space = space.matrix();
        let light = mul(&to_space, white.to_array());
        if light.iter().any(|l| !(l.is_finite() && *l != 0.0)) {
            return Err(Error::NoMass);
        }
        Ok(Prefiltered { to_space, from_space: inverse(&to_space), light })
    }

    /// The light's colour in the space.
    #[must_use]
    pub fn light(&self) -> [f64; 3] {
        self.light
    }

    /// A surface's three numbers, from the exact XYZ of light × surface.
    #[must_use]
    pub fn surface(&self, xyz: Xyz) -> [f64; 3] {
        let c = self.in_space(xyz);
        [0, 1, 2].map(|i| c[i] / self.light[i])
    }

    /// `xyz` in the space: `A·xyz`.
    #[must_use]
    pub fn in_space(&self, xyz: Xyz) -> [f64; 3] {
        mul(&self.to_space, xyz.to_array())
    }

    /// A colour in the space back in XYZ: `A⁻¹·c`.
    #[must_use]
    pub fn to_xyz(&self, c: [f64; 3]) -> Xyz {
        Xyz::from(mul(&self.from_space, c))
    }

    /// The XYZ of a path that meets the same surface `depth` times, from
    /// the exact XYZ of the light × that surface: `A⁻¹·(l ⊙ s^depth)`.
    #[must_use]
    pub fn path_xyz(&self, once: Xyz, depth: usize) -> Xyz {
        let s = self.surface(once);
        self.to_xyz((0..depth).fold(self.light, |acc, _| [0, 1, 2].map(|i| acc[i] * s[i])))
    }

    /// The XYZ of a path through `surfaces` (their three numbers, in
    /// order): `A⁻¹·(l ⊙ s₁ ⊙ …)`.
    #[must_use]
    pub fn xyz(&self, surfaces: &[[f64; 3]]) -> Xyz {
        self.to_xyz(surfaces.iter().fold(self.light, |acc, s| [0, 1, 2].map(|i| acc[i] * s[i])))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use speclab::data::{lights, patches};
    use speclab::sampling::reference;

    #[test]
    fn a_path_through_two_surfaces_multiplies_their_numbers() {
        // In XYZ a surface's numbers are XYZ(L·ρ) ⊘ XYZ(L): a path through
        // two gives XYZ(L·ρ₁) ⊙ XYZ(L·ρ₂) ⊘ XYZ(L).
        let white = reference::white(&lights::F11);
        let p = Prefiltered::new(Space::Xyz, white).unwrap();
        let (one, two) =
            (reference::xyz(&lights::F11, &patches::G4), reference::xyz(&lights::F11, &patches::J4));
        let ours = p.xyz(&[p.surface(one), p.surface(two)]).to_array();
        let hand = [0, 1, 2].map(|c| one.to_array()[c] * two.to_array()[c] / white.to_array()[c]);
        for (o, h) in ours.into_iter().zip(hand) {
            assert!((o - h).abs() <= 1e-12 * h.abs(), "{o} against {h}");
        }
        let once = p.path_xyz(one, 1);
        assert!((once.y - one.y).abs() <= 1e-12 * one.y && (once.z - one.z).abs() <= 1e-12 * one.z);
    }
}
