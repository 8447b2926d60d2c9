//! The fixed rules' tables: by M (with stable errors), and by depth.

use std::io::{self, Write};

use crate::study::experiments::rules::{self, DepthRow, RuleRow};

/// A Markdown table of `rows` at each M of `ms`: the worst ΔE00 over the
/// surfaces (called `surfaces` in the first column) of the fitted rule,
/// and of centre and box buckets with their stable errors.
pub fn rules_table(out: &mut impl Write, surfaces: &str, rows: &[RuleRow], ms: &[usize]) -> io::Result<()> {
    writeln!(
        out,
        "| surfaces | light | M | fitted | fitted, stable | centre | centre, stable | box | box, stable |"
    )?;
    writeln!(out, "|---|---|---:|---:|---:|---:|---:|---:|---:|")?;
    for row in rows.iter().filter(|r| ms.contains(&r.m)) {
        let stable = |pick: fn(&RuleRow) -> f64| rules::stable(rows, pick, row.m);
        writeln!(
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
    }
    Ok(())
}

/// A Markdown table of what each light needs at each depth.
pub fn depth_table(out: &mut impl Write, rows: &[DepthRow], budget: f64) -> io::Result<()> {
    let count = |c: Option<usize>| c.map_or_else(|| "> 64".to_string(), |c| c.to_string());
    writeln!(
        out,
        "| light | depth | centre, stable M | box, stable M | fitted, stable M | hero jitter, n (RMS < {budget}) |"
    )?;
    writeln!(out, "|---|---:|---:|---:|---:|---:|")?;
    for r in rows {
        let hero = r.hero.map_or_else(|| "> 4096".to_string(), |n| n.to_string());
        writeln!(
            out,
            "| {} | {} | {} | {} | {} | {hero} |",
            r.light,
            r.depth,
            count(r.center),
            count(r.boxed),
            count(r.fitted)
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
    let count = |c: Option<usize>| c.map_or_else(|| "> 64".to_string(), |c| c.to_string());
    writeln!(
        out,
        "| {head} | fitted, stable M | box, stable M | centre, stable M | hero jitter, n (RMS < {budget}) |"
    )?;
    writeln!(out, "|---|---:|---:|---:|---:|")?;
    for r in rows {
        let hero = r.hero.map_or_else(|| "> 4096".to_string(), |n| n.to_string());
        writeln!(
            out,
            "| {} | {} | {} | {} | {hero} |",
            label(r),
            count(r.fitted),
            count(r.boxed),
            count(r.center)
        )?;
    }
    Ok(())
}
