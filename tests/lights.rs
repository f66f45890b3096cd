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
//!
//! The `--sky` map (Preetham et al. 1999, src/scene/sky.rs): finite and non-negative, its
//! luminance that of the paper's formulas (evaluated again here, independently), brighter
//! toward the sun and toward the horizon; pt, pt-nee and BDPT agree block by block under it.

mod common;

use bidir::imaging::aov::{slot, Aovs};
use bidir::imaging::part::Accumulation;
use bidir::render::{Integrator, Join, RenderSettings, Renderer};
use bidir::scene::{Camera, Environment, Material, Preetham, Scene, SkySpec};
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

/// Luminance (kcd/m^2) of Preetham et al.'s clear sky, written out from the paper (eq. 3 and
/// Appendix A.2) for the test: view zenith angle theta, angle gamma to the sun, sun zenith
/// angle theta_s, turbidity t.
fn preetham_luminance(theta: f64, gamma: f64, theta_s: f64, t: f64) -> f64 {
    let (a, b, c, d, e) = (0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771, -0.0670 * t + 0.3703);
    let f = |th: f64, g: f64| (1.0 + a * (b / th.cos()).exp()) * (1.0 + c * (d * g).exp() + e * g.cos().powi(2));
    let chi = (4.0 / 9.0 - t / 120.0) * (std::f64::consts::PI - 2.0 * theta_s);
    let y_z = (4.0453 * t - 4.9710) * chi.tan() - 0.2155 * t + 2.4192;
    y_z * f(theta, gamma) / f(0.0, theta_s)
}

/// Rec. 709 luminance of linear RGB.
fn luminance(c: Vec3) -> f64 {
    (0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z) as f64
}

#[test]
fn sky_map_follows_preetham() {
    let t = 3.0;
    let theta_s = 50f64.to_radians();
    let sun = Vec3::new(theta_s.sin() as f32, theta_s.cos() as f32, 0.0);
    let spec = SkySpec { turbidity: t, ..SkySpec::default() };
    let env = Environment::preetham_sky(&spec, sun, Vec3::splat(100.0), 0.0, 256, 128);
    assert!(env.texels.iter().all(|t| t.is_finite() && t.min_element() >= 0.0), "finite, non-negative");
    assert!(env.texels[..(256 * 64)].iter().all(|t| t.min_element() > 0.0), "positive above the horizon");
    let sky = Preetham::new(sun, t);
    // Directions at (theta, gamma): the view at zenith angle theta, rotated about the zenith
    // away from the sun by phi (cos gamma = cos theta cos theta_s + sin theta sin theta_s cos phi).
    let view = |theta: f64, phi: f64| Vec3::new((theta.sin() * phi.cos()) as f32, theta.cos() as f32, (theta.sin() * phi.sin()) as f32);
    let gamma = |w: Vec3| (w.dot(sun) as f64).clamp(-1.0, 1.0).acos();
    let to_radiance = 1000.0 / 683.0;
    for (theta_deg, phi_deg) in [(0.0, 0.0), (30.0, 0.0), (50.0, 8.0), (70.0, 90.0), (85.0, 180.0), (60.0, 135.0)] {
        let (theta, phi) = (f64::to_radians(theta_deg), f64::to_radians(phi_deg));
        let w = view(theta, phi);
        let want = to_radiance * preetham_luminance(theta, gamma(w), theta_s, t);
        let model = luminance(sky.radiance(w).as_vec3());
        assert!((model / want - 1.0).abs() < 2e-3, "model at ({theta_deg}, {phi_deg}): {model} vs {want}");
        // The map holds the value at its texel's centre (1.4 degrees apart).
        let map = luminance(env.radiance(w));
        assert!((map / want - 1.0).abs() < 0.03, "map at ({theta_deg}, {phi_deg}): {map} vs {want}");
    }
    let lum = |theta_deg: f64, phi_deg: f64| luminance(env.radiance(view(f64::to_radians(theta_deg), f64::to_radians(phi_deg))));
    // Brighter toward the sun: along the sun's almucantar, and near it than at the zenith.
    assert!(lum(50.0, 10.0) > lum(50.0, 45.0) && lum(50.0, 45.0) > lum(50.0, 90.0), "toward the sun");
    assert!(lum(45.0, 5.0) > lum(0.0, 0.0), "near the sun brighter than the zenith");
    // Brighter toward the horizon, away from the sun (the Perez gradient term, A < 0).
    assert!(lum(85.0, 180.0) > lum(60.0, 180.0) && lum(60.0, 180.0) > lum(30.0, 180.0), "toward the horizon");
    // The ground: albedo / pi times the irradiance on a horizontal surface (sky and sun).
    let ground = env.radiance(Vec3::new(0.1, -0.9, 0.2).normalize());
    let e_sun = 100.0 * theta_s.cos();
    assert!(luminance(ground) > 0.3 / std::f64::consts::PI * e_sun, "the ground is lit by the sun and the sky");
}

/// Per 8 x 8 block, the mean of the pixel differences a - b (channel mean) against its
/// standard error: the sum of z^2 is chi-square with one degree of freedom per block. And
/// the whole image's mean difference within 4 standard errors.
fn assert_agree(what: &str, a: &bidir::imaging::RgbImage, b: &bidir::imaging::RgbImage) {
    let w = a.width as usize;
    let diff: Vec<f64> =
        a.data.chunks_exact(3).zip(b.data.chunks_exact(3)).map(|(x, y)| (0..3).map(|c| (x[c] - y[c]) as f64).sum::<f64>() / 3.0).collect();
    let mean_se = |d: &[f64]| {
        let n = d.len() as f64;
        let m = d.iter().sum::<f64>() / n;
        (m, (d.iter().map(|v| (v - m).powi(2)).sum::<f64>() / (n - 1.0) / n).sqrt())
    };
    let (mut chi2, mut blocks) = (0.0, 0u32);
    for by in (0..a.height as usize).step_by(8) {
        for bx in (0..w).step_by(8) {
            let d: Vec<f64> = (by..by + 8).flat_map(|y| (bx..bx + 8).map(move |x| (x, y))).map(|(x, y)| diff[y * w + x]).collect();
            let (m, se) = mean_se(&d);
            // Pixels that see only the map are exact up to the rounding of float sums.
            let level = (by..by + 8)
                .flat_map(|y| (bx..bx + 8).map(move |x| (x, y)))
                .map(|(x, y)| a.pixel(x as u32, y as u32)[1] as f64)
                .sum::<f64>()
                / 64.0;
            chi2 += (m / se.max(1e-5 * level.abs()).max(1e-12)).powi(2);
            blocks += 1;
        }
    }
    let level = a.mean().iter().sum::<f64>() / 3.0;
    let (m, se) = mean_se(&diff);
    let p = common::stats::chi2_sf(chi2, blocks);
    eprintln!(
        "{what}: mean difference {:+.3} % (4 sigma {:.3} %), blocks X^2 = {chi2:.1} dof {blocks} p = {p:.4}",
        100.0 * m / level,
        400.0 * se / level
    );
    assert!(4.0 * se / level < 0.02, "{what}: too noisy to resolve 2 %");
    assert!(m.abs() < 4.0 * se, "{what}: means differ by {:+.3} %", 100.0 * m / level);
    assert!(p >= 1e-3, "{what}: block means disagree beyond noise");
}

/// The box [-1, 1]^3 without its top (+Y) face, with a sphere inside, under a hazy low-sun
/// sky (a coarse map: the test is of the integrators, not of the map's resolution).
#[test]
fn integrators_agree_under_the_sky() {
    let mut s = Scene { source: "test:sky-box".into(), ..Default::default() };
    s.materials.push(Material { name: "box".into(), albedo: Vec3::new(0.7, 0.6, 0.5), ..Default::default() });
    s.materials.push(Material { name: "sphere".into(), albedo: Vec3::splat(0.5), ..Default::default() });
    let corner = |i: u32| Vec3::new([-1.0, 1.0][(i & 1) as usize], [-1.0, 1.0][(i >> 1 & 1) as usize], [-1.0, 1.0][(i >> 2 & 1) as usize]);
    let quads = [[0, 1, 5, 4], [0, 4, 6, 2], [1, 3, 7, 5], [0, 2, 3, 1], [4, 5, 7, 6]];
    add(&mut s, ((0..8).map(corner).collect(), quads.iter().flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]).collect()), 0);
    add(&mut s, geometry::icosphere(2, Vec3::new(0.2, -0.5, 0.1), 0.45), 1);
    s.cameras.push(Camera {
        name: "test".into(),
        eye: Vec3::new(1.6, 3.2, 2.4),
        target: Vec3::new(0.0, -0.4, 0.0),
        up: Vec3::Y,
        fov_y_deg: 45.0,
        width: 32,
        height: 32,
    });
    let sun = Vec3::new(-0.5, 0.6, 0.4).normalize();
    s.environment =
        Some(Environment::preetham_sky(&SkySpec { turbidity: 5.0, ..SkySpec::default() }, sun, Vec3::splat(20.0), 30.0, 32, 16));
    let image = |integrator: Integrator, spp: u32| {
        let ctx = gpu();
        let mut r = Renderer::new(&ctx, &s, &s.cameras[0], RenderSettings::new(integrator)).unwrap();
        r.render_spp(spp, |_| {}).unwrap();
        let img = r.image().unwrap();
        assert_eq!(r.nan_samples().unwrap(), 0);
        drop(r);
        finish(ctx);
        img
    };
    let reference = image(Integrator::PtNee, 128);
    for (integrator, spp) in [(Integrator::Pt, 128), (Integrator::Bdpt(Join::Lvc(0)), 64)] {
        assert_agree(&format!("sky: {} vs pt-nee", integrator.name()), &image(integrator, spp), &reference);
    }
}

#[test]
fn sky_flags_refuse_what_they_cannot_do() {
    let run = |args: &[&str]| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_bidir")).args(args).current_dir(std::env::temp_dir()).output().unwrap();
        assert!(!out.status.success(), "{args:?} succeeded");
        String::from_utf8_lossy(&out.stderr).into_owned()
    };
    let o = ["-o", "bidir-lights-sky.png"];
    assert!(run(&["render", "--sky", "turbidity=3", o[0], o[1]]).contains("needs the sun's direction"));
    // A bare --sky before another flag leaves that flag alone (it once took it as its value).
    assert!(run(&["render", "--sky", "--integrator", "pt", o[0], o[1]]).contains("needs the sun's direction"));
    assert!(run(&["render", "--sky", "sun=0,1,0", "--env", "1,1,1", o[0], o[1]]).contains("--sky and --env"));
    assert!(run(&["render", "--sky", "sun=0,-1,0.2", o[0], o[1]]).contains("below the horizon"));
    assert!(run(&["render", "--sky", "sun=1,1,0", "--sun", "0,1,0;1,1,1", o[0], o[1]]).contains("differ"));
    assert!(run(&["render", "--sky", "turbidity=20;sun=0,1,0", o[0], o[1]]).contains("bad turbidity"));
}

/// Emitters too weak for their scene (DamagedHelmet's emissive texture, TransmissionTest's
/// glowing labels) get the default environment as well, and a line saying so; a room lit by
/// its lamp (the Cornell box), a scene of bright emissive cubes and the modified Sponza's sun
/// and sky do not.
#[test]
fn weak_emitters_get_the_default_environment_too() {
    let threshold = bidir::scene::DIM_EMISSION_RATIO;
    let cornell = Scene::builtin_cornell_box().emitted_light_ratio().unwrap();
    eprintln!("Cornell box: emitted light ratio {cornell:.4}");
    assert!(cornell > threshold);
    let samples = std::path::Path::new("../shared/scenes");
    if !samples.is_dir() {
        eprintln!("skipping the sample models: ../shared/scenes is absent");
        return;
    }
    let load = |p: &str| bidir::scene::load(&samples.join(p), &Default::default()).unwrap().scene;
    let mut sponza = load("sponza/Sponza.gltf");
    for (i, q) in bidir::scene::QuadLight::sponza_sun_sky().iter().enumerate() {
        sponza.add_quad_light(q, &format!("q{i}"));
    }
    let helmet = "gltf-samples/DamagedHelmet/DamagedHelmet.glb";
    for (what, scene, dim) in [
        ("Sponza --sponza-sun-sky", sponza, false),
        ("EmissiveStrengthTest", load("gltf-samples/EmissiveStrengthTest/EmissiveStrengthTest.glb"), false),
        ("DamagedHelmet", load(helmet), true),
        ("TransmissionTest", load("gltf-samples/TransmissionTest/TransmissionTest.glb"), true),
    ] {
        let r = scene.emitted_light_ratio().unwrap();
        eprintln!("{what}: emitted light ratio {r:.4}");
        assert_eq!(r < threshold, dim, "{what}: ratio {r}");
    }
    let out =
        std::process::Command::new(env!("CARGO_BIN_EXE_bidir")).args(["info", samples.join(helmet).to_str().unwrap()]).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr);
    assert!(text.contains("its emitters are weak for its size") && text.contains("lit by a uniform white environment"), "{text}");
    // ... and renders lit (its own light alone leaves it nearly black).
    let mean = |extra: &[&str]| {
        let exr = std::env::temp_dir().join(format!("bidir-helmet-{}-{}.exr", std::process::id(), extra.len()));
        let model = samples.join(helmet);
        let mut args: Vec<String> =
            ["render", model.to_str().unwrap(), "--width", "16", "--height", "16", "--spp", "2"].iter().map(|s| s.to_string()).collect();
        args.extend(extra.iter().map(|s| s.to_string()));
        args.extend(["-o".to_owned(), exr.to_str().unwrap().to_owned()]);
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_bidir")).args(&args).env("BIDIR_VALIDATION", "1").output().unwrap();
        assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
        let img = bidir::imaging::read_exr(&exr).unwrap();
        std::fs::remove_file(&exr).unwrap();
        img.data.iter().map(|&v| v as f64).sum::<f64>() / img.data.len() as f64
    };
    let (lit, own) = (mean(&[]), mean(&["--env", "none"]));
    eprintln!("DamagedHelmet: image mean {lit:.4} by default, {own:.4} with --env none");
    assert!(lit > 10.0 * own, "DamagedHelmet is not lit by the default environment: mean {lit} against {own} under its own light");
}

/// Parts of disjoint sample ranges merge into the whole render's alpha and AOVs.
#[test]
fn merged_parts_carry_alpha_and_aovs() {
    let dir = std::env::temp_dir().join(format!("bidir-lights-merge-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = |n: &str| dir.join(n).to_str().unwrap().to_owned();
    let bidir = |args: &[&str]| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_bidir")).args(args).env("BIDIR_VALIDATION", "1").output().unwrap();
        assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    };
    let common = ["render", "--width", "12", "--height", "8", "--seed", "5"];
    fn with<'a>(common: &[&'a str], extra: &[&'a str]) -> Vec<&'a str> {
        common.iter().chain(extra).copied().collect()
    }
    bidir(&with(&common, &["--sample-range", "0..3", "--aov", "depth,normal", "-o", &p("a.exr")]));
    bidir(&with(&common, &["--sample-range", "3..5", "--aov", "depth", "-o", &p("b.exr")]));
    bidir(&with(&common, &["--spp", "5", "--aov", "depth", "-o", &p("whole.exr")]));
    bidir(&["merge", &p("a.exr"), &p("b.exr"), "-o", &p("merged.exr")]);
    let read = |f: &str| bidir::imaging::part::read_part(std::path::Path::new(&p(f))).unwrap().sums;
    let (merged, whole) = (read("merged.exr"), read("whole.exr"));
    let (m, w) = (merged.first_hit.expect("merged alpha"), whole.first_hit.unwrap());
    assert_eq!(m.aovs, Aovs { depth: true, ..Aovs::default() }, "the layers both parts have");
    for (a, b) in m.sums.iter().zip(&w.sums) {
        for k in [slot::HITS, slot::DEPTH] {
            assert!((a[k] - b[k]).abs() <= 1e-5 * b[k].abs().max(1.0), "{k}: {} vs {}", a[k], b[k]);
        }
    }
    assert!(w.sums.iter().any(|s| s[slot::DEPTH] > 0.0));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Albedo and normal are those of the first non-specular surface seen through a mirror (as
/// OIDN defines them), depth the distance to the mirror: a mirror facing the camera reflects
/// every camera ray onto a Lambertian wall behind the camera. Half-mirrored, the albedo is the
/// mixture of the wall's and the material's own, within its binomial noise.
#[test]
fn albedo_is_seen_through_mirrors() {
    let (wall, own) = (Vec3::new(0.2, 0.4, 0.6), Vec3::new(0.9, 0.5, 0.1));
    let (w, h, spp) = (6u32, 4u32, 16u32);
    for reflectivity in [1.0f32, 0.5] {
        let mut s = quad_scene(-50.0, own, w, h);
        s.materials[0].reflectivity = reflectivity;
        s.materials.push(Material { name: "wall".into(), albedo: wall, ..Default::default() });
        let z = 10.0;
        let back = (
            vec![Vec3::new(-50.0, -50.0, z), Vec3::new(-50.0, 50.0, z), Vec3::new(50.0, 50.0, z), Vec3::new(50.0, -50.0, z)],
            vec![[0, 1, 2], [0, 2, 3]],
        );
        add(&mut s, back, 1);
        let sums = render(&s, Integrator::PtNee, spp, ALL_AOVS);
        let fh = sums.first_hit.unwrap();
        let n = (w * h * spp) as f64;
        let total = |k: usize| fh.sums.iter().map(|p| p[k]).sum::<f64>() / n;
        assert_eq!(total(slot::HITS), 1.0);
        let r = reflectivity as f64;
        for k in 0..3 {
            let expect = r * wall[k] as f64 + (1.0 - r) * own[k] as f64;
            // Each sample's albedo is the wall's (probability r) or the material's.
            let se = (r * (1.0 - r)).sqrt() * (wall[k] - own[k]).abs() as f64 / n.sqrt();
            let got = total(slot::ALBEDO + k);
            assert!((got - expect).abs() <= 4.0 * se + 1e-6, "reflectivity {r}: albedo[{k}] {got} vs {expect} (se {se})");
        }
        // The wall's normal faces the reflected rays (-Z), the quad's the camera (+Z).
        let nz = total(slot::NORMAL + 2);
        let expect_nz = -r + (1.0 - r);
        let se = (r * (1.0 - r)).sqrt() * 2.0 / n.sqrt();
        assert!((nz - expect_nz).abs() <= 4.0 * se + 1e-6, "reflectivity {r}: normal z {nz} vs {expect_nz}");
        // Depth is the camera ray's, to the mirror: at least D, nowhere near the wall.
        assert!(fh.sums.iter().all(|p| p[slot::DEPTH] / spp as f64 >= D as f64 && p[slot::DEPTH] / (spp as f64) < 1.2 * D as f64));
    }
}
