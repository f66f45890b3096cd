//! The environment light in every integrator:
//! - a convex diffuse object of albedo rho under a uniform environment L has outgoing
//!   radiance rho L everywhere (each point sees the whole environment over its hemisphere, no
//!   interreflection): every integrator and join within 0.5 %;
//! - a furnace: an open box and a sphere in it, all of albedo 1, under a uniform environment
//!   L: radiance L everywhere, whatever the number of bounces;
//! - a small HDR map with a hot spot (made here) over a non-convex scene: pt, pt-nee and every
//!   BDPT join agree block by block within their noise.

mod common;

use bidir::imaging::RgbImage;
use bidir::render::{Integrator, Join, RenderSettings, Renderer};
use bidir::scene::{Camera, Environment, Material, Scene};
use common::stats::chi2_sf;
use common::{finish, geometry, gpu};
use glam::Vec3;

fn all_integrators() -> [Integrator; 6] {
    [
        Integrator::Pt,
        Integrator::PtNee,
        Integrator::Bdpt(Join::Full),
        Integrator::Bdpt(Join::K(2)),
        Integrator::Bdpt(Join::K(1)),
        Integrator::Bdpt(Join::Lvc(0)),
    ]
}

/// Adds triangles with material `m` to the scene.
fn add(scene: &mut Scene, (positions, tris): (Vec<Vec3>, Vec<[u32; 3]>), m: u32) {
    let base = scene.positions.len() as u32;
    scene.positions.extend(positions);
    scene.material_ids.extend(std::iter::repeat_n(m, tris.len()));
    scene.triangles.extend(tris.into_iter().map(|t| t.map(|i| i + base)));
}

/// The box [-1, 1]^3 without its top (+Y) face: ten triangles, seen from both sides.
fn open_box() -> (Vec<Vec3>, Vec<[u32; 3]>) {
    let c =
        |i: u32| Vec3::new(if i & 1 == 0 { -1.0 } else { 1.0 }, if i & 2 == 0 { -1.0 } else { 1.0 }, if i & 4 == 0 { -1.0 } else { 1.0 });
    let positions = (0..8).map(c).collect();
    // Faces as quads (corner indices), every one but y = +1.
    let quads = [[0, 1, 5, 4], [0, 4, 6, 2], [1, 3, 7, 5], [0, 2, 3, 1], [4, 5, 7, 6]];
    let tris = quads.iter().flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]).collect();
    (positions, tris)
}

fn camera(eye: Vec3, target: Vec3, fov: f32, size: u32) -> Camera {
    Camera { name: "test".into(), eye, target, up: Vec3::Y, fov_y_deg: fov, width: size, height: size }
}

/// A unit sphere of albedo rho filling the whole image, under uniform radiance L.
fn sphere_scene(rho: f32, l: f32) -> Scene {
    let mut s = Scene { source: "test:env-sphere".into(), ..Default::default() };
    s.materials.push(Material { name: "sphere".into(), albedo: Vec3::splat(rho), ..Default::default() });
    add(&mut s, geometry::icosphere(3, Vec3::ZERO, 1.0), 0);
    // From 2 units away the sphere spans 30 degrees about the axis; the image corners 21.
    s.cameras.push(camera(Vec3::new(0.3, 1.2, 1.55), Vec3::ZERO, 30.0, 32));
    s.environment = Some(Environment::uniform(Vec3::splat(l)));
    s
}

/// The open box with a sphere inside, albedo rho, seen from above and to the side.
fn box_scene(rho_box: f32, rho_sphere: f32, env: Environment, size: u32) -> Scene {
    let mut s = Scene { source: "test:env-box".into(), ..Default::default() };
    s.materials.push(Material { name: "box".into(), albedo: Vec3::splat(rho_box), ..Default::default() });
    s.materials.push(Material { name: "sphere".into(), albedo: Vec3::splat(rho_sphere), ..Default::default() });
    add(&mut s, open_box(), 0);
    add(&mut s, geometry::icosphere(2, Vec3::new(0.2, -0.5, 0.1), 0.45), 1);
    s.cameras.push(camera(Vec3::new(1.6, 3.2, 2.4), Vec3::new(0.0, -0.4, 0.0), 45.0, size));
    s.environment = Some(env);
    s
}

fn render(scene: &Scene, integrator: Integrator, spp: u32) -> RgbImage {
    let ctx = gpu();
    let mut r = Renderer::new(&ctx, scene, &scene.cameras[0], RenderSettings::new(integrator)).unwrap();
    assert!(r.gpu_scene().features.env, "the environment is compiled in");
    r.render_spp(spp, |_| {}).unwrap();
    let img = r.image().unwrap();
    assert_eq!(r.nan_samples().unwrap(), 0, "{}: NaN/Inf samples", integrator.name());
    drop(r);
    finish(ctx);
    img
}

/// Mean of the pixel values (averaged over channels) and its standard error over pixels.
fn mean_and_se(data: &[f32]) -> (f64, f64) {
    let px: Vec<f64> = data.chunks_exact(3).map(|c| (c[0] as f64 + c[1] as f64 + c[2] as f64) / 3.0).collect();
    sample_mean_and_se(&px)
}

fn sample_mean_and_se(px: &[f64]) -> (f64, f64) {
    let n = px.len() as f64;
    let mean = px.iter().sum::<f64>() / n;
    let var = px.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, (var / n).sqrt())
}

/// The image's mean is `expect` within 0.5 % and within 4 standard errors.
fn check_flat(what: &str, integrator: Integrator, img: &RgbImage, expect: f64) {
    let (mean, se) = mean_and_se(&img.data);
    let err = mean / expect - 1.0;
    eprintln!(
        "{what} {}: mean {mean:.5} expected {expect:.5} ({:+.3} %), 4 sigma {:.3} %",
        integrator.name(),
        100.0 * err,
        400.0 * se / expect
    );
    assert!(4.0 * se / expect < 0.005, "{what} {}: too noisy to resolve 0.5 %", integrator.name());
    assert!(
        err.abs() < 0.005 && (mean - expect).abs() < 4.0 * se.max(1e-6 * expect),
        "{what} {}: mean {mean} vs {expect} ({:+.3} %)",
        integrator.name(),
        100.0 * err
    );
}

#[test]
fn convex_diffuse_object_reflects_rho_times_l() {
    let scene = sphere_scene(0.6, 2.0);
    for integrator in all_integrators() {
        let spp = if matches!(integrator, Integrator::Bdpt(_)) { 32 } else { 16 };
        check_flat("sphere rho 0.6 under L 2", integrator, &render(&scene, integrator, spp), 1.2);
    }
}

#[test]
fn white_furnace_under_uniform_environment() {
    // BDPT's light tracing and connections are noisier than BSDF sampling here (albedo-1
    // paths bounce about five times in the box): it needs more samples for 0.5 %.
    let scene = box_scene(1.0, 1.0, Environment::uniform(Vec3::splat(1.5)), 48);
    for integrator in all_integrators() {
        let spp = if matches!(integrator, Integrator::Bdpt(_)) { 512 } else { 64 };
        check_flat("open box + sphere, albedo 1, under L 1.5", integrator, &render(&scene, integrator, spp), 1.5);
    }
}

/// An 8 x 4 map: a dim gradient and one hot texel, high and to one side.
fn hot_spot_map() -> Environment {
    let texels = (0..32)
        .map(|i| {
            let (x, y) = ((i % 8) as f32, (i / 8) as f32);
            if (x, y) == (5.0, 1.0) {
                Vec3::new(60.0, 50.0, 40.0)
            } else {
                Vec3::new(0.2 + 0.05 * x, 0.3, 0.4 - 0.08 * y)
            }
        })
        .collect();
    let mut env = Environment::from_texels("test:hot-spot", 8, 4, texels);
    env.rotate_deg = 20.0;
    env
}

/// Per 8 x 8 block, the mean of the pixel differences a - b against its standard error (the
/// differences' spread in the block; both are zero-mean under agreement): the sum of z^2 is
/// chi-square with one degree of freedom per block.
fn assert_agree(what: &str, a: &RgbImage, b: &RgbImage) {
    let w = a.width as usize;
    let diff: Vec<f64> = a
        .data
        .chunks_exact(3)
        .zip(b.data.chunks_exact(3))
        .map(|(x, y)| (0..3).map(|c| x[c] as f64 - y[c] as f64).sum::<f64>() / 3.0)
        .collect();
    let (mut chi2, mut blocks, mut worst) = (0.0, 0u32, 0.0f64);
    for by in (0..a.height as usize).step_by(8) {
        for bx in (0..w).step_by(8) {
            let d: Vec<f64> = (by..by + 8).flat_map(|y| (bx..bx + 8).map(move |x| (x, y))).map(|(x, y)| diff[y * w + x]).collect();
            let n = d.len() as f64;
            let m = d.iter().sum::<f64>() / n;
            let var = d.iter().map(|v| (v - m).powi(2)).sum::<f64>() / (n - 1.0);
            // Pixels that see the map directly are exact up to float rounding of the sums.
            let floor = 1e-5 * (by..by + 8).map(|y| a.data[3 * (y * w + bx)] as f64).sum::<f64>().abs() / 8.0;
            let z = m / (var / n).sqrt().max(floor).max(1e-12);
            chi2 += z * z;
            blocks += 1;
            worst = worst.max(z.abs());
        }
    }
    let (ma, _) = mean_and_se(&a.data);
    let (mean_d, se_d) = sample_mean_and_se(&diff);
    let p = chi2_sf(chi2, blocks);
    eprintln!(
        "{what}: mean difference {:+.3} % (4 sigma {:.3} %), blocks X^2 = {chi2:.1} dof {blocks} p = {p:.4}, worst |z| {worst:.2}",
        100.0 * mean_d / ma,
        400.0 * se_d / ma
    );
    assert!(4.0 * se_d / ma < 0.02, "{what}: too noisy to resolve 2 %");
    assert!(mean_d.abs() < 4.0 * se_d, "{what}: means differ by {:+.3} %", 100.0 * mean_d / ma);
    assert!(p >= 1e-3, "{what}: block means disagree beyond noise (X^2 = {chi2:.1}, {blocks} blocks)");
}

const JOINS: [(Integrator, u32); 4] = [
    (Integrator::Bdpt(Join::Full), 128),
    (Integrator::Bdpt(Join::K(2)), 128),
    (Integrator::Bdpt(Join::K(1)), 128),
    (Integrator::Bdpt(Join::Lvc(0)), 128),
];

fn check_agreement(what: &str, scene: &Scene) {
    let mut all = vec![(Integrator::Pt, 512)];
    all.extend(JOINS);
    check_agreement_of(what, scene, &all);
}

fn check_agreement_of(what: &str, scene: &Scene, integrators: &[(Integrator, u32)]) {
    let reference = render(scene, Integrator::PtNee, 256);
    for &(integrator, spp) in integrators {
        let img = render(scene, integrator, spp);
        assert_agree(&format!("{what}: {} vs pt-nee", integrator.name()), &img, &reference);
    }
}

#[test]
fn integrators_agree_under_a_hot_spot_map() {
    check_agreement("hot-spot map", &box_scene(0.7, 0.5, hot_spot_map(), 48));
}

/// With emissive triangles too, light sampling picks the environment or a triangle with
/// probability 1/2 each; every strategy's pdf must carry that choice.
#[test]
fn integrators_agree_with_an_environment_and_an_emitter() {
    let mut scene = box_scene(0.7, 0.5, hot_spot_map(), 48);
    // A small warm quad inside the box, under the rim, facing down and in.
    let quad = bidir::scene::QuadLight::new(
        Vec3::new(-0.9, 0.6, -0.9),
        Vec3::new(0.0, 0.0, 0.5),
        Vec3::new(0.5, -0.2, 0.0),
        Vec3::new(8.0, 6.0, 3.0),
    )
    .unwrap();
    scene.add_quad_light(&quad, "quad");
    assert_eq!(scene.emitters().len(), 2);
    check_agreement("hot-spot map + quad light", &scene);
}

/// Without an environment the kernels compile none of it in, and the scene stays dark
/// where nothing emits (`--env none`).
#[test]
fn no_environment_compiles_out_and_stays_dark() {
    let mut scene = sphere_scene(0.6, 2.0);
    scene.environment = None;
    let ctx = gpu();
    for integrator in [Integrator::PtNee, Integrator::Bdpt(Join::Lvc(0))] {
        let mut r = Renderer::new(&ctx, &scene, &scene.cameras[0], RenderSettings::new(integrator)).unwrap();
        assert!(!r.gpu_scene().features.env);
        r.render_spp(2, |_| {}).unwrap();
        assert!(r.image().unwrap().data.iter().all(|&v| v == 0.0), "{}: light without any emitter", integrator.name());
    }
    finish(ctx);
}

/// `--env FILE`: an EXR written here reads back texel for texel (rows top to bottom), and a
/// bad file is an error naming it.
#[test]
fn environment_maps_load_from_exr_and_refuse_bad_files() {
    let dir = std::env::temp_dir();
    let exr = dir.join(format!("bidir-env-{}.exr", std::process::id()));
    let mut img = RgbImage::new(4, 2);
    for (i, v) in img.data.iter_mut().enumerate() {
        *v = i as f32 * 0.25;
    }
    bidir::imaging::write_image(&exr, &img, 0.0).unwrap();
    let env = Environment::load(&exr).unwrap();
    std::fs::remove_file(&exr).unwrap();
    assert_eq!((env.width, env.height), (4, 2));
    for (i, t) in env.texels.iter().enumerate() {
        assert_eq!(*t, Vec3::new(0.75 * i as f32, 0.75 * i as f32 + 0.25, 0.75 * i as f32 + 0.5), "texel {i}");
    }
    // Radiance RGBE keeps 8 bits of mantissa: powers of two survive exactly.
    let hdr = dir.join(format!("bidir-env-{}.hdr", std::process::id()));
    let px: Vec<image::Rgb<f32>> = (0..6).map(|i| image::Rgb([2f32.powi(i), 0.5, 4.0])).collect();
    image::codecs::hdr::HdrEncoder::new(std::fs::File::create(&hdr).unwrap()).encode(&px, 3, 2).unwrap();
    let env = Environment::load(&hdr).unwrap();
    std::fs::remove_file(&hdr).unwrap();
    assert_eq!((env.width, env.height), (3, 2));
    assert_eq!(env.texels[4], Vec3::new(16.0, 0.5, 4.0));

    let missing = dir.join("bidir-no-such-env.hdr");
    let e = Environment::load(&missing).unwrap_err().to_string();
    assert!(e.contains("bidir-no-such-env.hdr"), "{e}");
    let garbage = dir.join(format!("bidir-env-garbage-{}.hdr", std::process::id()));
    std::fs::write(&garbage, b"not an image").unwrap();
    let e = Environment::load(&garbage).unwrap_err().to_string();
    std::fs::remove_file(&garbage).unwrap();
    assert!(e.contains("bidir-env-garbage") && e.contains("cannot read"), "{e}");
}

/// A sun (2 degrees, irradiance 4 facing it) low over the box with a dim sky: pt-nee and
/// every BDPT join agree (plain path tracing would find so small a disk too rarely to test).
#[test]
fn integrators_agree_under_a_sun() {
    let mut env = Environment::uniform(Vec3::new(0.1, 0.15, 0.25));
    env.sun =
        Some(bidir::scene::Sun { direction: Vec3::new(-0.4, 0.8, 0.3).normalize(), irradiance: Vec3::new(4.0, 3.6, 3.0), angle_deg: 2.0 });
    check_agreement_of("sun + sky", &box_scene(0.7, 0.5, env, 48), &JOINS);
}
