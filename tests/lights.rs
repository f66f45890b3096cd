//! Output for lit scenes (issue #14): the EXR's alpha and the AOVs a denoiser takes, from the
//! first-hit pass every integrator runs when asked (src/render/first_hit.rs):
//! - alpha is 1 wherever every camera ray hits geometry (a closed scene), in every integrator;
//! - a quad covering exactly the right half of the image: alpha 0 on the left, 1 on the
//!   right, and the fraction of samples whose jitter falls in the covered half in the middle
//!   column (within its binomial noise);
//! - on a flat Lambertian quad the albedo AOV is its albedo, the normal its normal and the
//!   depth the analytic camera-ray distance averaged over the pixel (within the estimator's
//!   own noise, computed from the within-pixel variance);
//! - the EXR written carries `A`, `albedo.R/G/B`, `normal.X/Y/Z`, `depth.Z`, read back.

mod common;

use bidir::imaging::aov::{slot, Aovs};
use bidir::imaging::part::Accumulation;
use bidir::render::{Integrator, Join, RenderSettings, Renderer};
use bidir::scene::{Camera, Material, Scene};
use common::{finish, geometry, gpu};
use glam::Vec3;

fn add(scene: &mut Scene, (positions, tris): (Vec<Vec3>, Vec<[u32; 3]>), m: u32) {
    let base = scene.positions.len() as u32;
    scene.positions.extend(positions);
    scene.material_ids.extend(std::iter::repeat_n(m, tris.len()));
    scene.triangles.extend(tris.into_iter().map(|t| t.map(|i| i + base)));
}

const ALL_AOVS: Aovs = Aovs { albedo: true, normal: true, depth: true };

/// The film's sums (with the first-hit sums) after `spp` samples of `integrator`.
fn render(scene: &Scene, integrator: Integrator, spp: u32, aovs: Aovs) -> Accumulation {
    let ctx = gpu();
    let mut settings = RenderSettings::new(integrator);
    settings.first_hit = Some(aovs);
    let mut r = Renderer::new(&ctx, scene, &scene.cameras[0], settings).unwrap();
    r.render_spp(spp, |_| {}).unwrap();
    let sums = r.sums().unwrap();
    drop(r);
    finish(ctx);
    sums
}

fn camera(eye: Vec3, target: Vec3, width: u32, height: u32) -> Camera {
    Camera { name: "test".into(), eye, target, up: Vec3::Y, fov_y_deg: 40.0, width, height }
}

/// The quad z = 0 over x in [x0, 50], y in [-50, 50], facing +Z (toward the camera at z = D).
fn quad_scene(x0: f32, albedo: Vec3, width: u32, height: u32) -> Scene {
    let mut s = Scene { source: "test:quad".into(), ..Default::default() };
    s.materials.push(Material { name: "lambert".into(), albedo, ..Default::default() });
    let quad = (
        vec![Vec3::new(x0, -50.0, 0.0), Vec3::new(50.0, -50.0, 0.0), Vec3::new(50.0, 50.0, 0.0), Vec3::new(x0, 50.0, 0.0)],
        vec![[0, 1, 2], [0, 2, 3]],
    );
    add(&mut s, quad, 0);
    s.cameras.push(camera(Vec3::new(0.0, 0.0, D), Vec3::ZERO, width, height));
    s
}

const D: f32 = 3.0;

#[test]
fn alpha_is_one_inside_a_closed_scene_for_every_integrator() {
    let mut s = Scene { source: "test:inside-sphere".into(), ..Default::default() };
    s.materials.push(Material { name: "glow".into(), albedo: Vec3::splat(0.5), emission: Vec3::ONE, ..Default::default() });
    add(&mut s, geometry::icosphere(1, Vec3::ZERO, 2.0), 0);
    s.cameras.push(camera(Vec3::new(0.1, 0.2, 0.3), Vec3::new(0.0, 0.0, -1.0), 8, 6));
    for integrator in [Integrator::Pt, Integrator::PtNee, Integrator::Bdpt(Join::Lvc(0))] {
        let sums = render(&s, integrator, 4, Aovs::default());
        let fh = sums.first_hit.as_ref().expect("first-hit sums");
        let alpha = fh.channels(sums.spp);
        assert_eq!(alpha.len(), 1, "alpha only without --aov");
        assert!(alpha[0].1.iter().all(|&a| a == 1.0), "{}: alpha {:?}", integrator.name(), alpha[0].1);
    }
}

#[test]
fn alpha_is_the_covered_fraction_of_each_pixel() {
    // 9 columns: the quad's edge x = 0 is seen down the middle of column 4.
    let (w, h, spp) = (9u32, 4u32, 16u32);
    let sums = render(&quad_scene(0.0, Vec3::splat(0.5), w, h), Integrator::PtNee, spp, Aovs::default());
    let a = &sums.first_hit.as_ref().unwrap().channels(sums.spp)[0].1;
    let mut middle = Vec::new();
    for y in 0..h {
        for x in 0..w {
            let v = a[(y * w + x) as usize];
            match x {
                0..=3 => assert_eq!(v, 0.0, "pixel ({x}, {y}) sees only the environment"),
                4 => middle.push(v as f64),
                _ => assert_eq!(v, 1.0, "pixel ({x}, {y}) is covered"),
            }
        }
    }
    // Each middle pixel's alpha is a fraction of `spp` Bernoulli(1/2) samples (stratified
    // samplers only do better); their mean over the column is 1/2 within 4 standard errors.
    let mean = middle.iter().sum::<f64>() / middle.len() as f64;
    let se = (0.25 / (spp as f64 * middle.len() as f64)).sqrt();
    assert!((mean - 0.5).abs() <= 4.0 * se, "middle column alpha {mean} (expected 0.5 +- {se})");
    // The whole image: exactly half of its area is covered.
    let total = a.iter().map(|&v| v as f64).sum::<f64>() / a.len() as f64;
    assert!((total - 0.5).abs() <= 4.0 * se / (w as f64).sqrt() + 1e-6, "image alpha {total}");
}

/// Camera-ray distance to the plane z = 0 through image position (px, py), as the kernels
/// generate camera rays (glsl/common/ray.glsl, camera_direction).
fn plane_depth(cam: &bidir::gpu::abi::GpuCamera, px: f64, py: f64) -> f64 {
    let ndc_x = 2.0 * px / cam.size.x as f64 - 1.0;
    let ndc_y = 1.0 - 2.0 * py / cam.size.y as f64;
    let d = cam.forward.as_dvec3() + ndc_x * cam.right.truncate().as_dvec3() + ndc_y * cam.up.truncate().as_dvec3();
    let d = d.normalize();
    -(cam.eye.z as f64) / d.z
}

#[test]
fn aovs_on_a_lambertian_plane_are_its_albedo_normal_and_distance() {
    let albedo = Vec3::new(0.2, 0.5, 0.7);
    let (w, h, spp) = (6u32, 5u32, 8u32);
    let scene = quad_scene(-50.0, albedo, w, h);
    let sums = render(&scene, Integrator::PtNee, spp, ALL_AOVS);
    let fh = sums.first_hit.as_ref().unwrap();
    let cam = bidir::gpu_data::gpu_camera(&scene.cameras[0]);
    let n = spp as f64;
    for y in 0..h {
        for x in 0..w {
            let p = fh.sums[(y * w + x) as usize];
            assert_eq!(p[slot::HITS], n, "every ray hits the plane");
            for k in 0..3 {
                let a = p[slot::ALBEDO + k] / n;
                assert!((a - albedo[k] as f64).abs() < 1e-6, "albedo[{k}] {a} at ({x}, {y})");
                let nk = p[slot::NORMAL + k] / n;
                assert!((nk - [0.0, 0.0, 1.0][k]).abs() < 1e-6, "normal[{k}] {nk} at ({x}, {y})");
            }
            // The pixel's mean distance and its within-pixel spread, over 32 x 32 points.
            let m = 32;
            let depths: Vec<f64> = (0..m * m)
                .map(|i| plane_depth(&cam, x as f64 + ((i % m) as f64 + 0.5) / m as f64, y as f64 + ((i / m) as f64 + 0.5) / m as f64))
                .collect();
            let exact = depths.iter().sum::<f64>() / depths.len() as f64;
            let sd = (depths.iter().map(|d| (d - exact).powi(2)).sum::<f64>() / depths.len() as f64).sqrt();
            let est = p[slot::DEPTH] / n;
            assert!((est - exact).abs() <= 4.0 * sd / n.sqrt() + 1e-5 * exact, "depth {est} vs {exact} (sd {sd}) at ({x}, {y})");
        }
    }
}

#[test]
fn exr_carries_alpha_and_the_aov_layers() {
    use exr::prelude::*;
    let albedo = Vec3::new(0.3, 0.6, 0.9);
    let (w, h) = (4u32, 3u32);
    let sums = render(&quad_scene(-50.0, albedo, w, h), Integrator::Pt, 2, ALL_AOVS);
    let dir = std::env::temp_dir().join(format!("bidir-lights-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("aov.exr");
    let crop = bidir::imaging::Crop::full(w, h);
    bidir::imaging::part::write_part(&path, &sums, &bidir::imaging::part::RenderInfo::default(), crop).unwrap();
    let image = read().no_deep_data().largest_resolution_level().all_channels().all_layers().all_attributes().from_file(&path).unwrap();
    let layer = &image.layer_data[0];
    let channel = |name: &str| -> Vec<f32> {
        let c = layer.channel_data.list.iter().find(|c| c.name.to_string() == name);
        c.unwrap_or_else(|| panic!("no channel {name}")).sample_data.values_as_f32().collect()
    };
    assert!(channel("A").iter().all(|&a| a == 1.0));
    for (k, c) in ["albedo.R", "albedo.G", "albedo.B"].iter().enumerate() {
        assert!(channel(c).iter().all(|&v| (v - albedo[k]).abs() < 1e-6), "{c}");
    }
    for (k, c) in ["normal.X", "normal.Y", "normal.Z"].iter().enumerate() {
        assert!(channel(c).iter().all(|&v| (v - [0.0, 0.0, 1.0][k]).abs() < 1e-6), "{c}");
    }
    assert!(channel("depth.Z").iter().all(|&v| (D..1.2 * D).contains(&v)), "depth.Z");
    // Viewers and bidir itself still read the colour.
    let rgb = bidir::imaging::read_exr(&path).unwrap();
    assert_eq!((rgb.width, rgb.height), (w, h));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn aov_needs_an_exr_output_and_known_names() {
    let dir = std::env::temp_dir();
    let run = |args: &[&str]| std::process::Command::new(env!("CARGO_BIN_EXE_bidir")).args(args).current_dir(&dir).output().unwrap();
    let png = run(&["render", "--aov", "albedo", "-o", "bidir-lights-aov.png"]);
    assert!(!png.status.success());
    assert!(String::from_utf8_lossy(&png.stderr).contains("give an .exr output"), "{}", String::from_utf8_lossy(&png.stderr));
    let unknown = run(&["render", "--aov", "albedo,position", "-o", "bidir-lights-aov.exr"]);
    assert!(!unknown.status.success());
    assert!(String::from_utf8_lossy(&unknown.stderr).contains("unknown AOV 'position'"), "{}", String::from_utf8_lossy(&unknown.stderr));
}
