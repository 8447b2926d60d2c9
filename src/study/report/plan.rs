//! A plan as text: the scene, the rules, the chosen configuration, its
//! runners-up and why each other candidate tried was not chosen.

use std::io::{self, Write};

use crate::study::plan::{Candidate, Plan, Request, Verdict};
use crate::study::scene::Named;

/// `plan` for `lights × surfaces` under `request`, for people.
pub fn plan_text(
    out: &mut impl Write,
    lights: &[Named],
    surfaces: &[Named],
    request: &Request,
    plan: &Plan,
) -> io::Result<()> {
    let names = |s: &[Named]| s.iter().map(|n| n.name.as_str()).collect::<Vec<_>>().join(", ");
    let budget = request.budget;
    writeln!(out, "speclab plan: the cheapest sampling whose RMS ΔE00 stays within {budget} in every cell")?;
    let cells = lights.len() * surfaces.len();
    writeln!(out, "scene: lights {}; surfaces {} ({cells} cells)", names(lights), names(surfaces))?;
    let bias =
        if request.allow_bias { "allowed (regular buckets are candidates)" } else { "excluded (--unbiased)" };
    writeln!(out, "bias: {bias}")?;
    writeln!(
        out,
        "Monte Carlo: {} trials per cell; within budget if the upper end of a 95 % interval is; seed {}",
        request.trials, request.seed
    )?;
    writeln!(out, "buckets: within budget at M and at every larger M up to 64")?;
    if let (Some(l), Some(s)) = (lights.first(), surfaces.first()) {
        writeln!(
            out,
            "cost: ns per estimate, measured now on {} × {}, one thread (median of 7 timings)\n",
            l.name, s.name
        )?;
    }
    match &plan.chosen {
        Some(c) => line(out, "plan", c)?,
        None => writeln!(out, "plan         none: no candidate is within budget")?,
    }
    for c in &plan.runners_up {
        line(out, "runner-up", c)?;
    }
    let tried: Vec<&Candidate> = plan.others.iter().filter(|c| c.verdict != Verdict::NotTried).collect();
    if !tried.is_empty() {
        writeln!(out, "\nnot chosen, cheapest first:")?;
        for c in tried {
            line(out, "", c)?;
        }
    }
    let skipped = plan.others.len() - plan.others.iter().filter(|c| c.verdict != Verdict::NotTried).count();
    if skipped > 0 {
        writeln!(out, "\n{skipped} costlier candidates were not needed.")?;
    }
    Ok(())
}

/// One candidate: label, configuration, cost and verdict.
fn line(out: &mut impl Write, label: &str, c: &Candidate) -> io::Result<()> {
    let (ns, prep) = (c.cost.per_estimate_ns, c.cost.preparation_ns);
    let config = c.config.to_string();
    writeln!(out, "{label:<12} {config:<34} {ns:>10.1} ns  (prep {prep:>8.1} ns)  {}", reason(&c.verdict))
}

/// What the verdict says, in words.
fn reason(verdict: &Verdict) -> String {
    match verdict {
        Verdict::Within { worst } => format!("within budget: worst {worst:.3}"),
        Verdict::Above { worst, cell } => format!("above budget: {worst:.3} in {cell}"),
        Verdict::Unstable { worst, m } => format!("unstable: {worst:.3} here, above budget again at M={m}"),
        Verdict::Biased => "biased (excluded)".into(),
        Verdict::NotTried => "not needed".into(),
    }
}
