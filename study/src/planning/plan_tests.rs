use super::*;

#[test]
fn bucket_verdicts_on_hand_made_errors() {
    let worst = |v: &[f64]| v.iter().map(|&e| (e, "cell".to_string())).collect::<Vec<_>>();
    let errors = worst(&[2.0, 1.0, 1.0, 0.5]);
    assert_eq!(bucket_verdict(&errors, 1, 1.0), Verdict::Above { worst: 2.0, cell: "cell".into() });
    // Equal to the budget is within, at M and at every larger M.
    assert_eq!(bucket_verdict(&errors, 2, 1.0), Verdict::Within { worst: 1.0 });
    assert_eq!(bucket_verdict(&errors, 4, 1.0), Verdict::Within { worst: 0.5 });
    // Above again two counts later: the first such M is named.
    let errors = worst(&[0.5, 0.6, 2.0, 0.1]);
    assert_eq!(bucket_verdict(&errors, 1, 1.0), Verdict::Unstable { worst: 0.5, m: 3 });
    assert_eq!(bucket_verdict(&errors, 2, 1.0), Verdict::Unstable { worst: 0.6, m: 3 });
}

/// Statistics with a chosen RMS and standard error of the mean square.
fn stats(rms: f64, se: f64) -> Stats {
    let zero = Xyz::ZERO;
    Stats {
        trials: 10,
        bias: zero,
        sd: zero,
        rms_de00: rms,
        mean_square_se: se,
        p95_de00: rms,
        false_out_of_gamut: None,
        false_in_gamut: None,
    }
}

/// Hand-made statistics per cell and stage: the verdict takes every
/// cell's full-run upper bound, and names the cell that breaks a budget.
#[test]
fn the_verdict_bounds_every_cell_by_its_full_run() {
    let cells = ["A × E2", "A × F4", "A × G4"].map(String::from);
    let screen = [stats(0.5, 0.01), stats(0.6, 0.01), stats(0.4, 0.01)];
    let full = [stats(0.5, 0.02), stats(0.7, 0.02), stats(0.3, 0.02)];
    let run = |c: usize, stage: usize| Ok(if stage == 0 { screen[c] } else { full[c] });
    let upper = full.map(|s| s.rms_de00_interval().1);
    let worst = upper.iter().copied().fold(0.0, f64::max);
    assert_eq!(worst, upper[1]);
    assert_eq!(judge(&cells, 1.0, run).unwrap(), Verdict::Within { worst });
    // A budget equal to the worst upper bound is met; just below, it is
    // not, and the cell named is the one with that bound, with its RMS.
    assert_eq!(judge(&cells, worst, run).unwrap(), Verdict::Within { worst });
    let above = Verdict::Above { worst: 0.7, cell: cells[1].clone() };
    assert_eq!(judge(&cells, worst * (1.0 - 1e-12), run).unwrap(), above);
}

/// A cell whose screen is clearly above budget (its interval's lower
/// end) stops the run before any full run; a budget exactly at that
/// lower end passes the screen, and the full run decides.
#[test]
fn a_clear_failure_is_stopped_by_the_screen() {
    let cells = ["F11 × E2", "F11 × A1"].map(String::from);
    let screen = [stats(0.5, 0.01), stats(5.0, 0.5)];
    let full = [stats(0.5, 0.01), stats(6.0, 0.1)];
    let lower = screen[1].rms_de00_interval().0;
    let mut calls = Vec::new();
    let verdict = judge(&cells, 1.0, |c, stage| {
        calls.push((c, stage));
        Ok(if stage == 0 { screen[c] } else { full[c] })
    });
    assert_eq!(verdict.unwrap(), Verdict::Above { worst: lower, cell: cells[1].clone() });
    assert_eq!(calls, [(0, 0), (1, 0)], "no full run after a clear failure");
    let at = judge(&cells, lower, |c, stage| Ok(if stage == 0 { screen[c] } else { full[c] }));
    assert_eq!(at.unwrap(), Verdict::Above { worst: 6.0, cell: cells[1].clone() });
    // An error from a run is the verdict's error.
    let failing = judge(&cells, 1.0, |_, _| Err(StudyError::EmptyScene));
    assert!(matches!(failing, Err(StudyError::EmptyScene)));
}
