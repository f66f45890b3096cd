//! GGX materials in every integrator (lavapipe, validation on):
//! - a white furnace whose inner surface is half rough conductor with F = 1 and half diffuse
//!   never gains energy: its radiance stays below the lossless Le / (1 - rho) and the loss
//!   per roughness is printed;
//! - pt, pt-nee and every BDPT join agree on a small Cornell box with a rough metal floor, a
//!   near-mirror metal back wall, a rough glTF dielectric box and a rough thesis mirror box:
//!   16x16-pixel block means of the difference of two images are judged against their own
//!   standard errors (chi-square over the blocks, and the overall mean);
//! - the same with an emission texture on the light, and in a furnace whose inner surface has
//!   a tangent-space normal map and a glTF metallic-roughness material.

mod common;

use bidir::render::{Integrator, Join, RenderSettings, Renderer};
use bidir::scene::{Camera, Material, MaterialModel, Scene};
use common::{agree, finish, geometry, gpu};
use glam::Vec3;

fn render(scene: &Scene, camera: &Camera, integrator: Integrator, spp: u32) -> Vec<f32> {
    let ctx = gpu();
    let mut r = Renderer::new(&ctx, scene, camera, RenderSettings::new(integrator)).unwrap();
    r.render_spp(spp, |_| {}).unwrap();
    let img = r.image().unwrap();
    assert_eq!(r.nan_samples().unwrap(), 0, "{}: NaN/Inf samples", integrator.name());
    drop(r);
    finish(ctx);
    img.data
}

/// Mean of per-pixel values and its standard error (pixels are independent estimates).
fn mean_and_se(v: &[f64]) -> (f64, f64) {
    let n = v.len() as f64;
    let mean = v.iter().sum::<f64>() / n;
    let var = v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, (var / n).sqrt())
}

// ---- Energy: a furnace with a rough F = 1 conductor ------------------------------------------

/// A square view from inside the furnace boxes of these tests.
fn inside_camera(size: u32) -> Camera {
    Camera {
        name: "inside".into(),
        eye: Vec3::new(0.1, -0.05, 0.02),
        target: Vec3::new(1.0, 0.3, 0.2),
        up: Vec3::Y,
        fov_y_deg: 90.0,
        width: size,
        height: size,
    }
}

#[test]
fn rough_conductor_furnace_never_gains_energy() {
    let (positions, tris) = geometry::icosphere(3, Vec3::ZERO, 1.0);
    let triangles: Vec<[u32; 3]> = tris.into_iter().map(|[a, b, c]| [a, c, b]).collect();
    let n = triangles.len();
    let (refl, rho_d, le) = (0.5f32, 0.6f32, 1.0f32);
    // Lossless bound: every bounce keeps refl * 1 + (1 - refl) * rho_d.
    let bound = (le / (1.0 - refl - (1.0 - refl) * rho_d)) as f64;
    let camera = inside_camera(32);
    eprintln!("furnace, half rough conductor (F = 1) and half diffuse 0.6, lossless radiance {bound}:");
    for roughness in [0.05f32, 0.3, 0.8] {
        let material = Material {
            name: "rough".into(),
            albedo: Vec3::splat(rho_d),
            emission: Vec3::splat(le),
            reflectivity: refl,
            roughness,
            ..Default::default()
        };
        assert!(material.is_glossy());
        let scene = Scene {
            source: "test:rough-furnace".into(),
            positions: positions.clone(),
            triangles: triangles.clone(),
            material_ids: vec![0; n],
            materials: vec![material],
            ..Default::default()
        };
        for (integrator, spp) in [(Integrator::PtNee, 256), (Integrator::Bdpt(Join::Lvc(0)), 64)] {
            let img = render(&scene, &camera, integrator, spp);
            // Channels are equal: average them per pixel.
            let px: Vec<f64> = img.chunks_exact(3).map(|c| c.iter().map(|&v| v as f64).sum::<f64>() / 3.0).collect();
            let (mean, se) = mean_and_se(&px);
            let loss = 1.0 - mean / bound;
            eprintln!(
                "  roughness {roughness}, {}: radiance {mean:.4} ± {se:.4}, {:.2} % below the lossless bound",
                integrator.name(),
                100.0 * loss
            );
            assert!(mean <= bound + 4.0 * se, "roughness {roughness}, {}: {mean} ± {se} exceeds the lossless {bound}", integrator.name());
            // Single-scattering GGX loses energy only at rough, grazing reflections: a
            // near-mirror keeps nearly all of it.
            if roughness <= 0.05 {
                assert!(loss < 0.02 + 4.0 * se / bound, "roughness {roughness}: loses {:.2} %", 100.0 * loss);
            }
        }
    }
}

// ---- Agreement of the integrators on a glossy Cornell box ------------------------------------

fn glossy_cornell() -> (Scene, Camera) {
    let mut s = Scene::builtin_cornell_box();
    for m in &mut s.materials {
        let gltf = |m: &mut Material, base: Vec3, metallic: f32, roughness: f32| {
            m.model = MaterialModel::MetalRough;
            m.albedo = base;
            m.metallic = metallic;
            m.roughness = roughness;
        };
        match m.name.as_str() {
            "floor" => gltf(m, Vec3::new(0.9, 0.7, 0.5), 1.0, 0.3),
            "backWall" => gltf(m, Vec3::new(0.8, 0.8, 0.8), 1.0, 0.05),
            "tallBox" => gltf(m, Vec3::new(0.2, 0.4, 0.7), 0.0, 0.5),
            "shortBox" => {
                m.reflectivity = 0.6;
                m.roughness = 0.15;
            }
            _ => {}
        }
    }
    let mut camera = s.cameras[0].clone();
    camera.width = 64;
    camera.height = 64;
    (s, camera)
}

/// Whether images a and b have the same expectation: 16x16-pixel blocks of their difference,
/// the overall mean resolving 1 % (tests/common/agree.rs).
fn assert_agree(what: &str, a: &[f32], b: &[f32], width: usize) {
    agree::assert_agree_blocks(what, a, b, width, 16, 0.01)
}

/// The glossy Cornell box with its light's emission scaled by a 2x2 linear checker texture
/// (0.25 and 1, bilinear, two periods across the light): pt sees it only where paths hit the
/// light (`material_emission`), pt-nee and BDPT also where they sample it
/// (`light_sample_radiance`), so their agreement checks both.
fn textured_light(mut s: Scene) -> Scene {
    let uvs = s.positions.iter().map(|p| glam::Vec2::new((p.x - 213.0) / 65.0, (p.z - 227.0) / 52.5)).collect();
    s.uvs = Some(uvs);
    let (lo, hi) = (64u8, 255u8);
    s.textures.push(bidir::scene::Texture {
        name: "checker".into(),
        width: 2,
        height: 2,
        rgba8: vec![lo, lo, lo, 255, hi, hi, hi, 255, hi, hi, hi, 255, lo, lo, lo, 255],
        srgb: false,
    });
    let light = s.materials.iter_mut().find(|m| m.name == "light").expect("the Cornell box has a light");
    light.emission_texture = Some(0);
    s
}

#[test]
fn emission_texture_is_seen_alike_by_every_integrator() {
    let (plain, camera) = glossy_cornell();
    let scene = textured_light(plain.clone());
    let w = camera.width as usize;
    let reference = render(&scene, &camera, Integrator::PtNee, 256);
    let untextured = render(&plain, &camera, Integrator::PtNee, 64);
    let (a, b) = (reference.iter().sum::<f32>(), untextured.iter().sum::<f32>());
    eprintln!("textured light: image mean {:.4} of the untextured one (checker mean 0.63)", a / b);
    assert!(a < 0.8 * b && a > 0.4 * b, "the emission texture is not applied ({a} vs {b})");
    assert_agree("textured light: pt vs pt-nee", &render(&scene, &camera, Integrator::Pt, 1024), &reference, w);
    for join in [Join::Lvc(0), Join::Full] {
        let img = render(&scene, &camera, Integrator::Bdpt(join), 128);
        assert_agree(&format!("textured light: {} vs pt-nee", Integrator::Bdpt(join).name()), &img, &reference, w);
    }
}

#[test]
fn pt_pt_nee_and_every_bdpt_join_agree_on_glossy_cornell_box() {
    let (scene, camera) = glossy_cornell();
    let w = camera.width as usize;
    let reference = render(&scene, &camera, Integrator::PtNee, 512);
    let pt = render(&scene, &camera, Integrator::Pt, 2048);
    assert_agree("pt vs pt-nee", &pt, &reference, w);
    for join in [Join::Lvc(0), Join::Full, Join::K(4), Join::K(1)] {
        let img = render(&scene, &camera, Integrator::Bdpt(join), 256);
        assert_agree(&format!("{} vs pt-nee", Integrator::Bdpt(join).name()), &img, &reference, w);
    }
}

// ---- Normal maps ----------------------------------------------------------------------------

/// A 16x16 tangent-space normal map of sinusoidal bumps (X and Y up to ±0.5), linear RGBA8.
fn bumpy_normal_map() -> bidir::scene::Texture {
    let mut rgba8 = Vec::new();
    for y in 0..16 {
        for x in 0..16 {
            let (a, b) = (x as f32 * std::f32::consts::PI / 4.0, y as f32 * std::f32::consts::PI / 4.0);
            let n = Vec3::new(0.5 * a.sin(), 0.5 * b.cos(), 1.0).normalize();
            let enc = (n * 0.5 + Vec3::splat(0.5)) * 255.0;
            rgba8.extend([enc.x.round() as u8, enc.y.round() as u8, enc.z.round() as u8, 255]);
        }
    }
    bidir::scene::Texture { name: "bumps".into(), width: 16, height: 16, rgba8, srgb: false }
}

#[test]
fn integrators_agree_in_a_normal_mapped_glossy_furnace() {
    let (positions, tris) = geometry::icosphere(3, Vec3::ZERO, 1.0);
    let triangles: Vec<[u32; 3]> = tris.into_iter().map(|[a, b, c]| [a, c, b]).collect();
    let n = triangles.len();
    let normals = positions.iter().map(|p| -p.normalize()).collect();
    let uvs = positions.iter().map(|p| glam::Vec2::new(2.0 * p.x.atan2(p.z), 3.0 * p.y)).collect();
    let material = Material {
        name: "bumpy".into(),
        albedo: Vec3::new(0.7, 0.6, 0.5),
        emission: Vec3::splat(0.5),
        model: MaterialModel::MetalRough,
        metallic: 0.5,
        roughness: 0.4,
        normal_texture: Some(0),
        ..Default::default()
    };
    let scene = Scene {
        source: "test:normal-mapped-furnace".into(),
        positions,
        normals: Some(normals),
        uvs: Some(uvs),
        triangles,
        material_ids: vec![0; n],
        materials: vec![material],
        textures: vec![bumpy_normal_map()],
        ..Default::default()
    };
    let camera = inside_camera(64);
    let mut flat = scene.clone();
    flat.materials[0].normal_texture = None;
    let reference = render(&scene, &camera, Integrator::PtNee, 128);
    let unmapped = render(&flat, &camera, Integrator::PtNee, 32);
    let (a, b) = (reference.iter().sum::<f32>(), unmapped.iter().sum::<f32>());
    eprintln!("normal-mapped furnace: image mean {:.4} of the unmapped one", a / b);
    assert!((a / b - 1.0).abs() > 0.01, "the normal map changes nothing ({a} vs {b})");
    assert_agree("normal map: pt vs pt-nee", &render(&scene, &camera, Integrator::Pt, 128), &reference, 64);
    for join in [Join::Lvc(0), Join::Full] {
        let img = render(&scene, &camera, Integrator::Bdpt(join), 48);
        assert_agree(&format!("normal map: {} vs pt-nee", Integrator::Bdpt(join).name()), &img, &reference, 64);
    }
}

// ---- Alpha BLEND ------------------------------------------------------------------------------

/// A black quad of opacity 0.3 covering the view inside a furnace of radiance 1 with black
/// walls: every pixel sees 1 - 0.3 = 0.7 exactly, if paths pass with probability 1 - alpha.
#[test]
fn blend_passes_paths_with_probability_one_minus_alpha() {
    let (mut positions, tris) = geometry::icosphere(2, Vec3::ZERO, 1.0);
    let mut triangles: Vec<[u32; 3]> = tris.into_iter().map(|[a, b, c]| [a, c, b]).collect();
    let mut material_ids = vec![0; triangles.len()];
    let q = positions.len() as u32;
    positions.extend([Vec3::new(-0.6, -0.6, 0.5), Vec3::new(0.6, -0.6, 0.5), Vec3::new(0.6, 0.6, 0.5), Vec3::new(-0.6, 0.6, 0.5)]);
    triangles.extend([[q, q + 2, q + 1], [q, q + 3, q + 2]]);
    material_ids.extend([1, 1]);
    let walls = Material { name: "walls".into(), albedo: Vec3::ZERO, emission: Vec3::ONE, ..Default::default() };
    let veil = Material { name: "veil".into(), albedo: Vec3::ZERO, blend: Some(0.3), ..Default::default() };
    let scene =
        Scene { source: "test:blend".into(), positions, triangles, material_ids, materials: vec![walls, veil], ..Default::default() };
    let camera = Camera { name: "c".into(), eye: Vec3::ZERO, target: Vec3::Z, up: Vec3::Y, fov_y_deg: 60.0, width: 32, height: 32 };
    for (integrator, spp) in
        [(Integrator::Pt, 64), (Integrator::PtNee, 64), (Integrator::Bdpt(Join::Lvc(0)), 64), (Integrator::Bdpt(Join::Full), 64)]
    {
        let img = render(&scene, &camera, integrator, spp);
        let px: Vec<f64> = img.chunks_exact(3).map(|c| c[0] as f64).collect();
        let (mean, se) = mean_and_se(&px);
        eprintln!("blend 0.3: {}: {mean:.4} ± {se:.4} (expected 0.7)", integrator.name());
        assert!(se < 0.0025, "too noisy to resolve 1.5 %");
        assert!((mean - 0.7).abs() < 4.0 * se, "{}: {mean} ± {se}, expected 0.7", integrator.name());
    }
}
