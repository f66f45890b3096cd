//! Where BDPT must win: a glass sphere focusing a small light onto the floor
//! (`assets/scenes/caustic`). The caustic is reached by light paths, hardly by path tracing
//! with light sampling (its shadow rays hit the glass). At equal sample counts (a fixed seed:
//! deterministic) BDPT's MSE (the default join, the light vertex cache) against a long
//! reference render must be lower than pt-nee's by more than a BDPT sample costs in pt-nee
//! samples, so that it wins at equal time. No time is measured here: the cost ratio comes from
//! the benchmarks (`bidir render --time 1`, caustic scene 128²: 1.4 on the H200, 20,966 against
//! 15,057 spp, docs/results.md; 1.75 on lavapipe in CI, 490 against 280 spp in 12 s), and the
//! test asks for the larger. (Until session 14 it raced the two for 12 s on lavapipe, which
//! made its outcome depend on the load of the machine: BDPT got 222 to 281 spp.)
//!
//! And where the light hides: the Cornell box with a panel under its light, which then reaches
//! the room only off the panel and the ceiling (`bdpt_beats_pt_nee_where_the_light_hides`).

mod common;

use bidir::imaging::{metrics, read_exr};
use bidir::render::{Integrator, Join, RenderSettings, Renderer};
use bidir::scene::Camera;
use common::{finish, gpu};
use glam::Vec3;
use std::path::Path;

const SCENE: &str = "assets/scenes/caustic/caustic.obj";
const REFERENCE: &str = "assets/scenes/caustic/reference.exr";

pub fn caustic_camera() -> Camera {
    Camera {
        name: "caustic".into(),
        // Framed on the caustic and the sphere's shadow around it.
        eye: Vec3::new(0.0, 1.0, -2.0),
        target: Vec3::new(0.0, 0.15, -0.2),
        up: Vec3::Y,
        fov_y_deg: 35.0,
        width: 128,
        height: 128,
    }
}

/// BDPT's MSE per sample over pt-nee's that makes it win at equal time on every device
/// measured (module doc).
const COST_RATIO: f64 = 1.75;
/// Samples per pixel of each render: ~6 s (pt-nee) and ~11 s (bdpt) on lavapipe.
const SPP: u32 = 256;

#[test]
fn bdpt_beats_pt_nee_at_equal_time_on_a_caustic() {
    let reference = read_exr(Path::new(REFERENCE)).expect("the caustic reference is committed beside the scene");
    let scene = bidir::scene::load(Path::new(SCENE), &Default::default()).unwrap().scene;
    let cam = caustic_camera();
    let ctx = gpu();
    let mut mse = Vec::new();
    for integrator in [Integrator::PtNee, Integrator::Bdpt(Join::DEFAULT)] {
        let mut r = Renderer::new(&ctx, &scene, &cam, RenderSettings::new(integrator)).unwrap();
        r.render_spp(SPP, |_| {}).unwrap();
        let img = r.image().unwrap();
        let e = metrics::rmse(&img, &reference);
        let ratio = metrics::mean_ratio(&img, &reference);
        eprintln!("{}: {SPP} spp, RMSE {e:.5}, mean ratio {:.4} {:.4} {:.4}", integrator.name(), ratio[0], ratio[1], ratio[2]);
        mse.push(e * e);
        if integrator != Integrator::PtNee {
            // BDPT's mean must match the reference within 4 standard errors of the image
            // mean, estimated from the variance across pixels: a loose check (~11 %, the
            // spread of the scene's own pixel values, whatever the sample count; the H200 at
            // 8,192 spp gave 10.6 %). BDPT's bias is tested tightly by the furnace and Cornell
            // tests.
            let px: Vec<f64> = img.data.chunks_exact(3).map(|c| (c[0] + c[1] + c[2]) as f64).collect();
            let n = px.len() as f64;
            let mean = px.iter().sum::<f64>() / n;
            let var = px.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0);
            let rel_se = (var / n).sqrt() / mean;
            let m = (ratio[0] + ratio[1] + ratio[2]) / 3.0;
            eprintln!("bdpt mean ratio {m:.4}, 4 standard errors {:.2} %", 400.0 * rel_se);
            assert!((m - 1.0).abs() < 4.0 * rel_se, "bdpt mean ratio {m:.4} vs the caustic reference (4 sigma {:.4})", 4.0 * rel_se);
        }
        drop(r);
    }
    // Seeds 0 to 3 gave 2.62, 2.55, 1.98 and 2.51 (session 14).
    let per_sample = mse[0] / mse[1];
    eprintln!("MSE ratio pt-nee / bdpt at {SPP} spp: {per_sample:.2} (must exceed the cost ratio {COST_RATIO})");
    assert!(
        per_sample > COST_RATIO,
        "BDPT's MSE per sample on the caustic is only {per_sample:.2}x below pt-nee's ({:.3e} vs {:.3e}): it would not win at equal time where a BDPT sample costs {COST_RATIO} pt-nee samples",
        mse[1],
        mse[0]
    );
    finish(ctx);
}

/// The Cornell box with a diffuse panel (250 x 220) 48 units under its light, facing it: the
/// room is lit only by what the panel's top throws onto the ceiling. Light sampling then finds
/// nothing from most of the room (the panel shadows it), so pt-nee's estimate rests on paths
/// that reach the light by chance; BDPT's light paths reach the ceiling (its connections and
/// light tracing carry that light). Each integrator renders the same 64 x 64 image with seeds 1
/// and 2 (deterministic); half the MSE between the two is its variance per pixel, so no
/// reference is needed. Per sample, pt-nee's variance must exceed BDPT's by `HIDDEN_MARGIN`,
/// twice a BDPT sample's cost in pt-nee samples (2.9 on the H200, less on lavapipe): seeds 1
/// and 2 give 17.1, the pairs 3-4, 5-6, 7-8 12.9, 11.2, 18.5 (pt-nee's error here is rare
/// bright paths, so its estimate from two renders spreads; at 128² and 1024 spp it was ~50).
#[test]
fn bdpt_beats_pt_nee_where_the_light_hides() {
    const HIDDEN_MARGIN: f64 = 6.0;
    const OBJ: &str = include_str!("../assets/cornell-box.obj");
    const MTL: &str = include_str!("../assets/cornell-box.mtl");
    let vertices = OBJ.lines().filter(|l| l.starts_with("v ")).count();
    let obj = format!(
        "{OBJ}\no panel\nusemtl floor\nv 400 500 170\nv 150 500 170\nv 150 500 390\nv 400 500 390\nf {a} {b} {c}\nf {a} {c} {d}\n",
        a = vertices + 1,
        b = vertices + 2,
        c = vertices + 3,
        d = vertices + 4
    );
    let mtl = |name: &str| (name == "cornell-box.mtl").then(|| MTL.to_owned());
    let scene = bidir::scene::load_obj_str("hidden-light.obj", &obj, &mtl, &bidir::scene::LoadOptions { strict: true }).unwrap().scene;
    let mut cam = Camera::cornell_box();
    cam.width = 64;
    cam.height = 64;
    let ctx = gpu();
    let mut variance = Vec::new();
    for (integrator, spp) in [(Integrator::PtNee, 256), (Integrator::Bdpt(Join::DEFAULT), 32)] {
        let mut images = Vec::new();
        for seed in [1, 2] {
            let mut settings = RenderSettings::new(integrator);
            settings.seed = seed;
            let mut r = Renderer::new(&ctx, &scene, &cam, settings).unwrap();
            r.render_spp(spp, |_| {}).unwrap();
            assert_eq!(r.nan_samples().unwrap(), 0);
            images.push(r.image().unwrap());
        }
        let mean = images[0].mean();
        assert!(mean.iter().all(|&m| m > 0.01), "{}: the room is lit ({mean:?})", integrator.name());
        let e = metrics::rmse(&images[0], &images[1]);
        let per_sample = e * e / 2.0 * spp as f64;
        eprintln!(
            "{} where the light hides: {spp} spp, RMSE between seeds {e:.5}, variance per sample {per_sample:.3e}",
            integrator.name()
        );
        variance.push(per_sample);
    }
    let ratio = variance[0] / variance[1];
    eprintln!("variance per sample, pt-nee / bdpt: {ratio:.1} (must exceed {HIDDEN_MARGIN})");
    assert!(
        ratio > HIDDEN_MARGIN,
        "where the light hides BDPT's variance per sample is only {ratio:.1}x below pt-nee's, expected more than {HIDDEN_MARGIN}x"
    );
    finish(ctx);
}
