//! Parts of a render merge exactly (issue #19): disjoint sample ranges merged equal one
//! render of their union, crop windows merged equal the uncropped render (every pixel within
//! 1e-5 relative: only float summation order differs), and mismatched parts are refused.

mod common;

use bidir::imaging::merge::merge;
use bidir::imaging::part::{keys, read_part, write_part, Accumulation, Part, RenderInfo};
use bidir::imaging::{Crop, RgbImage, SampleRange};
use bidir::render::{Integrator, Join, RenderSettings, Renderer};
use bidir::scene::{Camera, Scene};
use common::{finish, gpu};
use std::path::PathBuf;

fn cornell() -> (Scene, Camera) {
    let scene = Scene::builtin_cornell_box();
    // Not a multiple of the 8x8 tiles, so windows cut tiles.
    let camera = Camera { width: 20, height: 14, ..scene.cameras[0].clone() };
    (scene, camera)
}

/// Sums of samples `range` of `crop` (None: the whole image).
fn render(ctx: &bidir::vk::Context, integrator: Integrator, range: SampleRange, crop: Option<Crop>, slices: u32) -> Accumulation {
    let (scene, camera) = cornell();
    let mut s = RenderSettings::new(integrator);
    s.seed = 7;
    s.sample_start = range.start;
    s.crop = crop;
    s.sample_slices = slices;
    let mut r = Renderer::new(ctx, &scene, &camera, s).unwrap();
    r.render_spp(range.len(), |_| {}).unwrap();
    assert_eq!(r.samples(), range.len());
    r.sums().unwrap()
}

fn info(integrator: Integrator, seed: u32, crop: Crop, range: SampleRange) -> RenderInfo {
    let mut i = RenderInfo::default();
    i.set(keys::SCENE_HASH, "test");
    i.set(keys::CAMERA, "cornell");
    i.set(keys::FULL_SIZE, "20x14");
    i.set(keys::CROP, crop.to_string());
    i.set(keys::INTEGRATOR, integrator.name());
    i.set(keys::SETTINGS, "test");
    i.set(keys::SEED, seed.to_string());
    i.set(keys::SAMPLE_RANGE, range.to_string());
    i
}

fn dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("bidir-parts-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Writes each part as EXR and reads it back (the merge sees what `bidir merge` sees).
fn through_files(name: &str, parts: Vec<(Accumulation, RenderInfo, Crop)>) -> Vec<(PathBuf, Part)> {
    let d = dir(name);
    parts
        .into_iter()
        .enumerate()
        .map(|(i, (sums, info, crop))| {
            let p = d.join(format!("part{i}.exr"));
            write_part(&p, &sums, &info, crop).unwrap();
            let part = read_part(&p).unwrap();
            (p, part)
        })
        .collect()
}

/// Every channel of every pixel within 1e-5 relative.
fn assert_same(what: &str, a: &RgbImage, b: &RgbImage) {
    assert_eq!((a.width, a.height), (b.width, b.height), "{what}: sizes");
    let mut worst = 0.0f64;
    for (i, (x, y)) in a.data.iter().zip(&b.data).enumerate() {
        let (x, y) = (*x as f64, *y as f64);
        let rel = (x - y).abs() / x.abs().max(y.abs()).max(1e-30);
        worst = worst.max(rel);
        assert!(rel <= 1e-5, "{what}: pixel {} channel {}: {x} vs {y} ({rel:.2e} relative)", i / 3, i % 3);
    }
    let mean = a.mean();
    assert!(mean[0] > 0.0, "{what}: a black image proves nothing");
    eprintln!("{what}: worst relative difference {worst:.2e}, mean {:.4}", mean[0]);
}

fn ranges_merge(integrator: Integrator, slices: u32, split: &[u32]) {
    let ctx = gpu();
    let full = Crop::full(20, 14);
    let whole = SampleRange { start: split[0], end: *split.last().unwrap() };
    let one = render(&ctx, integrator, whole, None, slices);
    let parts: Vec<_> = split
        .windows(2)
        .map(|w| {
            let r = SampleRange { start: w[0], end: w[1] };
            (render(&ctx, integrator, r, None, slices), info(integrator, 7, full, r), full)
        })
        .collect();
    let name = format!("ranges-{}-{slices}", integrator.name().replace(':', "-"));
    let merged = merge(&through_files(&name, parts)).unwrap();
    assert!(merged.warnings.is_empty(), "{:?}", merged.warnings);
    assert_eq!(merged.part.sums.spp, whole.len() as u64);
    assert_eq!(merged.part.info.get(keys::SAMPLE_RANGE), Some(whole.to_string().as_str()));
    assert_same(&format!("{} ranges {split:?}", integrator.name()), &merged.part.sums.resolve(), &one.resolve());
    // The film's own resolve agrees with the sums' (the EXR's R, G, B are the estimate).
    finish(ctx);
}

#[test]
fn sample_ranges_merge_pt_nee() {
    ranges_merge(Integrator::PtNee, 0, &[0, 3, 8]);
}

#[test]
fn sample_ranges_merge_bdpt_joins() {
    for join in [Join::Full, Join::K(1), Join::K(3), Join::Lvc(0)] {
        ranges_merge(Integrator::Bdpt(join), 0, &[0, 3, 7]);
    }
}

/// Iterations of several samples (sample slices) start at multiples of the slice count, so
/// ranges on those boundaries split the light vertex cache's iterations exactly.
#[test]
fn sample_ranges_merge_sliced_lvc() {
    ranges_merge(Integrator::Bdpt(Join::Lvc(0)), 4, &[0, 4, 12]);
    ranges_merge(Integrator::PtNee, 3, &[2, 5, 11]);
}

fn crops_merge(integrator: Integrator) {
    let ctx = gpu();
    let range = SampleRange { start: 0, end: 6 };
    let one = render(&ctx, integrator, range, None, 0);
    let windows = [
        Crop { x0: 0, y0: 0, x1: 9, y1: 5 },
        Crop { x0: 9, y0: 0, x1: 20, y1: 5 },
        Crop { x0: 0, y0: 5, x1: 9, y1: 14 },
        Crop { x0: 9, y0: 5, x1: 20, y1: 14 },
    ];
    let parts: Vec<_> = windows.iter().map(|&c| (render(&ctx, integrator, range, Some(c), 0), info(integrator, 7, c, range), c)).collect();
    let merged = merge(&through_files(&format!("crops-{}", integrator.name().replace(':', "-")), parts)).unwrap();
    assert_eq!(merged.part.crop, Crop::full(20, 14));
    assert_same(&format!("{} four crops", integrator.name()), &merged.part.sums.resolve(), &one.resolve());
    finish(ctx);
}

#[test]
fn crops_merge_pt_nee() {
    crops_merge(Integrator::PtNee);
}

#[test]
fn crops_merge_bdpt() {
    crops_merge(Integrator::Bdpt(Join::Lvc(0)));
    crops_merge(Integrator::Bdpt(Join::Full));
}

/// BDPT's default join on the diffuse box resamples each connection from 8 candidates whose
/// reads the connecting lanes share (glsl/common/bdpt_camera_path.glsl). The candidates belong
/// to a block of pixels, not to the lanes that happen to connect together, so crop windows that
/// cut the blocks (and the subgroups) and sample ranges still give the whole render's image.
/// (Session 38's lane pools took them from the lanes: these 4 crops merged at RMSE 0.0026 from
/// the whole render at 6 spp; the ranges guard the same for sample ranges and slices.)
#[test]
fn parts_merge_bdpt_with_shared_candidates() {
    crops_merge(Integrator::Bdpt(Join::DEFAULT));
    ranges_merge(Integrator::Bdpt(Join::DEFAULT), 0, &[0, 3, 7]);
    ranges_merge(Integrator::Bdpt(Join::DEFAULT), 4, &[0, 4, 12]);
}

/// Parts that are not of one render are refused, naming the mismatch and the files.
#[test]
fn mismatched_parts_are_refused() {
    let (w, h) = (4, 3);
    let sums = |light: bool| {
        let mut a = Accumulation::new(w, h, light);
        a.camera.iter_mut().for_each(|p| *p = [1.0, 2.0, 3.0, 2.0]);
        a
    };
    let i = Integrator::PtNee;
    let full = Crop { x0: 0, y0: 0, x1: 4, y1: 3 };
    let r = |a, b| SampleRange { start: a, end: b };
    let info_wh = |seed, crop: Crop, range| {
        let mut x = info(i, seed, crop, range);
        x.set(keys::FULL_SIZE, "8x3");
        x
    };
    let case = |name: &str, parts: Vec<(Accumulation, RenderInfo, Crop)>| match merge(&through_files(name, parts)) {
        Ok(_) => panic!("{name}: merged"),
        Err(e) => e.to_string(),
    };
    let right = Crop { x0: 4, y0: 0, x1: 8, y1: 3 };
    let e = case("seed", vec![(sums(false), info_wh(1, full, r(0, 4)), full), (sums(false), info_wh(2, full, r(4, 8)), full)]);
    assert!(e.contains("seed differs") && e.contains("part0.exr") && e.contains("part1.exr"), "{e}");
    let mut other = info_wh(1, full, r(4, 8));
    other.set(keys::INTEGRATOR, "bdpt:lvc");
    let e = case("integrator", vec![(sums(false), info_wh(1, full, r(0, 4)), full), (sums(false), other, full)]);
    assert!(e.contains("integrator differs") && e.contains("pt-nee") && e.contains("bdpt:lvc"), "{e}");
    let e = case("overlap", vec![(sums(false), info_wh(1, full, r(0, 4)), full), (sums(false), info_wh(1, full, r(3, 8)), full)]);
    assert!(e.contains("0..4") && e.contains("3..8") && e.contains("overlap"), "{e}");
    let gap = Crop { x0: 5, y0: 0, x1: 8, y1: 3 };
    let e =
        case("hole", vec![(sums(false), info_wh(1, full, r(0, 4)), full), (Accumulation::new(3, 3, false), info_wh(1, gap, r(0, 4)), gap)]);
    assert!(e.contains("tiles are missing") && e.contains("pixel 4,0"), "{e}");
    let e = case("tile-ranges", vec![(sums(false), info_wh(1, full, r(0, 4)), full), (sums(false), info_wh(1, right, r(0, 5)), right)]);
    assert!(e.contains("different sample ranges"), "{e}");
    // Missing samples are reported, not refused: the merge is still unbiased.
    let m =
        merge(&through_files("gap", vec![(sums(false), info_wh(1, full, r(0, 4)), full), (sums(false), info_wh(1, full, r(6, 8)), full)]))
            .unwrap();
    // ... as is a merge that covers only part of the image (here the left 4x3 of 8x3).
    assert_eq!(m.warnings.len(), 2, "{:?}", m.warnings);
    assert!(m.warnings.iter().any(|w| w.contains("window 0,0,4,3 of the 8x3 image")), "{:?}", m.warnings);
    assert!(m.warnings.iter().any(|w| w.contains("samples 4..6 are missing")), "{:?}", m.warnings);
    assert_eq!(m.part.sums.spp, 6);
}
