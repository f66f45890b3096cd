//! `bidir render --sample-range/--crop`, `bidir merge` and `bidir info IMAGE.exr` end to end
//! (the binary, on the built-in Cornell box, validation on).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn bidir(args: &[&str]) -> Output {
    let out = Command::new(env!("CARGO_BIN_EXE_bidir")).args(args).env("BIDIR_VALIDATION", "1").output().unwrap();
    eprintln!("bidir {}:\n{}{}", args.join(" "), String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    out
}

fn ok(args: &[&str]) -> String {
    let out = bidir(args);
    assert!(out.status.success(), "bidir {} failed", args.join(" "));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!err.to_lowercase().contains("validation"), "validation messages: {err}");
    String::from_utf8_lossy(&out.stdout).into_owned()
}

fn dir() -> PathBuf {
    let d = std::env::temp_dir().join(format!("bidir-cli-parts-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn render_ranges_merge_info_and_refusal() {
    let d = dir();
    let (a, b, whole, merged, png) = (d.join("a.exr"), d.join("b.exr"), d.join("whole.exr"), d.join("merged.exr"), d.join("merged.png"));
    let common = ["render", "--width", "16", "--height", "12", "--seed", "3"];
    fn with<'a>(common: &[&'a str], extra: &[&'a str]) -> Vec<&'a str> {
        common.iter().chain(extra).copied().collect()
    }
    ok(&with(&common, &["--sample-range", "0..3", "-o", s(&a)]));
    // The second part runs the other kernel form (layout, regeneration): the same estimator,
    // so it merges, and the metadata keeps both forms.
    ok(&with(&common, &["--sample-range", "3..8", "--crop", "0,0,16,12", "--bvh", "bvh2", "--path-regeneration", "off", "-o", s(&b)]));
    ok(&with(&common, &["--spp", "8", "-o", s(&whole)]));
    let out = ok(&["merge", s(&a), s(&b), "-o", s(&merged), "-o", s(&png)]);
    assert!(out.contains("samples 0..8 (8 spp)"), "{out}");
    assert!(png.exists());
    // The merge equals the whole render (every pixel within 1e-5 relative).
    let (m, w) = (bidir::imaging::read_exr(&merged).unwrap(), bidir::imaging::read_exr(&whole).unwrap());
    for (x, y) in m.data.iter().zip(&w.data) {
        assert!((x - y).abs() <= 1e-5 * x.abs().max(y.abs()), "{x} vs {y}");
    }
    let info = ok(&["info", s(&merged)]);
    for key in [
        "version",
        "scene_hash",
        "camera",
        "full_size",
        "16x12",
        "crop",
        "0,0,16,12",
        "integrator",
        "pt-nee",
        "settings",
        "seed",
        "sample_range",
        "0..8",
        "spp",
        "render_time_s",
        "merged_from",
        "kernels",
    ] {
        assert!(info.contains(key), "bidir info lacks {key}:\n{info}");
    }
    assert!(info.contains("bvh2, path regeneration off"), "the second part's kernel form is lost:\n{info}");
    // Another seed: refused, naming the key and both files; nothing written.
    let c = d.join("c.exr");
    let refused = d.join("refused.exr");
    ok(&["render", "--width", "16", "--height", "12", "--seed", "4", "--sample-range", "8..10", "-o", s(&c)]);
    let out = bidir(&["merge", s(&a), s(&c), "-o", s(&refused), "-o", s(&d.join("refused.png"))]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("seed differs") && err.contains("a.exr") && err.contains("c.exr"), "{err}");
    assert!(!refused.exists() && !d.join("refused.png").exists(), "a refused merge wrote output");
    // An EXR without bidir's sums is refused by name.
    let plain = d.join("plain.exr");
    bidir::imaging::write_image(&plain, &w, 0.0).unwrap();
    let out = bidir(&["merge", s(&a), s(&plain), "-o", s(&refused)]);
    assert!(!out.status.success() && String::from_utf8_lossy(&out.stderr).contains("plain.exr"));
    std::fs::remove_dir_all(&d).ok();
}

/// BDPT's parts record the MIS heuristic that ran (`--mis`, resolved for the scene): on the
/// diffuse Cornell box the default is the balance heuristic, so a part rendered with `--mis
/// balance` merges with a default one, and one with `--mis power` (another estimator of the
/// same image, with other noise) is refused by its settings.
#[test]
fn bdpt_parts_merge_only_under_one_mis_heuristic_and_candidate_count() {
    // A folder of its own: the other test removes `dir()` when it ends.
    let d = std::env::temp_dir().join(format!("bidir-cli-parts-mis-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    let (a, b, c, out) = (d.join("a.exr"), d.join("b.exr"), d.join("c.exr"), d.join("out.exr"));
    let common = ["render", "--width", "16", "--height", "12", "--seed", "3", "--integrator", "bdpt"];
    let with = |extra: &[&str]| -> Vec<String> { common.iter().chain(extra).map(|x| x.to_string()).collect() };
    let run = |args: Vec<String>| ok(&args.iter().map(String::as_str).collect::<Vec<_>>());
    run(with(&["--sample-range", "0..2", "-o", s(&a)]));
    run(with(&["--sample-range", "2..4", "--mis", "balance", "-o", s(&b)]));
    run(with(&["--sample-range", "4..6", "--mis", "power", "-o", s(&c)]));
    let e = d.join("e.exr");
    run(with(&["--sample-range", "4..6", "--connection-candidates", "4", "-o", s(&e)]));
    let merged = ok(&["merge", s(&a), s(&b), "-o", s(&out)]);
    assert!(merged.contains("samples 0..4 (4 spp)"), "{merged}");
    assert!(ok(&["info", s(&out)]).contains("mis Balance"), "the heuristic is not recorded");
    assert!(ok(&["info", s(&e)]).contains("connection_candidates 4"), "the connections' candidates are not recorded");
    for other in [&c, &e] {
        let refused = bidir(&["merge", s(&a), s(other), "-o", s(&d.join("refused.exr"))]);
        assert!(!refused.status.success());
        let err = String::from_utf8_lossy(&refused.stderr);
        assert!(err.contains("settings differs"), "{err}");
        assert!(!d.join("refused.exr").exists(), "a refused merge wrote output");
    }
    std::fs::remove_dir_all(&d).ok();
}
