//! The library's layers, checked: every `crate::` path in `src/<module>` must name a module of
//! a lower layer (docs/architecture.md). A use of a module of the same or a higher layer — an
//! arrow pointing up or sideways, the start of a circle — fails here with the file and line.
//! The binary (`src/main.rs`, `src/cli/`) is the top layer and may use every module.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};

/// Layer of each top-level module of `src/lib.rs`, from the bottom. A module may use only
/// modules of a strictly lower layer.
const LAYERS: &[(&str, u32)] = &[
    ("text", 0),
    ("limits", 0),
    ("vk", 1),
    ("scene", 1),
    ("imaging", 1),
    ("gpu", 2),
    ("compute", 3),
    ("bvh", 3),
    ("gpu_data", 4),
    ("trace", 5),
    ("render", 6),
    ("viewer", 7),
    ("bench", 7),
];

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The top-level modules a line of code names through `crate::`, including grouped imports
/// (`use crate::{a::X, b::Y}`).
fn crate_paths(code: &str) -> Vec<String> {
    let mut out = Vec::new();
    let ident = |s: &str| s.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect::<String>();
    let mut rest = code;
    while let Some(i) = rest.find("crate::") {
        let after = &rest[i + "crate::".len()..];
        if let Some(group) = after.strip_prefix('{') {
            // The brace that closes the group (groups nest: `crate::{a::{X, Y}, b}`).
            let mut level = 0;
            let end = group
                .char_indices()
                .find(|&(_, c)| {
                    level += (c == '{') as i32 - (c == '}') as i32;
                    level < 0
                })
                .map_or(group.len(), |(j, _)| j);
            // Top-level names of the group: the first identifier of each comma-separated item
            // at nesting depth 0.
            let (mut depth, mut start) = (0, 0);
            let bytes = &group.as_bytes()[..end];
            for (j, &b) in bytes.iter().enumerate().chain(std::iter::once((end, &b','))) {
                match b {
                    b'{' => depth += 1,
                    b'}' => depth -= 1,
                    b',' if depth == 0 => {
                        let item = ident(group[start..j].trim_start());
                        if !item.is_empty() {
                            out.push(item);
                        }
                        start = j + 1;
                    }
                    _ => {}
                }
            }
        } else {
            out.push(ident(after));
        }
        rest = after;
    }
    out
}

#[test]
fn every_arrow_between_modules_points_down() {
    let layers: BTreeMap<&str, u32> = LAYERS.iter().copied().collect();
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let lib = fs::read_to_string(src.join("lib.rs")).unwrap();
    // Every module the library declares has a layer (a new module must be placed).
    for line in lib.lines() {
        if let Some(name) = line.trim().strip_prefix("pub mod ").and_then(|s| s.strip_suffix(';')) {
            assert!(
                layers.contains_key(name),
                "src/lib.rs declares module `{name}`: give it a layer in tests/layers.rs and docs/architecture.md"
            );
        }
    }
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let mut violations = Vec::new();
    let mut arrows = 0;
    for file in &files {
        let rel = file.strip_prefix(&src).unwrap();
        let top = rel.components().next().unwrap().as_os_str().to_string_lossy().trim_end_matches(".rs").to_string();
        let Some(&from) = layers.get(top.as_str()) else { continue }; // lib.rs, main.rs, cli/
        let text = fs::read_to_string(file).unwrap();
        for (n, line) in text.lines().enumerate() {
            let code = line.split("//").next().unwrap();
            for target in crate_paths(code) {
                if target == top {
                    continue;
                }
                arrows += 1;
                match layers.get(target.as_str()) {
                    Some(&to) if to < from => {}
                    Some(&to) => {
                        violations.push(format!("src/{}:{}: `{top}` (layer {from}) uses `{target}` (layer {to})", rel.display(), n + 1))
                    }
                    None => {
                        violations.push(format!("src/{}:{}: `{top}` uses `{target}`, which is not a library layer", rel.display(), n + 1))
                    }
                }
            }
        }
    }
    assert!(arrows > 50, "found only {arrows} crate:: paths: the scan is broken");
    assert!(violations.is_empty(), "arrows pointing up or sideways:\n{}", violations.join("\n"));
}

#[test]
fn the_scan_sees_grouped_and_plain_paths() {
    assert_eq!(crate_paths("use crate::{bvh::{Bvh, TriTest}, gpu::abi};"), ["bvh", "gpu"]);
    assert_eq!(crate_paths("let x = crate::trace::gpu_camera(c) + crate::vk::X;"), ["trace", "vk"]);
    assert!(crate_paths("let y = 1;").is_empty());
}
