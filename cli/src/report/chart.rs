//! Chart points as CSV.

use std::io::{self, Write};

use super::sampling_columns;
use speclab_study::planning::chart::Point;

/// One row per point: `light,method,pdf,strata,count,evals,ns_per_estimate,
/// preparation_ns,worst_rms_de00,mean_rms_de00,trials,pareto`. `count` is
/// n (random, hero), M (buckets) or 0 (reference); `pareto` is `true` for
/// the points on the light's Pareto front.
pub fn chart_csv(out: &mut impl Write, points: &[Point]) -> io::Result<()> {
    writeln!(
        out,
        "light,method,pdf,strata,count,evals,ns_per_estimate,preparation_ns,worst_rms_de00,mean_rms_de00,trials,pareto"
    )?;
    for p in points {
        let (method, count) = (p.config.method, p.config.count);
        let (pdf, strata) = sampling_columns(method);
        writeln!(
            out,
            "{},{},{pdf},{strata},{},{},{},{},{},{},{},{}",
            p.light,
            method,
            method.reported_samples(count),
            method.evaluations(count),
            p.cost.per_estimate_ns,
            p.cost.preparation_ns,
            p.worst_rms,
            p.mean_rms,
            p.trials,
            p.pareto
        )?;
    }
    Ok(())
}
