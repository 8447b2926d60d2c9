//! No file of the core imports a file that imports it back: the files of
//! `src/` form a ladder (ARCHITECTURE.md). A file is a module (`mod.rs` and
//! `lib.rs` stand for their folder); it imports another when its code, not
//! its comments or unit tests, names a path `crate::…` inside it (a module
//! naming its own parent's re-exports is not an edge).

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// Module path (`color::space`) → its source, unit tests and comments cut.
fn modules(dir: &Path, prefix: &str, out: &mut BTreeMap<String, String>) {
    for entry in std::fs::read_dir(dir).expect("src/ is readable").flatten() {
        let (path, name) = (entry.path(), entry.file_name().to_string_lossy().into_owned());
        if path.is_dir() {
            modules(&path, &join(prefix, &name), out);
        } else if let Some(stem) = name.strip_suffix(".rs") {
            let module = if stem == "mod" || stem == "lib" { prefix.to_string() } else { join(prefix, stem) };
            let source = std::fs::read_to_string(&path).expect("a source file");
            let code = source.split("#[cfg(test)]\nmod tests").next().unwrap_or("");
            let code: Vec<&str> = code.lines().filter(|l| !l.trim_start().starts_with("//")).collect();
            out.insert(module, code.join("\n"));
        }
    }
}

fn join(prefix: &str, name: &str) -> String {
    if prefix.is_empty() { name.to_string() } else { format!("{prefix}::{name}") }
}

/// The paths a source names after `crate::`, with `use` groups expanded
/// (`crate::a::{b, c::d}` → `a::b`, `a::c::d`).
fn crate_paths(code: &str) -> Vec<String> {
    let mut out = Vec::new();
    for (i, _) in code.match_indices("crate::") {
        let rest = &code[i + "crate::".len()..];
        let end = rest
            .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':' || c == '{'))
            .unwrap_or(rest.len());
        let head = rest[..end].trim_end_matches(':');
        match head.find('{') {
            Some(open) => {
                let group_end = rest[open..].find('}').map_or(rest.len(), |e| open + e);
                for item in rest[open + 1..group_end].split(',') {
                    let item = item.trim().trim_start_matches('{');
                    out.push(format!("{}{}", &head[..open], item.split(" as ").next().unwrap_or("").trim()));
                }
            }
            None => out.push(head.to_string()),
        }
    }
    out
}

/// The longest module that `path` lies in.
fn resolve<'a>(path: &str, modules: &'a BTreeMap<String, String>) -> Option<&'a str> {
    let parts: Vec<&str> = path.split("::").collect();
    (1..=parts.len())
        .rev()
        .find_map(|n| modules.get_key_value(&parts[..n].join("::")).map(|(k, _)| k.as_str()))
}

#[test]
fn no_file_of_the_core_imports_one_that_imports_it() {
    let mut sources = BTreeMap::new();
    modules(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"), "", &mut sources);
    assert!(sources.len() > 40, "{} files", sources.len());
    let mut edges: BTreeMap<&str, BTreeSet<&str>> = BTreeMap::new();
    for (module, code) in &sources {
        for path in crate_paths(code) {
            if let Some(to) = resolve(&path, &sources) {
                let parent = module.starts_with(&format!("{to}::")) || to.is_empty();
                if to != module && !parent {
                    edges.entry(module).or_default().insert(to);
                }
            }
        }
    }
    assert!(edges.values().map(BTreeSet::len).sum::<usize>() > 100, "too few imports found: {edges:?}");
    // Depth-first search for a back edge, reporting the circle.
    fn visit<'a>(
        m: &'a str,
        edges: &BTreeMap<&'a str, BTreeSet<&'a str>>,
        path: &mut Vec<&'a str>,
        done: &mut BTreeSet<&'a str>,
    ) -> Result<(), String> {
        if let Some(start) = path.iter().position(|&p| p == m) {
            return Err(format!("{} → {m}", path[start..].join(" → ")));
        }
        if done.contains(m) {
            return Ok(());
        }
        path.push(m);
        for &to in edges.get(m).into_iter().flatten() {
            visit(to, edges, path, done)?;
        }
        path.pop();
        done.insert(m);
        Ok(())
    }
    let mut done = BTreeSet::new();
    for &m in edges.keys() {
        if let Err(circle) = visit(m, &edges, &mut Vec::new(), &mut done) {
            panic!("a circle of imports: {circle}");
        }
    }
}
