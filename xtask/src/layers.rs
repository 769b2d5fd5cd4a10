//! The stage order of `src/` (`math -> geometry -> raster -> texture -> shading -> pipeline
//! -> surface -> scene`), checked: a file of one stage may name
//! (`crate::stage` in code, comments aside) only its own stage or a lower one; and no two
//! files name each other ([`crate::imports`]). Both tests run in CI (`cargo test`).

use std::path::Path;

/// The stages, lowest first. Top-level files (`error.rs`, `color.rs`, `fill.rs`, `lib.rs`) are below
/// every stage; `guide` is documentation.
pub(crate) const ORDER: [&str; 8] = [
    "math", "geometry", "raster", "texture", "shading", "pipeline", "surface", "scene",
];

fn rank(stage: &str) -> Option<usize> {
    ORDER.iter().position(|s| *s == stage)
}

/// The stages a line of code names through `crate::` (`crate::a::..` and the groups of
/// `crate::{a::.., b::..}`).
fn named(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = line;
    while let Some(i) = rest.find("crate::") {
        rest = &rest[i + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let end = group.find('}').unwrap_or(group.len());
            for item in group[..end].split(',') {
                let word: String = item
                    .trim()
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                out.push(word);
            }
        } else {
            out.push(
                rest.chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect(),
            );
        }
    }
    out
}

/// Every upward reference under `src`: (path relative to `src`, the stage named), sorted.
pub(crate) fn upward(src: &Path) -> Result<Vec<(String, String)>, String> {
    let mut found = Vec::new();
    for (rel, text) in crate::imports::read_tree(src)? {
        let stage = rel.split('/').next().unwrap_or("").trim_end_matches(".rs");
        let Some(own) = rank(stage) else { continue };
        for line in text.lines().filter(|l| !l.trim_start().starts_with("//")) {
            for name in named(line) {
                if rank(&name).is_some_and(|r| r > own) {
                    found.push((rel.clone(), name));
                }
            }
        }
    }
    found.sort();
    found.dedup();
    Ok(found)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_stages_of_src_depend_one_way() {
        let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("../src");
        let found = upward(&src).unwrap();
        assert!(
            found.is_empty(),
            "files naming a higher stage ({}): {found:?}; move the shared type down to the \
             stage that owns it",
            ORDER.join(" -> ")
        );
    }

    /// A file that names another may not be named by it: shared items move to a third file
    /// (or down a stage), so each file can be read knowing only the ones it names.
    #[test]
    fn no_two_files_of_src_name_each_other() {
        let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("../src");
        let graph = crate::imports::graph(&src).unwrap();
        let pairs = crate::imports::mutual(&graph);
        assert!(
            pairs.is_empty(),
            "{} pairs of files name each other: {pairs:#?}",
            pairs.len()
        );
    }

    #[test]
    fn grouped_and_plain_paths_are_both_read() {
        assert_eq!(
            named("use crate::{surface::Frame, math::Fx}; let x = crate::scene::f();"),
            ["surface", "math", "scene"]
        );
    }
}
