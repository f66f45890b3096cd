//! Where BDPT must win: a glass sphere focusing a small light onto the floor
//! (`assets/scenes/caustic`). The caustic is reached by light paths, hardly by path tracing
//! with light sampling (its shadow rays hit the glass). At equal render time BDPT's RMSE
//! against a long reference render must be lower than pt-nee's; the MSE ratio is reported.

mod common;

use bidir::film::{metrics, read_exr};
use bidir::render::{Integrator, Join, RenderSettings, Renderer};
use bidir::scene::Camera;
use common::{finish, gpu};
use glam::Vec3;
use std::path::Path;
use std::time::Duration;

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

#[test]
fn bdpt_beats_pt_nee_at_equal_time_on_a_caustic() {
    let reference = read_exr(Path::new(REFERENCE)).expect("the caustic reference is committed beside the scene");
    let scene = bidir::scene::load(Path::new(SCENE), &Default::default()).unwrap().scene;
    let cam = caustic_camera();
    let ctx = gpu();
    // Long enough on lavapipe for a few dozen BDPT samples per pixel; GPUs get far more.
    let time = Duration::from_secs_f64(if ctx.info().device_type == bidir::vk::PhysicalDeviceType::CPU { 12.0 } else { 1.0 });
    let mut mse = Vec::new();
    for integrator in [Integrator::PtNee, Integrator::Bdpt(Join::Full)] {
        let mut r = Renderer::new(&ctx, &scene, &cam, RenderSettings::new(integrator)).unwrap();
        r.render_time(time, |_| {}).unwrap();
        let img = r.image().unwrap();
        let e = metrics::rmse(&img, &reference);
        let ratio = metrics::mean_ratio(&img, &reference);
        eprintln!("{}: {} spp in {:?}, RMSE {e:.5}, mean ratio {:.4} {:.4} {:.4}", integrator.name(), r.samples(), time, ratio[0], ratio[1], ratio[2]);
        if integrator != Integrator::PtNee {
            // BDPT is nearly converged here: its mean must match the reference.
            for r in ratio {
                assert!((r - 1.0).abs() < 0.01, "bdpt mean ratio {r:.4} vs the caustic reference");
            }
        }
        mse.push(e * e);
        drop(r);
    }
    eprintln!("equal-time MSE ratio pt-nee / bdpt: {:.2}", mse[0] / mse[1]);
    assert!(mse[1] < mse[0], "BDPT must beat pt-nee at equal time on the caustic (MSE {:.3e} vs {:.3e})", mse[1], mse[0]);
    finish(ctx);
}
