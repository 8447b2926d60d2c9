//! The fixed rules' tables: by M (with stable errors), and by depth.

use std::io::{self, Write};

use speclab_study::experiments::rules::{self, DepthRow, RuleRow};
use speclab_study::published::rules::Family;

/// A Markdown table of `rows` at each M of `ms`: the worst ΔE00 over the
/// surfaces (called `surfaces` in the first column) of the fitted rule,
/// and of centre and box buckets with their stable errors; then each
/// published rule's worst and stable error (over the M at which it
/// exists), `—` where it has no rule of M.
pub fn rules_table(out: &mut impl Write, surfaces: &str, rows: &[RuleRow], ms: &[usize]) -> io::Result<()> {
    write!(
        out,
        "| surfaces | light | M | fitted | fitted, stable | centre | centre, stable | box | box, stable |"
    )?;
    for family in Family::NAMES {
        write!(out, " {family} (stable) |")?;
    }
    writeln!(out, "\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")?;
    for row in rows.iter().filter(|r| ms.contains(&r.m)) {
        let stable = |pick: fn(&RuleRow) -> f64| rules::stable(rows, pick, row.m);
        write!(
            out,
            "| {surfaces} | {} | {} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} |",
            row.light,
            row.m,
            row.fitted,
            stable(|r| r.fitted),
            row.center,
            stable(|r| r.center),
            row.boxed,
            stable(|r| r.boxed)
        )?;
        for (i, worst) in row.published.iter().enumerate() {
            match worst {
                Some(w) => write!(
                    out,
                    " {w:.2} ({:.2}) |",
                    rules::stable(rows, |r| r.published[i].unwrap_or(0.0), row.m)
                )?,
                None => write!(out, " — |")?,
            }
        }
        writeln!(out)?;
    }
    Ok(())
}

/// A Markdown table of what each light needs at each depth.
pub fn depth_table(out: &mut impl Write, rows: &[DepthRow], budget: f64) -> io::Result<()> {
    writeln!(
        out,
        "| light | depth | centre, stable M | box, stable M | fitted, stable M | hero jitter, n (RMS < {budget}) |"
    )?;
    writeln!(out, "|---|---:|---:|---:|---:|---:|")?;
    for r in rows {
        let hero = hero_n(r.hero);
        writeln!(
            out,
            "| {} | {} | {} | {} | {} | {hero} |",
            r.light,
            r.depth,
            stable_m(r.center),
            stable_m(r.boxed),
            stable_m(r.fitted)
        )?;
    }
    Ok(())
}

/// A Markdown table of what each light needs (one depth), each row led by
/// `label` of it (the light, or the surfaces and the light).
pub fn needs_table(
    out: &mut impl Write,
    rows: &[DepthRow],
    budget: f64,
    head: &str,
    label: impl Fn(&DepthRow) -> String,
) -> io::Result<()> {
    writeln!(
        out,
        "| {head} | fitted, stable M | box, stable M | centre, stable M | hero jitter, n (RMS < {budget}) |"
    )?;
    writeln!(out, "|---|---:|---:|---:|---:|")?;
    for r in rows {
        let hero = hero_n(r.hero);
        writeln!(
            out,
            "| {} | {} | {} | {} | {hero} |",
            label(r),
            stable_m(r.fitted),
            stable_m(r.boxed),
            stable_m(r.center)
        )?;
    }
    Ok(())
}

/// A stable bucket or fitted count, or "> 64" where none up to 64 is.
fn stable_m(m: Option<usize>) -> String {
    m.map_or_else(|| "> 64".to_string(), |m| m.to_string())
}

/// Hero's sample count, or "> 4096" where none up to 4096 is within budget.
fn hero_n(n: Option<usize>) -> String {
    n.map_or_else(|| "> 4096".to_string(), |n| n.to_string())
}
