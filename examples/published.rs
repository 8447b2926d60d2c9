//! The fitted rule beside the published few-wavelength rules (ASTM E308 /
//! E2022, Borges 1994, Meyer 1988, Wallis 1975) and Ward's spectral
//! prefiltering, on every built-in light × the 53 held-apart reflectances
//! (`data/held-apart/`, in no fitted prior): worst / mean ΔE00 and pairs
//! above 1, at depth 1 and 2, then each light's worst for the targets of
//! docs/published-rules.md. `fitted-munsell` is the same fit over measured
//! Munsell chips (`published::measured`) instead of the generated prior.
//! The last two columns are reference points,
//! not methods (they have seen the answers): `oracle`, the rule fitted to
//! each light over these very 53 reflectances
//! (`FittedRules::with_surfaces`), and `oracle-minimax`, its wavelengths
//! with weights that lower the worst ΔE00 over them (`published::minimax`).
//! Markdown, as the docs quote it.
//!
//! ```text
//! cargo run --release --example published
//! cargo run --release --example published -- --depth 2
//! ```

use std::fmt::Write as _;
use std::io::{self, Write as _};
use std::process::ExitCode;
use std::time::Instant;

use speclab::sampling::fitted::FittedRules;
use speclab::spectrum::Spectrum;
use speclab_cli::args::{fail, finish};
use speclab_study::StudyError;
use speclab_study::evaluate::scene::{self, Depth, Named};
use speclab_study::published::compare::{self, Candidate, Row};
use speclab_study::published::prefilter::Space;
use speclab_study::published::{held_apart, measured, rules::Family};

const USAGE: &str = "\
usage: published [--depth D]
  --depth D   surfaces per path, 1 to 4; repeat for several (default: 1 and 2)";

/// The Ms the table shows.
const MS: [usize; 9] = [4, 6, 8, 10, 12, 16, 18, 24, 36];

fn main() -> ExitCode {
    let mut depths = Vec::new();
    let mut parser = lexopt::Parser::from_env();
    loop {
        use lexopt::prelude::*;
        match parser.next() {
            Ok(None) => break,
            Ok(Some(Long("depth"))) => match parser.value().and_then(|v| v.parse::<usize>()) {
                Ok(d) => depths.push(d),
                Err(e) => return fail("published", format!("{e}\n{USAGE}")),
            },
            Ok(Some(Short('h') | Long("help"))) => {
                println!("{USAGE}");
                return ExitCode::SUCCESS;
            }
            Ok(Some(other)) => return fail("published", format!("{}\n{USAGE}", other.unexpected())),
            Err(e) => return fail("published", format!("{e}\n{USAGE}")),
        }
    }
    if depths.is_empty() {
        depths = vec![1, 2];
    }
    match report(&depths) {
        Ok(text) => {
            let out = &mut io::stdout().lock();
            finish("published", out.write_all(text.as_bytes()).and_then(|()| out.flush()))
        }
        Err(e) => fail("published", e),
    }
}

/// The whole report, as Markdown.
fn report(depths: &[usize]) -> Result<String, StudyError> {
    let (lights, surfaces) = (scene::every_light(), held_apart::all()?);
    let mut out = String::new();
    fit_times(&lights, &mut out)?;
    let (chips, prior) = (measured::munsell()?.len(), measured::prior()?.len());
    // Writing to a String cannot fail.
    let _ = writeln!(
        out,
        "\nfitted-munsell: fitted over {prior} of the {chips} Munsell chips (the {} within {} ΔE00 of a held-apart surface under A or D65 dropped)",
        chips - prior,
        measured::NEAR
    );
    for &d in depths {
        let depth = Depth::new(d)?;
        let _ = writeln!(out, "\n## Depth {d}: {} lights × {} reflectances\n", lights.len(), surfaces.len());
        let by_m = table_by_m(&lights, &surfaces, depth, &mut out)?;
        let pre = compare::table(&lights, &surfaces, &Space::ALL.map(Candidate::Prefiltered), depth)?;
        let _ = writeln!(out);
        for r in &pre {
            let _ = writeln!(out, "{} (3 numbers per surface): {}", r.candidate, summary(r));
        }
        per_light(&lights, &by_m, &mut out);
    }
    Ok(out)
}

/// Every candidate with wavelengths at every M at `depth`, as one table
/// (each light's fits over surfaces are built once), written to `out` a
/// row per M; the rows by M.
fn table_by_m(
    lights: &[Named],
    surfaces: &[Named],
    depth: Depth,
    out: &mut String,
) -> Result<Vec<(usize, Vec<Row>)>, StudyError> {
    let mut candidates = Vec::new();
    for m in MS {
        candidates.extend([
            Candidate::Fitted(m),
            Candidate::FittedMunsell(m),
            Candidate::Oracle(m),
            Candidate::OracleMinimax(m),
        ]);
        candidates
            .extend(Family::ALL.into_iter().filter(|f| m >= f.min_m()).map(|f| Candidate::Published(f, m)));
    }
    let rows = compare::table(lights, surfaces, &candidates, depth)?;
    let by_m: Vec<(usize, Vec<Row>)> = MS
        .iter()
        .map(|&m| (m, rows.iter().filter(|r| r.candidate.m() == Some(m)).cloned().collect()))
        .collect();
    // (column, header): ASTM's cell names its interval.
    let columns = [
        ("fitted", "fitted"),
        ("fitted-munsell", "fitted-munsell"),
        ("borges", "borges"),
        ("meyer", "meyer"),
        ("wallis", "wallis"),
        ("astm", "astm (interval)"),
        ("oracle", "oracle"),
        ("oracle-minimax", "oracle-minimax"),
    ];
    let headers: Vec<&str> = columns.iter().map(|c| c.1).collect();
    let _ = writeln!(out, "| M | {} |", headers.join(" | "));
    let _ = writeln!(out, "|---:|{}", "---|".repeat(columns.len()));
    for (m, rows) in &by_m {
        let cell = |name: &str| match name {
            "astm" => rows
                .iter()
                .find(|r| matches!(r.candidate, Candidate::Published(Family::Astm, _)))
                .map_or("–".into(), |r| format!("{} ({})", summary(r), r.candidate)),
            _ => rows.iter().find(|r| r.candidate.to_string() == name).map_or("–".into(), summary),
        };
        let cells: Vec<String> = columns.iter().map(|c| cell(c.0)).collect();
        let _ = writeln!(out, "| {m} | {} |", cells.join(" | "));
    }
    Ok(by_m)
}

/// `worst / mean / pairs above 1` (and lights without the rule).
fn summary(r: &Row) -> String {
    let missing = r.per_light.iter().filter(|w| w.is_nan()).count();
    let gap = if missing > 0 { format!(", {missing} lights without") } else { String::new() };
    if r.pairs == 0 {
        return format!("none{gap}");
    }
    format!("{:.2} / {:.3} / {}{gap}", r.worst, r.mean, r.above_one)
}

/// Light by light: fitted M = 10 against ASTM at 20 nm (M = 18), fitted
/// M = 12 against ASTM at 10 nm (M = 36); then `fitted-munsell`'s and the
/// oracles' rules the same.
fn per_light(lights: &[Named], by_m: &[(usize, Vec<Row>)], out: &mut String) {
    let row = |m: usize, pick: &dyn Fn(&Candidate) -> bool| {
        by_m.iter().find(|(k, _)| *k == m).and_then(|(_, rows)| rows.iter().find(|r| pick(&r.candidate)))
    };
    let fitted = |m| row(m, &|c| matches!(c, Candidate::Fitted(_)));
    let munsell = |m| row(m, &|c| matches!(c, Candidate::FittedMunsell(_)));
    let oracle = |m| row(m, &|c| matches!(c, Candidate::Oracle(_)));
    let minimax = |m| row(m, &|c| matches!(c, Candidate::OracleMinimax(_)));
    let astm = |m| row(m, &|c| matches!(c, Candidate::Published(Family::Astm, _)));
    let ways =
        [(10, 18, "fitted"), (12, 36, "fitted"), (10, 18, "fitted-munsell"), (12, 36, "fitted-munsell")];
    let ways = ways.into_iter().chain([(10, 18, "oracle"), (12, 36, "oracle")]);
    let ways = ways.chain([(10, 18, "oracle-minimax"), (12, 36, "oracle-minimax")]);
    for (fm, am, rule) in ways {
        let f = match rule {
            "fitted" => fitted(fm),
            "fitted-munsell" => munsell(fm),
            "oracle" => oracle(fm),
            _ => minimax(fm),
        };
        let (Some(f), Some(a)) = (f, astm(am)) else { continue };
        let losses: Vec<String> = lights
            .iter()
            .zip(f.per_light.iter().zip(&a.per_light))
            .filter(|(_, (f, a))| f >= a)
            .map(|(l, (f, a))| format!("{} {f:.2}/{a:.2}", l.name))
            .collect();
        let line = format!(
            "\n{rule} M = {fm} against {}: worst at or above ASTM's on {} of {} lights{}{}",
            a.candidate,
            losses.len(),
            lights.len(),
            if losses.is_empty() { "" } else { ": " },
            losses.join(", ")
        );
        let _ = writeln!(out, "{line}");
    }
}

/// The fit's time per M for one light (D65), over the generated prior and
/// over the Munsell chips; the first fit in the process is included in
/// the first M, building the Munsell problem is timed apart.
fn fit_times(lights: &[Named], out: &mut String) -> Result<(), StudyError> {
    let d65 = lights.iter().find(|l| l.name == "D65").unwrap_or(&lights[0]);
    let per_m = |rules: &FittedRules| -> Result<String, StudyError> {
        let mut times = Vec::new();
        for m in MS {
            let start = Instant::now();
            rules.rule(m)?;
            times.push(format!("M = {m}: {:.0} ms", start.elapsed().as_secs_f64() * 1e3));
        }
        Ok(times.join(", "))
    };
    let generated = per_m(&FittedRules::of(&d65.spectrum)?)?;
    let prior: Vec<&dyn Spectrum> = measured::prior()?.iter().map(|c| &c.spectrum as &dyn Spectrum).collect();
    let start = Instant::now();
    let munsell = FittedRules::with_surfaces(&[&d65.spectrum], &prior)?;
    let built = start.elapsed().as_secs_f64();
    let munsell = per_m(&munsell)?;
    let _ = writeln!(
        out,
        "Fit time under {} (one thread; after the prior's moments and the light's normal equations, built once): {generated}",
        d65.name
    );
    let _ = writeln!(
        out,
        "\nThe same over the Munsell chips ({} surfaces; the problem built in {:.0} ms): {munsell}",
        prior.len(),
        built * 1e3
    );
    Ok(())
}
