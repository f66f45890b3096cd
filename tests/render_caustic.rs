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
