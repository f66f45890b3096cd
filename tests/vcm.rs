//! Vertex connection and merging (`--integrator vcm`, docs/integrators.md): its weights
//! checked by what they must reduce to (no merging: BDPT's image; no connections:
//! progressive photon mapping), and its estimate against analytic answers and references.
//!
//! Merging shares every light vertex of an iteration among all pixels, so pixels are not
//! independent estimates: standard errors here come from independent replicates (seeds), the
//! statistic of each replicate being a whole-image or a block mean.

mod common;

use bidir::imaging::{metrics::block_means, read_exr, RgbImage};
use bidir::render::vcm::{VcmMode, VcmRadius};
use bidir::render::{Integrator, Join, Mis, RenderSettings, Renderer};
use bidir::scene::Scene;
use common::{finish, gpu, scenes::furnace_scene};
use std::path::Path;

const NO_MERGE: Integrator = Integrator::Vcm(VcmMode::NO_MERGE);
const NO_CONNECT: Integrator = Integrator::Vcm(VcmMode::NO_CONNECT);
const MERGE_ALL: Integrator = Integrator::Vcm(VcmMode::MERGE_ALL);
const VCM: Integrator = Integrator::Vcm(VcmMode::FULL);
const SHARP: &str = "../shared/references/cornell-box/reference-bidir-h200.exr";
/// Largest |t| accepted. Replicates give t with `REPLICATES - 1` degrees of freedom: with 9,
/// P(|t| > 6) is about 2e-4 per statistic.
const T_MAX: f64 = 6.0;
const REPLICATES: u32 = 10;

/// Renders `spp` samples per pixel of `scene`'s first camera once per seed.
fn render(scene: &Scene, settings: RenderSettings, spp: u32, seeds: std::ops::RangeInclusive<u32>) -> Vec<RgbImage> {
    let ctx = gpu();
    let name = settings.integrator.name();
    let mut r = Renderer::new(&ctx, scene, &scene.cameras[0], settings).unwrap();
    let mut images = Vec::new();
    for seed in seeds {
        r.set_seed(seed).unwrap();
        r.render_spp(spp, |_| {}).unwrap();
        images.push(r.image().unwrap());
    }
    assert_eq!(r.nan_samples().unwrap(), 0, "{name}: NaN/Inf samples");
    drop(r);
    finish(ctx);
    images
}

/// Whole-image mean over pixels and channels.
fn image_mean(img: &RgbImage) -> f64 {
    img.mean().iter().sum::<f64>() / 3.0
}

/// Small images of the Cornell box (the reference's camera at 1/4 the resolution, so a pixel
/// is the mean of 4 x 4 reference pixels).
fn small_cornell(size: u32) -> Scene {
    let mut scene = Scene::builtin_cornell_box();
    scene.cameras[0].width = size;
    scene.cameras[0].height = size;
    scene
}

/// With merging off VCM's weights are BDPT's (eta_VCM = 0 removes every merging term), so
/// `vcm:no-merge` and `bdpt` (the same join, `Join::DEFAULT`) give the same image for the
/// same seed and MIS heuristic (`--mis`: BDPT takes the balance heuristic on this diffuse box
/// by default, VCM the power heuristic; both are run under each), with light tracing a
/// strategy of direct lighting (`--direct-light-tracing`) or not (the default): the same
/// kernels with dVM carried but unused, the same random numbers (so both take VCM's light
/// paths per pixel and connection candidates, BDPT's defaults in diffuse scenes being others;
/// and 4 shared candidates once).
/// Not always to the last bit: light tracing
/// splats with float atomics whose order varies from run to run (as BDPT against itself), so
/// values may differ by a few ulps (measured: at most 2e-7 relative; a weight error would show
/// at 1e-3 or more).
#[test]
fn no_merge_equals_bdpt() {
    let scene = small_cornell(32);
    for (direct_light_tracing, mis, candidates) in
        [(false, Mis::Power, 1), (true, Mis::Power, 1), (false, Mis::Balance, 1), (false, Mis::Balance, 4)]
    {
        let settings = |integrator| {
            let mut s = RenderSettings::new(integrator);
            s.direct_light_tracing = direct_light_tracing;
            s.mis = Some(mis);
            s.light_path_ratio = Some(1.0);
            s.connection_candidates = Some(candidates);
            // VCM's camera pass is a megakernel: so must BDPT's be (GPUs default to its
            // wavefront form), whose lanes then share candidates as VCM's do.
            s.wavefront = Some(false);
            s
        };
        let a = render(&scene, settings(Integrator::Bdpt(Join::DEFAULT)), 2, 3..=3).remove(0);
        let b = render(&scene, settings(NO_MERGE), 2, 3..=3).remove(0);
        let differ = a.data.iter().zip(&b.data).filter(|(x, y)| x != y).count();
        let rel = a.data.iter().zip(&b.data).map(|(x, y)| ((x - y).abs() / x.abs().max(1e-6)) as f64).fold(0.0, f64::max);
        let mean = image_mean(&a);
        eprintln!(
            "vcm:no-merge vs bdpt (direct light tracing {direct_light_tracing}, {mis:?} heuristic, {candidates} candidates): {differ} of {} values differ, by at most {rel:.1e} relative (image mean {mean:.5})",
            a.data.len()
        );
        assert!(mean > 0.01, "the image is lit");
        assert!(rel < 2e-6, "vcm:no-merge differs from bdpt by {rel:e} relative: more than float atomics' rounding");
    }
}

/// The furnace (radiance exactly 2): merging a uniform photon density is unbiased on a
/// sphere at any radius (its area within distance r of a point on it is pi r^2), so VCM must
/// hit the analytic answer, judged by replicates. At the default radius merging has a
/// fraction of a percent of the weight; at 2 % of the diagonal it is comparable to the
/// connections', so a merging term counted at a vertex where that strategy does not run (or
/// missed where it does) shows as energy lost (or gained): counting merging at every camera
/// vertex while merging at the first only loses 2.2 % (t -9.6; measured when this test was
/// written).
#[test]
fn furnace() {
    let mut scene = furnace_scene(0.5, 1.0);
    scene.cameras[0].width = 32;
    scene.cameras[0].height = 32;
    // Also with 3 camera samples per iteration (as GPUs run small images): merging then
    // shares the light paths of all 3 and divides by their number, light tracing by one
    // sample's.
    let moderate = VcmRadius::Relative(0.02);
    for (integrator, slices, spp, radius) in
        [(VCM, 1, 2, VcmRadius::default()), (VCM, 3, 3, VcmRadius::default()), (VCM, 1, 4, moderate), (MERGE_ALL, 1, 4, moderate)]
    {
        let mut s = RenderSettings::new(integrator);
        s.sample_slices = slices;
        s.vcm_radius = radius;
        let means: Vec<Vec<f64>> = render(&scene, s, spp, 1..=REPLICATES).iter().map(|i| vec![image_mean(i)]).collect();
        let (mean, se) = common::stats::replicate_mean_se(&means)[0];
        let (err, t) = (mean / 2.0 - 1.0, (mean - 2.0) / se);
        eprintln!(
            "{}, {slices} sample(s) per iteration, radius {radius:?}: furnace mean {mean:.5} expected 2 ({:+.3} %), se {:.3} %, t {t:.2}",
            integrator.name(),
            100.0 * err,
            50.0 * se
        );
        assert!(3.0 * se / 2.0 < 0.005, "too noisy to resolve 0.5 %");
        assert!(err.abs() < 0.005 && t.abs() < T_MAX, "furnace mean {mean} vs 2 ({:+.3} %, t {t:.2})", 100.0 * err);
    }
}

/// Channel means, then per block the mean of its pixels and channels.
fn statistics(img: &RgbImage, block: u32) -> Vec<f64> {
    let mut s: Vec<f64> = img.mean().to_vec();
    s.extend(block_means(img, block).iter().map(|(_, _, m)| (m[0] + m[1] + m[2]) / 3.0));
    s
}

/// The sharp reference, box-filtered to `size` x `size`: channel means, then the means of
/// blocks of `block` x `block` pixels of that size.
fn reference(size: u32, block: u32) -> Option<Vec<f64>> {
    if !Path::new(SHARP).exists() {
        eprintln!("skipping: {SHARP} is absent");
        return None;
    }
    let img = read_exr(Path::new(SHARP)).expect("reference reads");
    Some(statistics(&img, block * img.width / size))
}

/// (mean, standard error) of each statistic.
type Stats = Vec<(f64, f64)>;

const SIZE: u32 = 64;
const BLOCK: u32 = 16;

/// (mean, se) of each statistic of `integrator` minus `bdpt` (`Join::DEFAULT`, as VCM connects) over REPLICATES seeds, and
/// of `integrator` alone. Same seed, same sample indices: the camera and light paths are the
/// same random numbers, so the difference has a small fraction of either's variance (0.014 %
/// against 0.85 % of the mean measured here) and is the bias of `integrator` relative to an
/// unbiased estimator that `tests/render_cornell.rs` checks against the references.
fn paired(
    integrator: Integrator,
    settings: impl Fn(&mut RenderSettings),
    spp: u32,
    replicates: u32,
    scene_change: Option<&dyn Fn(&mut Scene)>,
) -> (Stats, Stats) {
    let mut scene = small_cornell(SIZE);
    if let Some(change) = scene_change {
        change(&mut scene);
    }
    let mut s = RenderSettings::new(Integrator::Bdpt(Join::DEFAULT));
    settings(&mut s);
    // VCM's light paths per pixel and connection candidates where `settings` does not say (BDPT
    // takes 0.4 light paths and 8 candidates by default in diffuse scenes): the pairing
    // needs both integrators to draw the same paths.
    s.light_path_ratio.get_or_insert(1.0);
    s.connection_candidates.get_or_insert(1);
    let base = render(&scene, s.clone(), spp, 1..=replicates);
    s.integrator = integrator;
    let est = render(&scene, s, spp, 1..=replicates);
    let stats: Vec<Vec<f64>> = est.iter().map(|i| statistics(i, BLOCK)).collect();
    let diffs: Vec<Vec<f64>> =
        base.iter().zip(&stats).map(|(b, e)| statistics(b, BLOCK).iter().zip(e).map(|(b, e)| e - b).collect()).collect();
    (common::stats::replicate_mean_se(&diffs), common::stats::replicate_mean_se(&stats))
}

/// Checks `integrator` on the Cornell box: its difference from BDPT (paired, see [`paired`])
/// per channel mean within `tolerance` of the reference's mean; with `unbiased_blocks` also
/// every statistic's difference within T_MAX standard errors (the blur of a finite radius is
/// then too small to see); and itself against the sharp reference within T_MAX of its own
/// (larger) standard error, per channel and per 16 x 16 block.
fn cornell(integrator: Integrator, settings: impl Fn(&mut RenderSettings), spp: u32, tolerance: f64, unbiased_blocks: bool) {
    let Some(reference) = reference(SIZE, BLOCK) else { return };
    let name = integrator.name();
    let (diff, est) = paired(integrator, settings, spp, REPLICATES, None);
    let mut worst_t = 0.0f64;
    for (i, (((d, se_d), (m, se)), r)) in diff.iter().zip(&est).zip(&reference).enumerate() {
        let (t_d, t_ref) = (d / se_d, (m - r) / se);
        if i < 3 {
            eprintln!(
                "{name}: channel {i}: minus bdpt {:+.3} % (se {:.3} %, t {t_d:.2}); against the reference {:+.3} % (se {:.3} %, t {t_ref:.2})",
                100.0 * d / r,
                100.0 * se_d / r,
                100.0 * (m / r - 1.0),
                100.0 * se / r
            );
            assert!(3.0 * se_d / r < tolerance, "{name}: channel {i}: too noisy to resolve {:.2} %", 100.0 * tolerance);
            assert!((d / r).abs() < tolerance, "{name}: channel {i} differs from bdpt by {:+.3} %", 100.0 * d / r);
        }
        worst_t = worst_t.max(if unbiased_blocks { t_d.abs() } else { 0.0 }).max(t_ref.abs());
        assert!(
            !unbiased_blocks || t_d.abs() < T_MAX,
            "{name}: statistic {i} (channels, then blocks) differs from bdpt by {d:.2e}, t {t_d:.2}"
        );
        assert!(t_ref.abs() < T_MAX, "{name}: statistic {i} (channels, then blocks): {m:.5} vs reference {r:.5}, t {t_ref:.2}");
    }
    eprintln!("{name}: worst |t| over channels and blocks {worst_t:.2}");
}

/// VCM with its default radius (0.5 % of the scene's diagonal, shrinking as i^-1/8) on the
/// Cornell box: mean within 0.5 % of the reference.
#[test]
fn cornell_vcm_matches_reference() {
    cornell(VCM, |_| {}, 1, 0.005, true);
}

/// Merging at every continuous camera vertex (Georgiev et al. 2012's strategy set), as above.
#[test]
fn cornell_vcm_merge_all_matches_reference() {
    cornell(MERGE_ALL, |_| {}, 1, 0.005, true);
}

/// The other kinds of light (a uniform environment through the open front, a point light, a
/// directional light) weigh merging through their own start and light-sampling terms: VCM
/// paired with BDPT on the Cornell box lit by all of them at once.
#[test]
fn other_lights_paired_with_bdpt() {
    use bidir::scene::{Environment, PunctualKind, PunctualLight};
    let light = |kind, position: glam::Vec3, direction: glam::Vec3, intensity: glam::Vec3| PunctualLight {
        name: "test".into(),
        kind,
        position,
        direction: direction.normalize(),
        intensity,
    };
    let lights = vec![
        light(PunctualKind::Point, glam::Vec3::new(150.0, 400.0, 250.0), glam::Vec3::Y, glam::Vec3::splat(2.0e4)),
        light(PunctualKind::Directional, glam::Vec3::ZERO, glam::Vec3::new(0.3, -0.3, 1.0), glam::Vec3::splat(0.5)),
    ];
    let (diff, est) = paired(
        VCM,
        |_| {},
        1,
        REPLICATES,
        Some(&|scene: &mut Scene| {
            scene.environment = Some(Environment::uniform(glam::Vec3::splat(0.5)));
            scene.punctual_lights = lights.clone();
        }),
    );
    let mut worst = 0.0f64;
    for (i, ((d, se_d), (m, _))) in diff.iter().zip(&est).enumerate() {
        let t = d / se_d;
        worst = worst.max(t.abs());
        if i < 3 {
            eprintln!("vcm, all lights: channel {i}: minus bdpt {:+.3} % (se {:.3} %, t {t:.2})", 100.0 * d / m, 100.0 * se_d / m);
            assert!(3.0 * se_d / m < 0.005 && (d / m).abs() < 0.005, "channel {i} differs from bdpt by {:+.3} %", 100.0 * d / m);
        }
        assert!(t.abs() < T_MAX, "statistic {i} (channels, then blocks) differs from bdpt by {d:.2e}, t {t:.2}");
    }
    eprintln!("vcm, all lights: worst |t| {worst:.2}");
}

/// Progressive photon mapping (merging alone, unweighted; 8 light paths per pixel, since it
/// has no other strategy) agrees with the reference too: its image mean within 0.5 %. Its
/// blocks carry the blur of its radius (at 1.5 % of the diagonal, 17 standard errors of the
/// paired difference in one block, +5.7 % against the reference), so they are judged against
/// the reference's own noise only, at half that radius (at the default 0.5 % the paired
/// difference's standard error, 0.18 %, is too large to resolve 0.5 % in this test's time).
#[test]
fn cornell_photon_mapping_matches_reference() {
    cornell(
        NO_CONNECT,
        |s| {
            s.light_path_ratio = Some(8.0);
            s.vcm_radius = VcmRadius::Relative(0.0075);
        },
        1,
        0.005,
        false,
    );
}

/// VCM is consistent, not unbiased: merging blurs the light, so with a large first radius
/// (5 % of the diagonal) the image is biased; the radius shrinks as r_i = r_1 i^((alpha - 1)
/// / 2), so the same samples taken at iteration 4096 (radius 0.35 r_1) must be much less
/// biased. Bias measured as VCM minus BDPT for the same samples (see [`paired`]): the root mean
/// square over 16 x 16 blocks with the noise's share removed (blur moves light between places;
/// the whole image's mean, printed too, gains and loses at once and need not fall steadily).
#[test]
fn cornell_bias_shrinks() {
    let bias = |start: u32| {
        let (diff, _) = paired(
            VCM,
            |s| {
                s.vcm_radius = VcmRadius::Relative(0.05);
                s.sample_start = start;
            },
            1,
            6,
            None,
        );
        let mean: f64 = diff[..3].iter().map(|(d, _)| d).sum::<f64>() / 3.0;
        let mean_se = (diff[..3].iter().map(|(_, se)| se * se).sum::<f64>()).sqrt() / 3.0;
        let blocks = &diff[3..];
        let ms = blocks.iter().map(|(d, se)| d * d - se * se).sum::<f64>() / blocks.len() as f64;
        (mean, mean_se, ms.max(0.0).sqrt())
    };
    let (m1, se1, b1) = bias(0);
    let (m2, se2, b2) = bias(4095);
    eprintln!("VCM - BDPT, first radius 5 % of the diagonal: iteration 1: mean {m1:+.5} (se {se1:.5}), block rms {b1:.5}; iteration 4096: mean {m2:+.5} (se {se2:.5}), block rms {b2:.5}");
    assert!(b1 > 0.002, "the large radius shows no bias: the test cannot see it shrink");
    assert!(b2 < 0.5 * b1, "the bias did not shrink with the radius");
}

const SDS_SCENE: &str = "assets/scenes/sds/sds.obj";
const SDS_REFERENCE: &str = "assets/scenes/sds/reference-lavapipe-vcm.exr";

/// The SDS scene's camera (assets/scenes/sds/README.md) at the reference's 64 x 64.
fn sds_camera() -> bidir::scene::Camera {
    bidir::scene::Camera {
        name: "sds".into(),
        eye: glam::Vec3::new(0.9, 1.3, -3.2),
        target: glam::Vec3::new(-0.4, 0.4, 0.0),
        up: glam::Vec3::Y,
        fov_y_deg: 50.0,
        width: 64,
        height: 64,
    }
}

fn sds_scene() -> Scene {
    let mut scene = bidir::scene::load(Path::new(SDS_SCENE), &Default::default()).unwrap().scene;
    scene.cameras = vec![sds_camera()];
    scene
}

/// Where VCM must win: a caustic seen in a mirror (eye - mirror - floor - glass - glass -
/// light), which no BDPT connection samples. At an equal number of samples per pixel VCM's
/// RMSE against the reference must be below BDPT's, merging at the first continuous camera
/// vertex (the default) and at all; the MSE ratios are reported.
#[test]
fn sds_vcm_beats_bdpt_at_equal_samples() {
    let reference = read_exr(Path::new(SDS_REFERENCE)).expect("the SDS reference is committed beside the scene");
    let scene = sds_scene();
    let mut mse = Vec::new();
    for integrator in [Integrator::Bdpt(Join::DEFAULT), VCM, MERGE_ALL] {
        let t = std::time::Instant::now();
        let img = render(&scene, RenderSettings::new(integrator), 8, 1..=1).remove(0);
        let e = bidir::imaging::metrics::rmse(&img, &reference);
        eprintln!("{}: 8 spp in {:.1} s, RMSE {e:.5}", integrator.name(), t.elapsed().as_secs_f64());
        mse.push(e * e);
    }
    eprintln!("equal-spp MSE ratio bdpt / vcm: {:.2}; bdpt / vcm:merge-all: {:.2}", mse[0] / mse[1], mse[0] / mse[2]);
    assert!(mse[1] < mse[0], "VCM must beat BDPT on the SDS scene (MSE {:.3e} vs {:.3e})", mse[1], mse[0]);
    assert!(mse[2] < mse[0], "vcm:merge-all must beat BDPT on the SDS scene (MSE {:.3e} vs {:.3e})", mse[2], mse[0]);
}

/// Merging at the first camera vertex with a continuous component only (`vcm`) and at every
/// continuous vertex (`vcm:merge-all`) are two sets of strategies over the same paths, each
/// weighted to sum to one, so for the same seeds (merging draws no random numbers: the same
/// camera and light paths) the two images differ only by how each path's contribution is
/// split: their paired difference must vanish in expectation. On the SDS scene the paths pass
/// mirrors and glass before and after the first continuous vertex, which is where the two
/// weightings differ most; a light-side merging term left in or a camera-side one dropped at
/// the wrong vertex shows here as a bias. Twice: as it is, and with the mirror made mostly
/// diffuse (a vertex with both a continuous and a delta lobe: `vcm` merges there and not
/// after its mirror lobe, `vcm:merge-all` after it too). Judged per channel (0.5 %) and per
/// 16 x 16 block (t).
#[test]
fn sds_merge_first_agrees_with_merge_all() {
    for mixed in [false, true] {
        let mut scene = sds_scene();
        if mixed {
            let mirror = scene.materials.iter_mut().find(|m| m.name == "mirror").expect("the SDS scene has a mirror");
            mirror.albedo = glam::Vec3::splat(0.5);
            mirror.reflectivity = 0.3;
        }
        let stats = |integrator| -> Vec<Vec<f64>> {
            render(&scene, RenderSettings::new(integrator), 6, 1..=REPLICATES).iter().map(|i| statistics(i, BLOCK)).collect()
        };
        let (first, all) = (stats(VCM), stats(MERGE_ALL));
        let diffs: Vec<Vec<f64>> = first.iter().zip(&all).map(|(f, a)| f.iter().zip(a).map(|(f, a)| f - a).collect()).collect();
        let diff = common::stats::replicate_mean_se(&diffs);
        let est = common::stats::replicate_mean_se(&all);
        let what = if mixed { "SDS scene, mirror 0.5 diffuse + 0.3 mirror" } else { "SDS scene" };
        let mut worst = 0.0f64;
        for (i, ((d, se_d), (m, _))) in diff.iter().zip(&est).enumerate() {
            let t = if *se_d > 0.0 { d / se_d } else { 0.0 };
            worst = worst.max(t.abs());
            if i < 3 {
                eprintln!("vcm minus vcm:merge-all, {what}: channel {i}: {:+.3} % (se {:.3} %, t {t:.2})", 100.0 * d / m, 100.0 * se_d / m);
                assert!(3.0 * se_d / m < 0.005, "{what}: channel {i}: too noisy to resolve 0.5 %");
                assert!((d / m).abs() < 0.005, "{what}: channel {i}: vcm differs from vcm:merge-all by {:+.3} %", 100.0 * d / m);
            }
            assert!(t.abs() < T_MAX, "{what}: statistic {i} (channels, then blocks): vcm differs from vcm:merge-all by {d:.2e}, t {t:.2}");
        }
        eprintln!("vcm minus vcm:merge-all, {what}: worst |t| over channels and blocks {worst:.2}");
    }
}
