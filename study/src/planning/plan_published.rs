//! The planner's judgement of the published rules and of prefiltering
//! ([`crate::published`]): each built for the scene's one light.

use crate::StudyError;
use crate::evaluate::perceptual;
use crate::published::prefilter::{Prefiltered, Space};
use crate::published::rules::Family;
use speclab::sampling::rule::MAX_M;

use super::Scene;

impl Scene<'_> {
    /// For M = 1 … 64, the worst ΔE00 of the published rule of `family`
    /// for the scene's light, and where; NaN where the rule does not exist
    /// (below the family's smallest M, or a Borges rule without real nodes).
    pub(super) fn published_errors(&self, family: Family) -> Vec<(f64, String)> {
        (1..=MAX_M)
            .map(|m| {
                let mut worst = (f64::NEG_INFINITY, String::new());
                // One light (per-light methods are candidates for no other scene).
                let light = self.cells[0].0;
                let Ok(rule) = light.published(family, m) else {
                    return (f64::NAN, format!("no {family} rule of {m} for {}", light.name));
                };
                for (l, s, exact, white) in &self.cells {
                    let path = self.depth.path(&s.spectrum);
                    let de = perceptual::delta_e00(rule.xyz_of_product(path.factors()), *exact, *white);
                    if de > worst.0 {
                        worst = (de, format!("{} × {}", l.name, s.name));
                    }
                }
                worst
            })
            .collect()
    }

    /// The worst ΔE00 of prefiltering in `space`, and where.
    pub(super) fn prefiltered_error(&self, space: Space) -> Result<(f64, String), StudyError> {
        let mut worst = (f64::NEG_INFINITY, String::new());
        for (l, s, exact, white) in &self.cells {
            let p = Prefiltered::new(space, *white)?;
            let de =
                perceptual::delta_e00(p.path_xyz(l.exact(&s.spectrum), self.depth.get()), *exact, *white);
            if de > worst.0 {
                worst = (de, format!("{} × {}", l.name, s.name));
            }
        }
        Ok(worst)
    }
}
