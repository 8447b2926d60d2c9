//! A small path tracer over speclab's renderer API (the study's
//! `render`): a box of ColorChecker walls and spheres with an RGB-textured
//! back wall, lit by one or two lights in the ceiling, with colour carried
//! four ways (`--wavelengths`): hero wavelengths (K = 4, from a chosen
//! pdf and strata), a rule of M wavelengths fitted to the scene's lights,
//! RGB triples, or spectral prefiltering (three numbers per surface
//! computed under the scene's lights). It renders twice, with colour and grey (the same paths,
//! one number per surface), and prints the time per path vertex of each:
//! the difference is the colour's share. `--exact` integrates each of the
//! same paths exactly over wavelength and compares pixel by pixel;
//! `--survey` does so for every way and prints the render-level speed
//! against accuracy.
//!
//! ```text
//! cargo run --release --example render
//! cargo run --release --example render -- --light f11 --wavelengths fitted --m 10 --exact
//! cargo run --release --example render -- --light F11 --light A --survey --csv docs/render.csv
//! ```

mod args;
mod output;

use std::process::ExitCode;

use args::Args;
use speclab_study::carry::Carry;
use speclab_study::render::run::{self, WithCarry, with_carry};
use speclab_study::render::{Render, Setup, render};

fn main() -> ExitCode {
    let a = match args::parse() {
        Ok(a) => a,
        Err(e) => return fail(format!("{e}\n(render --help lists the options)")),
    };
    if a.survey {
        return match output::survey(&a) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => fail(e),
        };
    }
    let setup = match Setup::new(&a.lights) {
        Ok(s) => s,
        Err(e) => return fail(e),
    };
    let image = match with_carry(&a.options, &setup, Run(&a, &setup)) {
        Ok(image) => image,
        Err(e) => return fail(e),
    };
    let o = &a.options;
    match output::write_png(&a.out, o.width, o.height, &image.xyz, setup.white) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => fail(e),
    }
}

/// Renders a way as `render` does: timed against grey, then compared with
/// the exact image and a reference if asked; each reported.
struct Run<'a>(&'a Args, &'a Setup);

impl WithCarry for Run<'_> {
    type Out = Render;

    fn go<C: Carry + Sync>(self, carry: &C) -> Render {
        let (a, setup, o) = (self.0, self.1, &self.0.options);
        let timed = run::timed(o, setup, carry);
        output::report(a, setup, &timed);
        if a.exact {
            let (exact, prepared) = run::seconds(|| setup.exact());
            let with_exact = render(setup, carry, o, (o.spp, o.threads), 1, Some(&exact));
            output::exact_report(o, setup, &with_exact, timed.image.seconds, prepared);
        }
        if let Some(n) = a.reference {
            let (rms, count, seconds) = run::reference_error(o, setup, carry, &timed.image, n);
            println!("RMS ΔE*ab against {n} paths per pixel ({seconds:.1} s): {rms:.3} over {count} pixels");
        }
        timed.image
    }
}

fn fail(e: impl std::fmt::Display) -> ExitCode {
    eprintln!("render: {e}");
    ExitCode::from(2)
}
