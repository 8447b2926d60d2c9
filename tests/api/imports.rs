//! No file of the core imports a file that imports it back: the files of
//! `src/` form a ladder (ARCHITECTURE.md). A file is a module (`mod.rs` and
//! `lib.rs` stand for their folder); it imports another when its code, not
//! its comments or unit tests, names a path inside it (`crate::…`,
//! `super::…`, `self::…`; a name re-exported by a module counts as the
//! file that defines it; a module naming its own children is structure,
//! not an edge).

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

/// The paths a source names, absolute: `crate::…` as it is, `super::…`
/// and `self::…` from `module`, with `use` groups expanded
/// (`crate::a::{b, c::d}` → `a::b`, `a::c::d`).
fn paths(module: &str, code: &str) -> Vec<String> {
    let parent = module.rsplit_once("::").map_or("", |(p, _)| p);
    let mut out = Vec::new();
    for (prefix, base) in [("crate::", ""), ("super::", parent), ("self::", module)] {
        for (i, _) in code.match_indices(prefix) {
            let before = code[..i].chars().next_back();
            if before.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == ':') {
                continue; // `super::` inside `crate::a::super_x` or a longer path
            }
            let rest = &code[i + prefix.len()..];
            let end = rest
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':' || c == '{'))
                .unwrap_or(rest.len());
            let head = rest[..end].trim_end_matches(':');
            let mut push =
                |p: &str| out.push(if base.is_empty() { p.to_string() } else { format!("{base}::{p}") });
            match head.find('{') {
                Some(open) => {
                    let group_end = rest[open..].find('}').map_or(rest.len(), |e| open + e);
                    for item in rest[open + 1..group_end].split(',') {
                        let item = item.trim().trim_start_matches('{');
                        let item = item.split(" as ").next().unwrap_or("").trim();
                        push(&format!("{}{}", &head[..open], item).replace("::self", ""));
                    }
                }
                None => push(head),
            }
        }
    }
    out
}

/// Per module, the names its `use` lines re-export (`pub use` or
/// `pub(crate) use`), and the absolute path each stands for.
fn reexports(sources: &BTreeMap<String, String>) -> BTreeMap<(String, String), String> {
    let mut out = BTreeMap::new();
    for (module, code) in sources {
        for line in code.lines().map(str::trim) {
            let Some(rest) = line.strip_prefix("pub use ").or_else(|| line.strip_prefix("pub(crate) use "))
            else {
                continue;
            };
            let relative = if rest.starts_with("crate::")
                || rest.starts_with("super::")
                || rest.starts_with("self::")
            {
                rest.to_string()
            } else if rest.split("::").next().is_some_and(|first| sources.contains_key(&join(module, first)))
            {
                format!("self::{rest}")
            } else {
                continue; // another crate's
            };
            for target in paths(module, &relative) {
                let name = target.rsplit("::").next().unwrap_or("").to_string();
                out.insert((module.clone(), name), target);
            }
        }
    }
    out
}

/// The module that `path` lies in, following re-exports to where a name is
/// defined.
fn resolve(
    path: &str,
    sources: &BTreeMap<String, String>,
    reexported: &BTreeMap<(String, String), String>,
) -> Option<String> {
    let mut path = path.to_string();
    for _ in 0..8 {
        let parts: Vec<&str> = path.split("::").collect();
        let n = (0..=parts.len()).rev().find(|&n| sources.contains_key(&parts[..n].join("::")))?;
        let module = parts[..n].join("::");
        match parts.get(n).and_then(|name| reexported.get(&(module.clone(), (*name).to_string()))) {
            Some(target) if *target != path => {
                path =
                    format!("{target}{}", parts[n + 1..].iter().map(|p| format!("::{p}")).collect::<String>())
            }
            _ => return Some(module),
        }
    }
    None
}

#[test]
fn no_file_of_the_core_imports_one_that_imports_it() {
    let mut sources = BTreeMap::new();
    modules(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"), "", &mut sources);
    assert!(sources.len() > 40, "{} files", sources.len());
    let reexported = reexports(&sources);
    let mut edges: BTreeMap<&str, BTreeSet<String>> = BTreeMap::new();
    for (module, code) in &sources {
        for path in paths(module, code) {
            if let Some(to) = resolve(&path, &sources, &reexported) {
                // A module naming its own children (declaring, re-exporting) is structure.
                let own = to == *module || to.starts_with(&format!("{module}::")) || module.is_empty();
                if !own {
                    edges.entry(module).or_default().insert(to);
                }
            }
        }
    }
    assert!(edges.values().map(BTreeSet::len).sum::<usize>() > 100, "too few imports found: {edges:?}");
    // Depth-first search for a back edge, reporting the circle.
    fn visit<'a>(
        m: &'a str,
        edges: &'a BTreeMap<&'a str, BTreeSet<String>>,
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
        for to in edges.get(m).into_iter().flatten() {
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
