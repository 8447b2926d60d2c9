//! The texture table: what an RGB texture costs in colour, beside sampling.

use std::io::{self, Write};

use speclab_study::experiments::texture::{TextureOptions, TextureRow};

/// `rows` as a Markdown table, one row per light × surface.
pub fn texture_table(out: &mut impl Write, rows: &[TextureRow], o: &TextureOptions) -> io::Result<()> {
    writeln!(
        out,
        "Each surface's colour under D65 as a linear sRGB texture (clipped to [0, 1]; * where that"
    )?;
    writeln!(out, "clips), upsampled to an RgbAlbedo and lit by each light: ΔE00 to the measured spectrum,")?;
    writeln!(out, "beside sampling the measured spectrum ({} trials, seed {}).\n", o.trials, o.seed)?;
    let (n, m) = (o.n, o.m);
    writeln!(
        out,
        "| light | surface | texture (linear sRGB) | texture ΔE00 | hero n={n} jitter RMS ΔE00 | center M={m} ΔE00 | box M={m} ΔE00 |"
    )?;
    writeln!(out, "|---|---|---|---|---|---|---|")?;
    for r in rows {
        let star = if r.clipped { "*" } else { "" };
        let rgb = format!("{:.3}, {:.3}, {:.3}{star}", r.rgb.r, r.rgb.g, r.rgb.b);
        writeln!(
            out,
            "| {} | {} | {rgb} | {:.2} | {:.2} | {:.2} | {:.2} |",
            r.light, r.surface, r.texture_de00, r.hero_rms_de00, r.center_de00, r.box_de00
        )?;
    }
    Ok(())
}
