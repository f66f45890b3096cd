//! Punctual (delta) lights in pt-nee and every BDPT join:
//! - a point light of intensity I at height h over a diffuse plane of albedo rho: each pixel
//!   shows rho / pi * I cos(theta) / r^2 (no interreflection), integrated here over the pixel;
//! - a spot, a point and a directional light over a non-convex scene: pt-nee and every BDPT
//!   join agree block by block within their noise.
//!
//! Plain path tracing cannot find a delta light (no ray hits one): it renders such a scene
//! black, as every path tracer without light sampling does.

mod common;

use bidir::imaging::RgbImage;
use bidir::render::{Integrator, Join, RenderSettings, Renderer};
use bidir::scene::{Camera, Material, PunctualKind, PunctualLight, Scene};
use common::{finish, geometry, gpu};
use glam::Vec3;

fn add(scene: &mut Scene, (positions, tris): (Vec<Vec3>, Vec<[u32; 3]>), m: u32) {
    let base = scene.positions.len() as u32;
    scene.positions.extend(positions);
    scene.material_ids.extend(std::iter::repeat_n(m, tris.len()));
    scene.triangles.extend(tris.into_iter().map(|t| t.map(|i| i + base)));
}

fn render(scene: &Scene, integrator: Integrator, spp: u32) -> RgbImage {
    let ctx = gpu();
    let mut r = Renderer::new(&ctx, scene, &scene.cameras[0], RenderSettings::new(integrator)).unwrap();
    assert!(r.gpu_scene().features.punctual);
    assert_eq!(r.gpu_scene().features.env, scene.environment.is_some());
    r.render_spp(spp, |_| {}).unwrap();
    let img = r.image().unwrap();
    assert_eq!(r.nan_samples().unwrap(), 0, "{}: NaN/Inf samples", integrator.name());
    drop(r);
    finish(ctx);
    img
}

fn mean_and_se(v: &[f64]) -> (f64, f64) {
    let n = v.len() as f64;
    let mean = v.iter().sum::<f64>() / n;
    let var = v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, (var / n).sqrt())
}

const RHO: f32 = 0.5;
const H: f32 = 1.0;
const I: f32 = 3.0;

/// The plane y = 0 (a 20 x 20 quad facing up) under a point light at (0.3, H, -0.2), seen
/// from above at an angle.
fn plane_scene() -> Scene {
    let mut s = Scene { source: "test:point-over-plane".into(), ..Default::default() };
    s.materials.push(Material { name: "plane".into(), albedo: Vec3::splat(RHO), ..Default::default() });
    let quad = (
        vec![Vec3::new(-10.0, 0.0, -10.0), Vec3::new(-10.0, 0.0, 10.0), Vec3::new(10.0, 0.0, 10.0), Vec3::new(10.0, 0.0, -10.0)],
        vec![[0, 1, 2], [0, 2, 3]],
    );
    add(&mut s, quad, 0);
    s.cameras.push(Camera {
        name: "above".into(),
        eye: Vec3::new(0.5, 2.5, 1.5),
        target: Vec3::new(0.2, 0.0, -0.1),
        up: Vec3::Y,
        fov_y_deg: 50.0,
        width: 32,
        height: 32,
    });
    s.punctual_lights.push(PunctualLight {
        name: "point".into(),
        kind: PunctualKind::Point,
        position: Vec3::new(0.3, H, -0.2),
        direction: Vec3::ZERO,
        intensity: Vec3::splat(I),
    });
    s
}

/// The analytic image: rho / pi * I cos / r^2 at the plane point each ray meets, averaged over
/// 8 x 8 points of each pixel (the film's box filter).
fn analytic(scene: &Scene) -> Vec<f64> {
    let cam = &scene.cameras[0];
    let light = scene.punctual_lights[0].position.as_dvec3();
    let eye = cam.eye.as_dvec3();
    let mut out = Vec::new();
    for j in 0..cam.height {
        for i in 0..cam.width {
            let mut sum = 0.0;
            for k in 0..64 {
                let (x, y) = (i as f32 + (k % 8) as f32 / 8.0 + 1.0 / 16.0, j as f32 + (k / 8) as f32 / 8.0 + 1.0 / 16.0);
                let d = cam.ray_direction(x, y).as_dvec3();
                let p = eye + d * (-eye.y / d.y);
                let v = light - p;
                let r2 = v.length_squared();
                sum += RHO as f64 / std::f64::consts::PI * I as f64 * (v.y / r2.sqrt()) / r2;
            }
            out.push(sum / 64.0);
        }
    }
    out
}

#[test]
fn point_light_irradiance_is_i_cos_over_r2() {
    let scene = plane_scene();
    let expect = analytic(&scene);
    let (expect_mean, _) = mean_and_se(&expect);
    for (integrator, spp) in [
        (Integrator::PtNee, 16),
        (Integrator::Bdpt(Join::Full), 32),
        (Integrator::Bdpt(Join::K(1)), 32),
        (Integrator::Bdpt(Join::Lvc(0)), 32),
    ] {
        let img = render(&scene, integrator, spp);
        // Per pixel, the relative error (pixels differ by up to ~10x across the image).
        let rel: Vec<f64> = img.data.chunks_exact(3).zip(&expect).map(|(c, e)| (c[0] + c[1] + c[2]) as f64 / 3.0 / e - 1.0).collect();
        let (err, se) = mean_and_se(&rel);
        let worst = rel.iter().fold(0.0f64, |a, r| a.max(r.abs()));
        eprintln!("point light over a plane, {}: mean relative error {:+.3} % (4 sigma {:.3} %), worst pixel {:.2} %, expected mean {expect_mean:.5}", integrator.name(), 100.0 * err, 400.0 * se, 100.0 * worst);
        assert!(4.0 * se < 0.005, "{}: too noisy to resolve 0.5 %", integrator.name());
        assert!(err.abs() < 0.005 && err.abs() < 4.0 * se.max(1e-5), "{}: irradiance off by {:+.3} %", integrator.name(), 100.0 * err);
    }
    // Plain path tracing cannot find a delta light.
    assert!(render(&scene, Integrator::Pt, 2).data.iter().all(|&v| v == 0.0));
}

/// The box [-1, 1]^3 without its top, a sphere inside, lit by a spot from above, a point light
/// inside and a low directional light.
fn lit_box_scene() -> Scene {
    let mut s = Scene { source: "test:punctual-box".into(), ..Default::default() };
    s.materials.push(Material { name: "box".into(), albedo: Vec3::splat(0.7), ..Default::default() });
    s.materials.push(Material { name: "sphere".into(), albedo: Vec3::new(0.8, 0.5, 0.3), ..Default::default() });
    let c =
        |i: u32| Vec3::new(if i & 1 == 0 { -1.0 } else { 1.0 }, if i & 2 == 0 { -1.0 } else { 1.0 }, if i & 4 == 0 { -1.0 } else { 1.0 });
    let quads = [[0u32, 1, 5, 4], [0, 4, 6, 2], [1, 3, 7, 5], [0, 2, 3, 1], [4, 5, 7, 6]];
    add(&mut s, ((0..8).map(c).collect(), quads.iter().flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]).collect()), 0);
    add(&mut s, geometry::icosphere(2, Vec3::new(0.2, -0.5, 0.1), 0.45), 1);
    s.cameras.push(Camera {
        name: "test".into(),
        eye: Vec3::new(1.6, 3.2, 2.4),
        target: Vec3::new(0.0, -0.4, 0.0),
        up: Vec3::Y,
        fov_y_deg: 45.0,
        width: 48,
        height: 48,
    });
    let spot = PunctualKind::Spot { inner: 0.25, outer: 0.5 };
    s.punctual_lights.push(PunctualLight {
        name: "spot".into(),
        kind: spot,
        position: Vec3::new(-0.3, 2.0, 0.2),
        direction: Vec3::new(0.2, -1.0, -0.1).normalize(),
        intensity: Vec3::new(20.0, 16.0, 12.0),
    });
    s.punctual_lights.push(PunctualLight {
        name: "point".into(),
        kind: PunctualKind::Point,
        position: Vec3::new(-0.5, 0.3, -0.4),
        direction: Vec3::ZERO,
        intensity: Vec3::new(1.0, 1.5, 2.0),
    });
    s.punctual_lights.push(PunctualLight {
        name: "sun".into(),
        kind: PunctualKind::Directional,
        position: Vec3::ZERO,
        direction: Vec3::new(0.5, -0.6, -0.4).normalize(),
        intensity: Vec3::splat(2.0),
    });
    s
}

#[test]
fn pt_nee_and_every_bdpt_join_agree_under_spot_point_and_directional_lights() {
    let joins = [Integrator::Bdpt(Join::Full), Integrator::Bdpt(Join::K(2)), Integrator::Bdpt(Join::K(1)), Integrator::Bdpt(Join::Lvc(0))];
    check_agreement("spot + point + directional", &lit_box_scene(), &joins);
}

/// All three kinds of light at once (light sampling picks each with probability 1/3): the
/// punctual lights, an emissive quad and a dim uniform environment.
fn every_kind_of_light_scene() -> Scene {
    let mut scene = lit_box_scene();
    let quad = bidir::scene::QuadLight::new(
        Vec3::new(-0.9, 0.6, -0.9),
        Vec3::new(0.0, 0.0, 0.5),
        Vec3::new(0.5, -0.2, 0.0),
        Vec3::new(4.0, 3.0, 1.5),
    )
    .unwrap();
    scene.add_quad_light(&quad, "quad");
    scene.environment = Some(bidir::scene::Environment::uniform(Vec3::new(0.2, 0.25, 0.35)));
    scene
}

#[test]
fn pt_nee_and_bdpt_agree_with_every_kind_of_light() {
    let scene = every_kind_of_light_scene();
    check_agreement("punctual + quad + environment", &scene, &[Integrator::Bdpt(Join::Full), Integrator::Bdpt(Join::Lvc(0))]);
}

fn check_agreement(what: &str, scene: &Scene, integrators: &[Integrator]) {
    let reference = render(scene, Integrator::PtNee, 256);
    let w = reference.width as usize;
    for &integrator in integrators {
        let img = render(scene, integrator, 128);
        let diff: Vec<f64> = img
            .data
            .chunks_exact(3)
            .zip(reference.data.chunks_exact(3))
            .map(|(x, y)| (0..3).map(|c| x[c] as f64 - y[c] as f64).sum::<f64>() / 3.0)
            .collect();
        let (mean_ref, _) = mean_and_se(&reference.data.iter().map(|&v| v as f64).collect::<Vec<_>>());
        let (d, se) = mean_and_se(&diff);
        // 8 x 8 blocks: sum of z^2 is chi-square with one degree of freedom per block.
        let (mut chi2, mut blocks) = (0.0, 0u32);
        for by in (0..reference.height as usize).step_by(8) {
            for bx in (0..w).step_by(8) {
                let b: Vec<f64> = (by..by + 8).flat_map(|y| (bx..bx + 8).map(move |x| y * w + x)).map(|k| diff[k]).collect();
                let (m, s) = mean_and_se(&b);
                // Pixels that see only the environment are exact up to the float rounding of
                // sums accumulated in passes of varying size: ~1e-7 relative, not noise.
                let level: f64 =
                    (by..by + 8).flat_map(|y| (bx..bx + 8).map(move |x| y * w + x)).map(|k| reference.data[3 * k] as f64).sum::<f64>()
                        / 64.0;
                let s = s.max(1e-5 * level.abs());
                if s > 0.0 {
                    chi2 += (m / s).powi(2);
                    blocks += 1;
                }
            }
        }
        let p = common::stats::chi2_sf(chi2, blocks.max(1));
        eprintln!(
            "{what}: {} - pt-nee {:+.3} % (4 sigma {:.3} %), blocks X^2 = {chi2:.1} dof {blocks} p = {p:.4}",
            integrator.name(),
            100.0 * d / mean_ref,
            400.0 * se / mean_ref
        );
        assert!(4.0 * se / mean_ref < 0.02, "{}: too noisy to resolve 2 %", integrator.name());
        assert!(d.abs() < 4.0 * se, "{}: mean differs from pt-nee by {:+.3} %", integrator.name(), 100.0 * d / mean_ref);
        assert!(p >= 1e-3, "{}: block means disagree with pt-nee beyond noise", integrator.name());
    }
}

/// pt-nee's `--one-trace` (the shadow ray traced in the next step, through the extension
/// rays' call) against tracing it where it is drawn, with every kind of light at once
/// (punctual, emitter, environment: each builds its shadow ray its own way): the same image,
/// to the last bits the shader compiler may round differently in the two specialisations.
/// (On CPU devices such as lavapipe the default is off, so the reference tests run that form.)
#[test]
fn one_trace_gives_the_same_image_with_every_kind_of_light() {
    let scene = every_kind_of_light_scene();
    let ctx = gpu();
    let image = |one_trace: bool| {
        let mut settings = RenderSettings::new(Integrator::PtNee);
        settings.one_trace = Some(one_trace);
        settings.pass_target = std::time::Duration::from_secs(3600);
        let mut r = Renderer::new(&ctx, &scene, &scene.cameras[0], settings).unwrap();
        r.render_spp(8, |_| {}).unwrap();
        r.image().unwrap().data
    };
    let (on, off) = (image(true), image(false));
    assert!(on.iter().filter(|&&v| v > 0.0).count() * 2 > on.len(), "a mostly black image");
    let same = on.iter().zip(&off).filter(|(a, b)| (*a - *b).abs() <= 1e-5 * a.abs()).count();
    assert_eq!(same, on.len(), "{} of {} values differ", on.len() - same, on.len());
    finish(ctx);
}

/// The wavefront path tracer (`--wavefront`) with every kind of light at once (each builds
/// its shadow ray its own way, here queued for the any-hit trace kernel): pt-nee gives the
/// megakernel's image, up to the order of the film's float sums (to 1e-5 of each value).
#[test]
fn wavefront_gives_the_same_image_with_every_kind_of_light() {
    let scene = every_kind_of_light_scene();
    let ctx = gpu();
    let image = |wavefront: bool| {
        let mut settings = RenderSettings::new(Integrator::PtNee);
        settings.wavefront = Some(wavefront);
        settings.pass_target = std::time::Duration::from_secs(3600);
        let mut r = Renderer::new(&ctx, &scene, &scene.cameras[0], settings).unwrap();
        r.render_spp(8, |_| {}).unwrap();
        r.image().unwrap().data
    };
    let (on, off) = (image(true), image(false));
    assert!(off.iter().filter(|&&v| v > 0.0).count() * 2 > off.len(), "a mostly black image");
    let same = on.iter().zip(&off).filter(|(a, b)| (*a - *b).abs() <= 1e-5 * b.abs()).count();
    assert_eq!(same, off.len(), "{} of {} values differ", off.len() - same, off.len());
    finish(ctx);
}

/// The shadow-ray queue (`RenderSettings::shadow_queue`) with every kind of light at once
/// (each builds its shadow ray its own way, and BDPT's connections theirs): pt-nee's, BDPT's
/// and VCM's camera pass, and BDPT's and VCM's light pass (its joins to the camera), give the
/// same image with and without it, up to the order of the float sums (and of the light-tracing
/// splats, whose atomic adds land in any order either way): to 1e-5 of each value. Few slots,
/// so some rays are queued and the rest traced in place.
#[test]
fn shadow_queue_gives_the_same_image_with_every_kind_of_light() {
    use bidir::render::ShadowQueue;
    let scene = every_kind_of_light_scene();
    let ctx = gpu();
    let vcm = Integrator::Vcm(bidir::render::vcm::VcmMode::FULL);
    for (integrator, spp) in [(Integrator::PtNee, 8), (Integrator::Bdpt(Join::DEFAULT), 4), (vcm, 4)] {
        let image = |queue: Option<ShadowQueue>| {
            let mut settings = RenderSettings::new(integrator);
            settings.shadow_queue = Some(queue);
            settings.pass_target = std::time::Duration::from_secs(3600);
            let mut r = Renderer::new(&ctx, &scene, &scene.cameras[0], settings).unwrap();
            r.render_spp(spp, |_| {}).unwrap();
            r.image().unwrap().data
        };
        let off = image(None);
        let queued = image(Some(ShadowQueue { slots: 4, chunk_samples: 2, pause: true }));
        assert!(off.iter().filter(|&&v| v > 0.0).count() * 2 > off.len(), "a mostly black image");
        let same = queued.iter().zip(&off).filter(|(a, b)| (*a - *b).abs() <= 1e-5 * b.abs()).count();
        assert_eq!(same, off.len(), "{}: {} of {} values differ", integrator.name(), off.len() - same, off.len());
    }
    finish(ctx);
}
