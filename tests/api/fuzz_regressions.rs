//! Replays the fuzz target's seeds and any saved crash inputs through the
//! same code the fuzzer runs (`fuzz_body.rs`). CI runs this;
//! it does not run the fuzzer itself.

use std::path::Path;

#[test]
fn replay_saved_inputs() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz");
    let mut replayed = 0;
    for dir in ["seeds", "regressions"] {
        let Ok(entries) = std::fs::read_dir(root.join(dir)) else { continue };
        for entry in entries.flatten() {
            let bytes = std::fs::read(entry.path()).expect("readable input");
            super::fuzz_body::parsers(&bytes);
            replayed += 1;
        }
    }
    assert!(replayed >= 5, "expected the seed inputs, replayed {replayed}");
}
