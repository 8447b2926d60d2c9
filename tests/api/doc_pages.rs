//! Every page of `docs/` and the README are doctested: `lib.rs` includes
//! each under `cfg(doctest)`, and this test checks that its list is the
//! folder's, so a new page cannot be left out.

use std::collections::BTreeSet;

#[test]
fn every_docs_page_is_doctested() {
    let root = env!("CARGO_MANIFEST_DIR");
    let lib = std::fs::read_to_string(format!("{root}/src/lib.rs")).expect("src/lib.rs");
    let included: BTreeSet<String> = lib
        .split("include_str!(\"../")
        .skip(1)
        .filter_map(|rest| rest.split('"').next())
        .map(str::to_string)
        .collect();
    let mut pages: BTreeSet<String> = std::fs::read_dir(format!("{root}/docs"))
        .expect("docs/")
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|name| name.ends_with(".md"))
        .map(|name| format!("docs/{name}"))
        .collect();
    pages.insert("README.md".to_string());
    assert!(pages.len() > 5, "{pages:?}");
    assert_eq!(included, pages, "pages doctested by lib.rs against the pages that exist");
}
