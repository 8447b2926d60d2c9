//! A plan as text: the scene, the rules, the chosen configuration, its
//! runners-up and why each other candidate tried was not chosen.

use std::io::{self, Write};

use speclab_study::evaluate::scene::Named;
use speclab_study::planning::plan::{Candidate, Plan, Request, Verdict};

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
    let bias = if request.allow_bias && lights.len() == 1 {
        "allowed (regular buckets, rules fitted to the scene's lights, published rules and spectral prefiltering are candidates)"
    } else if request.allow_bias {
        "allowed (regular buckets and rules fitted to the scene's lights are candidates; published rules and prefiltering are built for one light)"
    } else {
        "excluded (Monte Carlo only: unbiased)"
    };
    writeln!(out, "bias: {bias}")?;
    writeln!(out, "paths: light × surface^{} (depth {})", request.depth, request.depth)?;
    writeln!(
        out,
        "Monte Carlo: {} trials per cell; within budget if the upper end of a 95 % interval is; seed {}",
        request.trials, request.seed
    )?;
    writeln!(out, "buckets and fitted rules: within budget at M and at every larger M up to 64")?;
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

#[cfg(test)]
mod tests {
    use std::num::NonZeroUsize;

    use super::*;
    use speclab_study::evaluate::method::Method;
    use speclab_study::evaluate::scene::{builtin_lights, builtin_surfaces};
    use speclab_study::planning::cost::{Config, Cost};

    fn candidate(count: usize, ns: f64, verdict: Verdict) -> Candidate {
        let config = Config::new(Method::BOX, NonZeroUsize::new(count).unwrap());
        Candidate { config, cost: Cost { per_estimate_ns: ns, preparation_ns: 0.5 }, verdict }
    }

    #[test]
    fn the_text_names_the_scene_the_plan_and_every_candidate_tried() {
        let (lights, surfaces) = (builtin_lights(), builtin_surfaces());
        let above = Verdict::Above { worst: 2.0, cell: "F11 × A1".into() };
        let others = vec![
            candidate(1, 1.0, above),
            candidate(2, 2.0, Verdict::Unstable { worst: 0.9, m: 3 }),
            candidate(5, 5.0, Verdict::NotTried),
            candidate(6, 6.0, Verdict::NotTried),
        ];
        let plan = Plan {
            chosen: Some(candidate(3, 3.0, Verdict::Within { worst: 0.8 })),
            runners_up: vec![candidate(4, 4.0, Verdict::Within { worst: 0.7 })],
            others,
        };
        let mut out = Vec::new();
        plan_text(&mut out, &lights[..2], &surfaces[..3], &Request::default(), &plan).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert!(text.contains("scene: lights A, D65; surfaces E2, F4, G4 (6 cells)"), "{text}");
        assert!(text.contains("bias: allowed"), "{text}");
        let lines: Vec<&str> = text.lines().filter(|l| l.contains(" ns  (prep ")).collect();
        assert_eq!(lines.len(), 4, "{text}");
        assert!(lines[0].starts_with("plan ") && lines[0].ends_with("within budget: worst 0.800"), "{text}");
        assert!(lines[1].starts_with("runner-up ") && lines[1].ends_with("worst 0.700"), "{text}");
        assert!(lines[2].ends_with("above budget: 2.000 in F11 × A1"), "{text}");
        assert!(lines[3].ends_with("unstable: 0.900 here, above budget again at M=3"), "{text}");
        assert!(text.contains("\nnot chosen, cheapest first:\n"), "{text}");
        assert!(text.ends_with("\n2 costlier candidates were not needed.\n"), "{text}");
    }

    #[test]
    fn nothing_within_budget_and_nothing_skipped() {
        let (lights, surfaces) = (builtin_lights(), builtin_surfaces());
        let plan =
            Plan { chosen: None, runners_up: Vec::new(), others: vec![candidate(1, 1.0, Verdict::Biased)] };
        let unbiased = Request { allow_bias: false, ..Request::default() };
        let mut out = Vec::new();
        plan_text(&mut out, &lights[..1], &surfaces[..1], &unbiased, &plan).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert!(text.contains("plan         none: no candidate is within budget"), "{text}");
        assert!(text.contains("bias: excluded (Monte Carlo only: unbiased)"), "{text}");
        assert!(text.trim_end().ends_with("biased (excluded)"), "{text}");
        assert!(!text.contains("not needed"), "{text}");
    }
}
