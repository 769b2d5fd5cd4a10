//! Which file of `src/` names which: the file-level import graph that the layering test
//! ([`crate::layers`]) checks for pairs of files naming each other.
//!
//! A file names another when its code (comment lines aside) holds a path through `crate::`
//! or `super::` (plain, or in a `use` group `{..}`, nested groups too) that resolves to an
//! item the other file defines. A path resolves through the deepest module that has a file
//! (`a/b.rs` or `a/b/mod.rs`); its next segment is the item, looked up first in that
//! module's file and then in the files below it (a module re-exporting a child's item leads to
//! the child). `self::` and relative paths (a `mod.rs` declaring and re-exporting its children)
//! are not imports. Inline `mod name { .. }` blocks (the tests) move `super` one module down.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::Path;

/// The import graph: each file (relative to `src`) and the files it names.
pub(crate) type Graph = BTreeMap<String, BTreeSet<String>>;

/// A file's module path: `scene/walk.rs` is `[scene, walk]`, `scene/mod.rs` is `[scene]`.
fn module_of(rel: &str) -> Vec<String> {
    let mut parts: Vec<String> = rel
        .trim_end_matches(".rs")
        .split('/')
        .map(String::from)
        .collect();
    if parts.last().is_some_and(|p| p == "mod" || p == "lib") {
        parts.pop();
    }
    parts
}

fn is_ident(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// The item a definition line defines (`pub(crate) const fn f`, `struct S`, `trait T`, ..).
fn defined(line: &str) -> Option<String> {
    let mut rest = line.trim_start();
    if let Some(r) = rest.strip_prefix("pub") {
        rest = r.trim_start();
        if rest.starts_with('(') {
            rest = rest[rest.find(')')? + 1..].trim_start();
        }
    }
    for qualifier in ["const fn ", "unsafe fn ", "async fn "] {
        if let Some(r) = rest.strip_prefix(qualifier) {
            rest = r;
            return Some(rest.chars().take_while(|c| is_ident(*c)).collect());
        }
    }
    for kw in [
        "fn ", "struct ", "enum ", "trait ", "const ", "type ", "static ", "union ",
    ] {
        if let Some(r) = rest.strip_prefix(kw) {
            let name: String = r
                .trim_start()
                .chars()
                .take_while(|c| is_ident(*c))
                .collect();
            return (!name.is_empty()).then_some(name);
        }
    }
    None
}

/// The paths of a use tree or plain path starting at `s` (just after `crate::` or `super::`),
/// each as segments appended to `prefix`.
fn paths_at(prefix: &[String], s: &str, out: &mut Vec<Vec<String>>) {
    let mut segs = prefix.to_vec();
    let mut rest = s;
    loop {
        if let Some(group) = rest.strip_prefix('{') {
            // Split the group at its top-level commas.
            let (mut depth, mut start) = (0, 0);
            for (i, c) in group.char_indices() {
                match c {
                    '{' => depth += 1,
                    '}' if depth == 0 => {
                        paths_at(&segs, group[start..i].trim_start(), out);
                        return;
                    }
                    '}' => depth -= 1,
                    ',' if depth == 0 => {
                        paths_at(&segs, group[start..i].trim_start(), out);
                        start = i + 1;
                    }
                    _ => {}
                }
            }
            paths_at(&segs, group[start..].trim_start(), out);
            return;
        }
        let word: String = rest.chars().take_while(|c| is_ident(*c)).collect();
        if word.is_empty() || word == "self" {
            break;
        }
        rest = &rest[word.len()..];
        segs.push(word);
        match rest.strip_prefix("::") {
            Some(r) => rest = r,
            None => break,
        }
    }
    if segs.len() > prefix.len() || prefix.is_empty() {
        out.push(segs);
    }
}

/// Every `crate::`/`super::` path of a file's code, resolved to absolute module segments.
fn file_paths(rel: &str, text: &str) -> Vec<Vec<String>> {
    let module = module_of(rel);
    let mut out = Vec::new();
    // Inline modules open at a brace depth: (depth, name).
    let mut inline: Vec<(i32, String)> = Vec::new();
    let mut depth = 0i32;
    for line in text.lines() {
        let code = line.trim_start();
        if code.starts_with("//") {
            continue;
        }
        let head = code.strip_prefix("pub ").unwrap_or(code);
        if let Some(name) = head.strip_prefix("mod ") {
            let name: String = name.chars().take_while(|c| is_ident(*c)).collect();
            if code.trim_end().ends_with('{') {
                inline.push((depth, name));
            }
        }
        let here: Vec<String> = module
            .iter()
            .cloned()
            .chain(inline.iter().map(|(_, n)| n.clone()))
            .collect();
        for (kw, base) in [
            ("crate::", Vec::new()),
            ("super::", here[..here.len().saturating_sub(1)].to_vec()),
        ] {
            let mut from = 0;
            while let Some(i) = code[from..].find(kw) {
                let at = from + i;
                from = at + kw.len();
                if code[..at].chars().next_back().is_some_and(is_ident) {
                    continue;
                }
                paths_at(&base, &code[from..], &mut out);
            }
        }
        for c in code.chars() {
            match c {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if inline.last().is_some_and(|(d, _)| *d == depth) {
                        inline.pop();
                    }
                }
                _ => {}
            }
        }
    }
    out
}

/// Reads every `.rs` file under `src` (path relative to `src`, text).
pub(crate) fn read_tree(src: &Path) -> Result<BTreeMap<String, String>, String> {
    let mut files = BTreeMap::new();
    let mut dirs = vec![src.to_path_buf()];
    while let Some(dir) = dirs.pop() {
        for entry in fs::read_dir(&dir).map_err(|e| format!("{}: {e}", dir.display()))? {
            let path = entry.map_err(|e| e.to_string())?.path();
            if path.is_dir() {
                dirs.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let rel = path.strip_prefix(src).map_err(|e| e.to_string())?;
                let rel = rel.to_string_lossy().replace('\\', "/");
                let text = fs::read_to_string(&path).map_err(|e| format!("{rel}: {e}"))?;
                files.insert(rel, text);
            }
        }
    }
    Ok(files)
}

/// The import graph of the files under `src`.
pub(crate) fn graph(src: &Path) -> Result<Graph, String> {
    let files = read_tree(src)?;
    let modules: BTreeMap<Vec<String>, &String> = files.keys().map(|f| (module_of(f), f)).collect();
    let mut defs: BTreeMap<String, BTreeSet<&String>> = BTreeMap::new();
    for (rel, text) in &files {
        for name in text.lines().filter_map(defined) {
            defs.entry(name).or_default().insert(rel);
        }
    }
    let mut graph = Graph::new();
    for (rel, text) in &files {
        let edges = graph.entry(rel.clone()).or_default();
        for path in file_paths(rel, text) {
            let Some(k) = (1..=path.len())
                .rev()
                .find(|k| modules.contains_key(&path[..*k]))
            else {
                continue;
            };
            let file = modules[&path[..k]];
            let Some(item) = path.get(k) else {
                edges.insert(file.clone());
                continue;
            };
            let owners = defs.get(item);
            if owners.is_some_and(|o| o.contains(file)) {
                edges.insert(file.clone());
                continue;
            }
            let below: Vec<&&String> = owners
                .into_iter()
                .flatten()
                .filter(|f| module_of(f).starts_with(&path[..k]))
                .collect();
            if below.is_empty() {
                edges.insert(file.clone());
            }
            edges.extend(below.into_iter().map(|f| (*f).clone()));
        }
        edges.remove(rel);
    }
    Ok(graph)
}

/// The pairs of files that name each other, each pair sorted, the list sorted.
pub(crate) fn mutual(graph: &Graph) -> Vec<(String, String)> {
    let mut pairs = Vec::new();
    for (a, names) in graph {
        for b in names.iter().filter(|b| a < *b) {
            if graph.get(b).is_some_and(|back| back.contains(a)) {
                pairs.push((a.clone(), b.clone()));
            }
        }
    }
    pairs
}

#[cfg(test)]
mod tests {
    use super::*;

    fn paths(rel: &str, text: &str) -> Vec<String> {
        file_paths(rel, text).iter().map(|p| p.join("::")).collect()
    }

    #[test]
    fn plain_grouped_and_nested_paths_are_read() {
        assert_eq!(
            paths(
                "scene/walk.rs",
                "use crate::{surface::{Frame, band::{A, B}}, math::Fx};\nlet x = crate::scene::f();"
            ),
            ["surface::Frame", "surface::band::A", "surface::band::B", "math::Fx", "scene::f"]
        );
    }

    #[test]
    fn super_is_the_parent_module_and_one_lower_inside_an_inline_module() {
        let text = "use super::mesh::Mesh;\n#[cfg(test)]\nmod tests {\n    use super::Walker;\n}\nuse super::X;";
        assert_eq!(
            paths("scene/walk.rs", text),
            ["scene::mesh::Mesh", "scene::walk::Walker", "scene::X"]
        );
    }

    #[test]
    fn definitions_are_read_through_visibility_and_qualifiers() {
        assert_eq!(
            defined("pub(crate) const fn recip(x: u32)"),
            Some("recip".into())
        );
        assert_eq!(defined("pub struct Frame<'a, C> {"), Some("Frame".into()));
        assert_eq!(defined("    fn shade(&self)"), Some("shade".into()));
        assert_eq!(defined("pub use band::Binned;"), None);
    }
}
