//! A new user's first render of the glTF sample models (`../shared/scenes/gltf-samples`):
//! every model renders non-black with the default settings; one without an emitter says so
//! in one warning line and is lit by the default white environment (`--env none` keeps it
//! dark); a model without a camera is framed from +Z, its front. Skipped with a message when
//! the models are absent.

use std::path::{Path, PathBuf};
use std::process::Command;

const SAMPLES: &str = "../shared/scenes/gltf-samples";
const WARNING: &str = "no emitter, no punctual light and no --env: lit by a uniform white environment of radiance 1";

fn models() -> Option<Vec<PathBuf>> {
    let dir = Path::new(SAMPLES);
    if !dir.is_dir() {
        eprintln!("skipping: {SAMPLES} is absent");
        return None;
    }
    let mut found = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap() {
        let sub = entry.unwrap().path();
        if !sub.is_dir() {
            continue;
        }
        for f in std::fs::read_dir(&sub).unwrap() {
            let f = f.unwrap().path();
            if matches!(f.extension().and_then(|e| e.to_str()), Some("gltf") | Some("glb")) {
                found.push(f);
            }
        }
    }
    found.sort();
    assert!(!found.is_empty(), "no .gltf/.glb under {SAMPLES}");
    Some(found)
}

fn bidir(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_bidir")).args(args).env("BIDIR_VALIDATION", "1").output().expect("bidir runs");
    (out.status.success(), String::from_utf8_lossy(&out.stdout).into_owned(), String::from_utf8_lossy(&out.stderr).into_owned())
}

/// Mean of a tiny render of `model` with `extra` flags, and bidir's stderr.
fn tiny_render(model: &Path, extra: &[&str]) -> (f64, String) {
    let exr = std::env::temp_dir().join(format!(
        "bidir-gltf-default-{}-{}.exr",
        std::process::id(),
        model.file_stem().unwrap().to_string_lossy()
    ));
    let mut args = vec!["render", model.to_str().unwrap(), "--width", "24", "--height", "16", "--spp", "2", "-o", exr.to_str().unwrap()];
    args.extend(extra);
    let (ok, _, err) = bidir(&args);
    assert!(ok, "bidir render {} failed:\n{err}", model.display());
    let img = bidir::imaging::read_exr(&exr).unwrap();
    std::fs::remove_file(&exr).unwrap();
    (img.data.iter().map(|&v| v as f64).sum::<f64>() / img.data.len() as f64, err)
}

#[test]
fn every_sample_model_renders_lit_by_default() {
    let Some(models) = models() else { return };
    for model in &models {
        let scene = bidir::scene::load(model, &Default::default()).unwrap().scene;
        let (mean, err) = tiny_render(model, &[]);
        let warned = err.matches(WARNING).count();
        eprintln!("{}: mean {mean:.4}, emitters {}, default-light warnings {warned}", model.display(), scene.emitters().len());
        assert!(mean > 0.0 && mean.is_finite(), "{}: black or non-finite image by default (mean {mean})", model.display());
        let expect = usize::from(scene.emitters().is_empty());
        assert_eq!(warned, expect, "{}: expected {expect} default-light warning(s), stderr:\n{err}", model.display());
    }
}

#[test]
fn env_none_keeps_an_unlit_model_dark() {
    let Some(models) = models() else { return };
    let model = models.iter().find(|m| m.to_string_lossy().contains("CesiumMilkTruck")).expect("CesiumMilkTruck");
    let (mean, err) = tiny_render(model, &["--env", "none"]);
    assert_eq!(mean, 0.0, "--env none: nothing should light the truck");
    assert!(!err.contains(WARNING), "--env none should not warn:\n{err}");
}

/// `bidir info` reports the framing camera of a model without cameras: it looks along -Z.
#[test]
fn cameraless_models_are_framed_from_the_front() {
    let Some(models) = models() else { return };
    let mut framed = 0;
    for model in &models {
        let (ok, out, err) = bidir(&["info", model.to_str().unwrap()]);
        assert!(ok, "bidir info {} failed:\n{err}", model.display());
        let Some(line) = out.lines().find(|l| l.starts_with("camera used:") && l.contains("framing")) else {
            continue;
        };
        let vec_after = |key: &str| -> [f64; 3] {
            let s = &line[line.find(key).unwrap() + key.len()..];
            let s = &s[s.find('(').unwrap() + 1..s.find(')').unwrap()];
            let v: Vec<f64> = s.split(',').map(|x| x.trim().parse().unwrap()).collect();
            [v[0], v[1], v[2]]
        };
        let (eye, target) = (vec_after("eye"), vec_after("target"));
        assert!(
            eye[2] > target[2] && (eye[0] - target[0]).abs() < 1e-3,
            "{}: framed from {eye:?} toward {target:?}, not from +Z",
            model.display()
        );
        framed += 1;
    }
    eprintln!("{framed} camera-less models framed from +Z");
    assert!(framed > 0, "no camera-less model among the samples");
}

/// KHR_lights_punctual: the lamp's five point lights are read, placed by their nodes.
#[test]
fn punctual_lights_are_read_from_gltf() {
    let Some(models) = models() else { return };
    let lamp = models.iter().find(|m| m.to_string_lossy().contains("LightsPunctualLamp")).expect("LightsPunctualLamp");
    let loaded = bidir::scene::load(lamp, &Default::default()).unwrap();
    let lights = &loaded.scene.punctual_lights;
    assert_eq!(lights.len(), 5, "{lights:?}");
    assert!(lights.iter().all(|l| l.kind == bidir::scene::PunctualKind::Point && l.intensity.min_element() > 0.0));
    let bright = lights.iter().find(|l| l.name == "Point.004").expect("Point.004");
    assert!((bright.position - glam::Vec3::new(0.292, 1.0324, 1.5589)).length() < 1e-3, "{:?}", bright.position);
    assert!(!loaded.warnings.iter().any(|w| w.contains("KHR_lights_punctual")), "{:?}", loaded.warnings);
}
