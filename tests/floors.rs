//! The floors hold: every file of `src/` uses only its own floor and those
//! below it (`ARCHITECTURE.md`, "Floors"):
//!
//! 0. `error.rs`, `names.rs`, and `speclab_tables`' error, range,
//!    validation and interpolation;
//! 1. `spectrum/` (the interpolant, validation, range, the observer's tables);
//! 2. `color/`;
//! 3. `sampling/`;
//! 4. `io/` (and `speclab_tables`' readers and formats: only `io` parses);
//! 5. `study/`;
//!
//! with `lib.rs` and `fuzzing.rs` above them all. The reader looks at every
//! `crate::…` path outside comments (in `use` lines and in code), resolves
//! names re-exported at the crate root through `lib.rs`, and fails on a
//! path that goes up a floor. Inside a floor, the modules' imports (names
//! re-exported by the floor's `mod.rs` resolved to their module; test code
//! left out) must form no cycle.

use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::path::{Path, PathBuf};

/// The floor of a top-level module of the crate.
fn module_floor(module: &str) -> Option<usize> {
    Some(match module {
        "error" | "names" => 0,
        "spectrum" | "data" => 1,
        "color" => 2,
        "sampling" => 3,
        "io" => 4,
        "study" => 5,
        _ => return None,
    })
}

/// The floor a module of `speclab_tables` counts as; `codegen` is for build
/// scripts only.
fn tables_floor(module: &str) -> usize {
    match module {
        "error" | "range" | "validate" | "interp" | "Interpolation" | "Role" => 0,
        "text" | "brace" | "columns" | "json" | "read" => 4,
        _ => usize::MAX,
    }
}

/// The floor of a source file, from its path under `src/`.
fn file_floor(relative: &Path) -> usize {
    let first = relative.components().next().and_then(|c| c.as_os_str().to_str()).unwrap_or("");
    let module = first.trim_end_matches(".rs");
    module_floor(module).unwrap_or_else(|| match module {
        "lib" | "fuzzing" => 6,
        other => panic!("src/{other}: a file on no floor; add it to tests/floors.rs and ARCHITECTURE.md"),
    })
}

/// Every `.rs` file under `dir`.
fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("readable src") {
        let path = entry.expect("entry").path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The text without comments (`//` to the end of the line), lines joined,
/// so that a `use` over several lines reads as one.
fn code(text: &str) -> String {
    text.lines()
        .map(|line| match line.find("//") {
            Some(i) if !line[..i].contains('"') => &line[..i],
            _ => line,
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// The first path segments after each `prefix` (`crate::`, `speclab_tables::`),
/// with the items of a `{…}` group each counted.
fn first_segments(code: &str, prefix: &str) -> Vec<String> {
    let mut out = Vec::new();
    let ident = |s: &str| s.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect::<String>();
    for (at, _) in code.match_indices(prefix) {
        if code[..at].ends_with('$') || code[..at].ends_with(|c: char| c.is_alphanumeric() || c == '_') {
            continue; // `$crate::` (a macro's own floor) or part of another path
        }
        let rest = &code[at + prefix.len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let (mut depth, mut item) = (0, String::new());
            for c in group.chars() {
                match c {
                    '{' => depth += 1,
                    '}' if depth == 0 => break,
                    '}' => depth -= 1,
                    ',' if depth == 0 => {
                        out.push(ident(item.trim()));
                        item.clear();
                        continue;
                    }
                    _ => {}
                }
                item.push(c);
            }
            out.push(ident(item.trim()));
        } else {
            out.push(ident(rest));
        }
    }
    out.retain(|s| !s.is_empty() && s != "self");
    out
}

/// Names re-exported at the crate root by `lib.rs`, with their module.
fn root_names(lib: &str) -> HashMap<String, String> {
    let mut names = HashMap::new();
    for statement in code(lib).split(';') {
        let Some(path) = statement.trim().strip_prefix("pub use ") else { continue };
        let module = path.split("::").next().unwrap_or("").trim().to_string();
        let items = path.split_once('{').map_or(path.rsplit("::").next().unwrap_or(""), |(_, g)| g);
        for item in items.split(',') {
            let name = item.trim().trim_end_matches('}').trim().to_string();
            if !name.is_empty() {
                names.insert(name, module.clone());
            }
        }
    }
    names
}

#[test]
fn no_file_uses_a_floor_above_its_own() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let roots = root_names(&std::fs::read_to_string(src.join("lib.rs")).expect("lib.rs"));
    let mut files = Vec::new();
    sources(&src, &mut files);
    files.sort();
    let mut breaches = Vec::new();
    for file in &files {
        let relative = file.strip_prefix(&src).expect("under src");
        let floor = file_floor(relative);
        let text = code(&std::fs::read_to_string(file).expect("readable"));
        for name in first_segments(&text, "crate::") {
            let module = roots.get(&name).cloned().unwrap_or(name.clone());
            let used = module_floor(&module).or(if module == "rand" { Some(0) } else { None });
            match used {
                Some(used) if used <= floor => {}
                Some(used) => {
                    breaches.push(format!("{}: crate::{name} (floor {used} > {floor})", relative.display()))
                }
                None => breaches.push(format!("{}: crate::{name} is on no floor", relative.display())),
            }
        }
        for name in first_segments(&text, "speclab_tables::") {
            if tables_floor(&name) > floor {
                breaches.push(format!("{}: speclab_tables::{name} above floor {floor}", relative.display()));
            }
        }
    }
    assert!(files.len() > 40, "found only {} files", files.len());
    assert!(breaches.is_empty(), "imports that go up a floor:\n{}", breaches.join("\n"));
}

/// The reader finds what it must: a grouped `use`, a path in code, a
/// re-exported root name, a comment it must ignore, and `$crate`.
#[test]
fn the_reader_sees_every_path() {
    let text = code(
        "use crate::{color::Xyz, sampling::{hero, pdf}};\n\
         let x = crate::study::evaluate::method::Method::HERO; // crate::io here is a comment\n\
         $crate::error::Error; not_crate::spectrum;",
    );
    assert_eq!(first_segments(&text, "crate::"), ["color", "sampling", "study"]);
    let roots = root_names("pub use color::{LinearSrgb, Xyz};\npub use error::Error;\npub use rand;");
    assert_eq!(roots.get("Xyz").map(String::as_str), Some("color"));
    assert_eq!(roots.get("Error").map(String::as_str), Some("error"));
    assert_eq!(file_floor(Path::new("sampling/hero.rs")), 3);
    assert_eq!(tables_floor("read"), 4);
}

/// The modules of a floor's folder that each module uses, from the
/// `crate::floor::…` paths of its code before any `#[cfg(test)]` (files
/// named `*_tests.rs` left out), names re-exported by `mod.rs` resolved to
/// their module.
fn floor_graph(folder: &Path, floor: &str) -> BTreeMap<String, BTreeSet<String>> {
    let mut files = Vec::new();
    sources(folder, &mut files);
    let module_of = |file: &Path| -> String {
        let relative = file.strip_prefix(folder).expect("under the folder");
        let first = relative.components().next().and_then(|c| c.as_os_str().to_str()).unwrap_or("");
        first.trim_end_matches(".rs").to_string()
    };
    let modules: BTreeSet<String> = files.iter().map(|f| module_of(f)).filter(|m| m != "mod").collect();
    let mod_rs = std::fs::read_to_string(folder.join("mod.rs")).unwrap_or_default();
    let mut exported = HashMap::new();
    for statement in code(&mod_rs).split(';') {
        let statement = statement.trim();
        let Some(path) = statement.strip_prefix("pub use ").or(statement.strip_prefix("pub(crate) use "))
        else {
            continue;
        };
        let module = path.split("::").next().unwrap_or("").trim().to_string();
        for name in
            first_segments(&format!("crate::{}", &path[module.len()..].trim_start_matches("::")), "crate::")
        {
            exported.insert(name, module.clone());
        }
    }
    let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for file in files.iter().filter(|f| !f.to_string_lossy().ends_with("_tests.rs")) {
        let module = module_of(file);
        let text = std::fs::read_to_string(file).expect("readable");
        let text = code(text.split("#[cfg(test)]").next().unwrap_or(""));
        for name in first_segments(&text.replace(&format!("crate::{floor}::"), "crate::"), "crate::") {
            let target = if modules.contains(&name) { Some(name) } else { exported.get(&name).cloned() };
            if let Some(target) = target.filter(|t| *t != module && modules.contains(t)) {
                graph.entry(module.clone()).or_default().insert(target);
            }
        }
    }
    graph
}

/// A cycle of `graph`, if it has one (depth-first search).
fn cycle(graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        node: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        path: &mut Vec<String>,
        done: &mut BTreeSet<String>,
    ) -> Option<Vec<String>> {
        if let Some(at) = path.iter().position(|p| p == node) {
            return Some(path[at..].iter().cloned().chain([node.to_string()]).collect());
        }
        if done.contains(node) {
            return None;
        }
        path.push(node.to_string());
        for next in graph.get(node).into_iter().flatten() {
            if let Some(found) = visit(next, graph, path, done) {
                return Some(found);
            }
        }
        path.pop();
        done.insert(node.to_string());
        None
    }
    let mut done = BTreeSet::new();
    graph.keys().find_map(|start| visit(start, graph, &mut Vec::new(), &mut done))
}

#[test]
fn no_import_cycle_inside_a_floor() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut edges = 0;
    for floor in ["spectrum", "color", "sampling", "io", "study"] {
        let graph = floor_graph(&src.join(floor), floor);
        edges += graph.values().map(BTreeSet::len).sum::<usize>();
        assert_eq!(cycle(&graph), None, "an import cycle inside {floor}/");
    }
    assert!(edges > 50, "found only {edges} imports inside floors");
}

/// The cycle finder finds a cycle, and only one that is there.
#[test]
fn the_cycle_finder_finds_cycles() {
    let graph = |edges: &[(&str, &str)]| {
        let mut g: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        for (a, b) in edges {
            g.entry(a.to_string()).or_default().insert(b.to_string());
        }
        g
    };
    assert_eq!(cycle(&graph(&[("a", "b"), ("b", "c"), ("a", "c")])), None);
    let found = cycle(&graph(&[("a", "b"), ("b", "c"), ("c", "b")])).expect("b ↔ c");
    assert_eq!(found, ["b", "c", "b"]);
}
