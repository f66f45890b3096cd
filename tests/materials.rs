//! The rough dielectric (Walter et al. 2007, `glsl/common/rough_dielectric.glsl`; issue #13),
//! on lavapipe with validation:
//! - its sampling against its own pdf (Pearson's chi-square over a (cos θ, φ) grid of the
//!   whole sphere, refined toward the mirror and the refracted directions; failed samples are
//!   one more cell of probability one minus the pdf's integral) at roughness 0.05 / 0.3 / 0.8,
//!   entering and leaving glass, at several angles (past the critical angle too);
//! - reciprocity: f_radiance(wo, wi) = f_importance(wi, wo) (so the reflection is symmetric),
//!   the reverse pdf is the swapped forward pdf, and a sample's weight is f |cos| / pdf;
//! - energy: the single-scattering albedo (importance, so no eta^2) never exceeds one (loss
//!   printed per roughness and angle); a rough glass sphere of IOR 1.5 in a uniform
//!   environment of radiance 1 (white furnace) stays at or below 1, loss printed;
//! - pt, pt-nee and every BDPT join agree on a small Cornell box with rough thesis glass and
//!   tinted glTF rough transmission (block means of the difference against their own noise).

mod common;

use bidir::gpu::abi;
use bidir::gpu_data::SceneFeatures;
use bidir::render::{Integrator, Join, RenderSettings, Renderer};
use bidir::scene::{Camera, Environment, Material, MaterialModel, Scene};
use bidir::vk::Context;
use common::agree::{assert_agree, mean_and_se, render_with, ALPHA};
use common::sampling_kernel::SamplingKernel;
use common::sphere::{dv, edges_about, frame, Cells};
use common::stats::{self, Fit};
use common::{finish, geometry, gpu, Pcg};
use glam::{DVec3, Vec3, Vec4};
use std::f64::consts::PI;

const IOR: f64 = 1.5;
/// Samples per chi-square case.
const N: u32 = 1 << 17;
/// The shading normal of the sampling tests, tilted so the kernel's basis is not the world's.
const NORMAL: Vec3 = Vec3::new(-0.48, 0.36, 0.8);

fn push(mode: u32, count: u32, seed: u32, wo: DVec3, eta: f64, roughness: f64, radiance: bool) -> abi::SamplingTestPush {
    let alpha = (roughness * roughness).max(1e-3);
    abi::SamplingTestPush {
        mode,
        count,
        seed,
        a: wo.as_vec3().extend(0.0),
        b: NORMAL.normalize().extend(0.0),
        c: Vec4::new(eta as f32, alpha as f32, if radiance { 1.0 } else { 0.0 }, 0.0),
        ..Default::default()
    }
}

/// wo at `theta_deg` from the normal, and the z of its mirror and refracted directions
/// (cell edges go there).
fn incident(theta_deg: f64, eta: f64) -> (DVec3, Vec<f64>) {
    let n = NORMAL.as_dvec3().normalize();
    let (t, _) = frame(n);
    let th = theta_deg.to_radians();
    let wo = (n * th.cos() + t * th.sin()).normalize();
    let sin2_t = eta * eta * th.sin() * th.sin();
    // Peaks, and where the pdf jumps: wi.z = -eta wo.z puts the refracting microfacet
    // normal on the horizon, where D is not zero (so the pdf steps to zero there).
    let mut peaks = vec![th.cos(), 0.0, -eta * th.cos()];
    if sin2_t < 1.0 {
        peaks.push(-(1.0 - sin2_t).sqrt());
    }
    (wo, peaks)
}

/// Chi-square of rough_dielectric_sample_world against the integral of its pdf over cells.
fn check_sampling(ctx: &Context, kernel: &SamplingKernel, roughness: f64, eta: f64, theta_deg: f64, seed: u32) -> Fit {
    let n = NORMAL.as_dvec3().normalize();
    let (wo, peaks) = incident(theta_deg, eta);
    let cells = Cells::new(n, edges_about(&peaks, -1.0, 1.0, 1e-8), edges_about(&[0.0], -PI, PI, 1e-4));
    let (pairs, weights) = cells.quadrature(wo);
    let input = ctx.upload_buffer("rough.pairs", &pairs).unwrap();
    let evals = kernel.run(push(abi::SAMPLING_ROUGH_GLASS_EVAL, weights.len() as u32, 0, wo, eta, roughness, true), 2, Some(&input));
    let mut expected = cells.integrate(|k| evals[2 * k].z as f64, &weights);
    let failed = cells.count();
    let integral: f64 = expected.iter().sum();
    let case = format!("roughness {roughness}, eta {eta:.3}, {theta_deg}°");
    assert!(integral <= 1.0 + 2e-3, "{case}: the pdf integrates to {integral} > 1");
    expected[failed] = (1.0 - integral).max(1e-12);
    for e in &mut expected {
        *e *= N as f64;
    }
    let out = kernel.run(push(abi::SAMPLING_ROUGH_GLASS, N, seed, wo, eta, roughness, true), 2, None);
    let mut observed = vec![0u64; failed + 1];
    let mut refracted = 0u64;
    for s in out.chunks_exact(2) {
        if s[0].w == 0.0 {
            observed[failed] += 1;
            continue;
        }
        let d = dv(s[0]).normalize();
        let z = d.dot(n);
        assert!(s[1].y > 0.0, "{case}: a sampled direction has pdf {}", s[1].y);
        assert_eq!(s[1].w > 0.0, z < 0.0, "{case}: refracted flag {} for z = {z}", s[1].w);
        refracted += (z < 0.0) as u64;
        observed[cells.cell(d)] += 1;
    }
    let fit = stats::pearson(&observed, &expected);
    eprintln!(
        "{case}: pdf integral {integral:.5}, refracted {:.4}, failed {:.5} ({} cells -> {}): {fit}",
        refracted as f64 / N as f64,
        observed[failed] as f64 / N as f64,
        failed + 1,
        fit.cells
    );
    fit
}

#[test]
fn rough_dielectric_samples_follow_their_pdf() {
    let ctx = gpu();
    let kernel = SamplingKernel::new(&ctx);
    let mut cases = Vec::new();
    for roughness in [0.05, 0.3, 0.8] {
        // Entering (eta = 1 / 1.5) and leaving (1.5; 60° is past the critical 41.8°).
        cases.extend([(roughness, 1.0 / IOR, 0.0), (roughness, 1.0 / IOR, 70.0), (roughness, IOR, 30.0), (roughness, IOR, 60.0)]);
    }
    let fits: Vec<Fit> =
        cases.iter().enumerate().map(|(i, &(r, eta, th))| check_sampling(&ctx, &kernel, r, eta, th, 100 + i as u32)).collect();
    for (&(r, eta, th), f) in cases.iter().zip(&fits) {
        assert!(f.p >= ALPHA / fits.len() as f64, "roughness {r}, eta {eta}, {th}°: samples do not follow the pdf ({f})");
    }
    drop(kernel);
    finish(ctx);
}

/// A direction uniform on the sphere.
fn uniform_dir(rng: &mut Pcg) -> DVec3 {
    loop {
        let v = DVec3::new(rng.next_f32() as f64 * 2.0 - 1.0, rng.next_f32() as f64 * 2.0 - 1.0, rng.next_f32() as f64 * 2.0 - 1.0);
        let l = v.length();
        if l > 0.05 && l <= 1.0 {
            return v / l;
        }
    }
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs()).max(1e-3)
}

#[test]
fn rough_dielectric_is_reciprocal_and_weights_are_f_cos_over_pdf() {
    let ctx = gpu();
    let kernel = SamplingKernel::new(&ctx);
    let n = NORMAL.as_dvec3().normalize();
    let mut rng = Pcg::new(11);
    let count = 4096usize;
    let mut pairs = Vec::new();
    for _ in 0..count {
        let mut wo = uniform_dir(&mut rng);
        if wo.dot(n) < 0.0 {
            wo -= 2.0 * wo.dot(n) * n;
        }
        pairs.extend([wo.as_vec3().extend(0.0), uniform_dir(&mut rng).as_vec3().extend(0.0)]);
    }
    let input = ctx.upload_buffer("rough.pairs", &pairs).unwrap();
    for roughness in [0.05, 0.3, 0.8] {
        for eta in [1.0 / IOR, IOR] {
            let case = format!("roughness {roughness}, eta {eta:.3}");
            let e = kernel.run(push(abi::SAMPLING_ROUGH_GLASS_EVAL, count as u32, 0, DVec3::Z, eta, roughness, true), 2, Some(&input));
            let (mut nonzero, mut grazing) = (0, 0);
            for i in 0..count {
                let (a, s) = (e[2 * i], e[2 * i + 1]);
                let (wo, wi) = (pairs[2 * i].truncate().as_dvec3(), pairs[2 * i + 1].truncate().as_dvec3());
                let transmit = wi.dot(n) < 0.0;
                // Near the critical angle the f32 Fresnel term is ill-conditioned (its
                // transmission grows like the outer side's cosine, computed as the root of a
                // difference that cancels): pairs whose outer-side cosine to the refracting
                // microfacet is below 0.05 are counted, not judged.
                if transmit {
                    let h = (eta * wo + wi).normalize();
                    if (if eta > 1.0 { wi } else { wo }).dot(h).abs() < 0.05 {
                        grazing += 1;
                        continue;
                    }
                }
                // Radiance in one direction is importance in the other (Veach 1997, 5.2).
                assert!(close(a.x as f64, s.y as f64, 1e-3), "{case}: f_rad(a, b) {} vs f_imp(b, a) {}", a.x, s.y);
                assert!(close(a.y as f64, s.x as f64, 1e-3), "{case}: f_imp(a, b) {} vs f_rad(b, a) {}", a.y, s.x);
                assert!(close(a.w as f64, s.z as f64, 1e-3), "{case}: pdf_rev {} vs swapped pdf_fwd {}", a.w, s.z);
                let scale = if transmit { eta * eta } else { 1.0 };
                assert!(close(a.x as f64, a.y as f64 * scale, 1e-4), "{case}: radiance is not eta^2 x importance");
                assert!(a.x >= 0.0 && a.z >= 0.0, "{case}: negative f or pdf");
                nonzero += (a.x > 0.0 && a.w > 0.0) as usize;
            }
            assert!(nonzero > count / 4, "{case}: only {nonzero} pairs with f > 0");
            eprintln!("{case}: {nonzero} of {count} pairs with f > 0 reciprocal; {grazing} within the critical angle's margin not judged");
            // A sample's weight is f |cos| / pdf of its own direction, for radiance and importance.
            for radiance in [true, false] {
                let wo = pairs[0].truncate().as_dvec3();
                let s = kernel.run(push(abi::SAMPLING_ROUGH_GLASS, count as u32, 3, wo, eta, roughness, radiance), 2, None);
                let sampled: Vec<Vec4> =
                    s.chunks_exact(2).filter(|p| p[0].w > 0.0).flat_map(|p| [wo.as_vec3().extend(0.0), p[0]]).collect();
                let buf = ctx.upload_buffer("rough.sampled", &sampled).unwrap();
                let ev = kernel.run(
                    push(abi::SAMPLING_ROUGH_GLASS_EVAL, (sampled.len() / 2) as u32, 0, wo, eta, roughness, true),
                    2,
                    Some(&buf),
                );
                for (k, p) in s.chunks_exact(2).filter(|p| p[0].w > 0.0).enumerate() {
                    let f = if radiance { ev[2 * k].x } else { ev[2 * k].y } as f64;
                    let cos = (dv(p[0]).normalize().dot(n)).abs();
                    let pdf = ev[2 * k].z as f64;
                    assert!(close(p[1].y as f64, pdf, 2e-3), "{case}: sampled pdf {} vs evaluated {pdf}", p[1].y);
                    assert!(
                        close(p[1].z as f64, ev[2 * k].w as f64, 2e-3),
                        "{case}: sampled pdf_rev {} vs evaluated {}",
                        p[1].z,
                        ev[2 * k].w
                    );
                    assert!(close(p[1].x as f64, f * cos / pdf, 2e-3), "{case}: weight {} vs f cos / pdf {}", p[1].x, f * cos / pdf);
                }
            }
        }
    }
    drop((kernel, input));
    finish(ctx);
}

#[test]
fn rough_dielectric_never_gains_energy() {
    let ctx = gpu();
    let kernel = SamplingKernel::new(&ctx);
    let n = NORMAL.as_dvec3().normalize();
    let (t, _) = frame(n);
    eprintln!("single-scattering albedo of the rough dielectric, IOR 1.5 (importance; 1 - albedo is the loss):");
    for eta in [1.0 / IOR, IOR] {
        for roughness in [0.05, 0.3, 0.8] {
            let mut line = format!("  {} roughness {roughness:4}:", if eta < 1.0 { "entering" } else { "leaving " });
            for th in [0.0f64, 45.0, 80.0] {
                let wo = (n * th.to_radians().cos() + t * th.to_radians().sin()).normalize();
                let out = kernel.run(push(abi::SAMPLING_ROUGH_GLASS, N / 2, 7, wo, eta, roughness, false), 2, None);
                let w: Vec<f64> = out.chunks_exact(2).map(|s| if s[0].w > 0.0 { s[1].x as f64 } else { 0.0 }).collect();
                let mean = w.iter().sum::<f64>() / w.len() as f64;
                let var = w.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (w.len() - 1) as f64;
                let se = (var / w.len() as f64).sqrt();
                line += &format!(" {th}°: {mean:.4} ± {se:.4} (loss {:.2} %)", 100.0 * (1.0 - mean));
                assert!(w.iter().all(|&x| x >= 0.0), "negative weight");
                assert!(mean <= 1.0 + 4.0 * se, "roughness {roughness}, eta {eta}, {th}°: albedo {mean} ± {se} exceeds 1");
                if roughness <= 0.05 && th <= 45.0 {
                    assert!(mean > 0.99, "roughness {roughness}, {th}°: a near-smooth dielectric loses {:.2} %", 100.0 * (1.0 - mean));
                }
            }
            eprintln!("{line}");
        }
    }
    drop(kernel);
    finish(ctx);
}

// ---- Renders ---------------------------------------------------------------------------------

fn render(ctx: &Context, scene: &Scene, camera: &Camera, integrator: Integrator, spp: u32) -> Vec<f32> {
    let mut r = Renderer::new(ctx, scene, camera, RenderSettings::new(integrator)).unwrap();
    render_with(&mut r, integrator, spp)
}

/// Renders `spp` with `integrator` on a renderer that keeps its scene (only the integrator's
/// kernels are rebuilt).
/// A rough glass sphere (IOR 1.5, no absorption, flat facets) filling a 16x16 view, in a
/// uniform environment of radiance 1: every path ends in the environment, so a lossless BSDF
/// gives exactly 1 and single-scattering GGX somewhat less.
#[test]
fn rough_glass_sphere_in_a_white_furnace_stays_at_most_one() {
    let (positions, triangles) = geometry::icosphere(3, Vec3::ZERO, 1.0);
    let n = triangles.len();
    let camera =
        Camera { name: "c".into(), eye: Vec3::new(0.0, 0.0, 3.0), target: Vec3::ZERO, up: Vec3::Y, fov_y_deg: 24.0, width: 16, height: 16 };
    eprintln!("rough glass sphere (IOR 1.5) in a uniform environment of radiance 1:");
    let ctx = gpu();
    for roughness in [0.05f32, 0.3, 0.8] {
        let glass =
            Material { name: "glass".into(), albedo: Vec3::ZERO, refractivity: 1.0, ior: IOR as f32, roughness, ..Default::default() };
        assert!(glass.has_rough_glass());
        let scene = Scene {
            source: "test:rough-glass-furnace".into(),
            positions: positions.clone(),
            triangles: triangles.clone(),
            material_ids: vec![0; n],
            materials: vec![glass],
            environment: Some(Environment::uniform(Vec3::ONE)),
            ..Default::default()
        };
        // pt only: BDPT's rough-glass MIS is judged by the agreement test below.
        let img = render(&ctx, &scene, &camera, Integrator::Pt, 64);
        let px: Vec<f64> = img.chunks_exact(3).map(|c| c.iter().map(|&v| v as f64).sum::<f64>() / 3.0).collect();
        let (mean, se) = mean_and_se(&px);
        eprintln!("  roughness {roughness}: {mean:.4} ± {se:.4} (loss {:.2} %)", 100.0 * (1.0 - mean));
        assert!(mean <= 1.0 + 4.0 * se, "roughness {roughness}: {mean} ± {se} exceeds 1");
        if roughness <= 0.05 {
            assert!(mean > 0.99 - 4.0 * se, "roughness {roughness}: a near-smooth sphere loses {:.2} %", 100.0 * (1.0 - mean));
        }
    }
    finish(ctx);
}

/// The Cornell box with a rough thesis glass tall box (IOR 1.5, roughness 0.3) and a tinted
/// glTF transmission short box (roughness 0.5, 80 % transmission, metallic 0), 32x32. The
/// light is made 3 x 3 times larger: light reaching a wall through rough glass is found only
/// by BSDF sampling in pt and pt-nee (rough glass is never connected), which with the small
/// light is a rare, bright event that leaves per-pixel variance estimates short.
fn rough_glass_cornell() -> (Scene, Camera) {
    let mut s = Scene::builtin_cornell_box();
    let light = s.materials.iter().position(|m| m.name == "light").expect("the Cornell box has a light");
    let mut corners: Vec<u32> =
        s.triangles.iter().zip(&s.material_ids).filter(|(_, &m)| m as usize == light).flat_map(|(t, _)| *t).collect();
    corners.sort_unstable();
    corners.dedup();
    let centre = corners.iter().map(|&i| s.positions[i as usize]).sum::<Vec3>() / corners.len() as f32;
    for &i in &corners {
        let p = &mut s.positions[i as usize];
        *p = Vec3::new(centre.x + 3.0 * (p.x - centre.x), p.y, centre.z + 3.0 * (p.z - centre.z));
    }
    for m in &mut s.materials {
        match m.name.as_str() {
            "tallBox" => {
                m.refractivity = 1.0;
                m.ior = 1.5;
                m.roughness = 0.3;
            }
            "shortBox" => {
                m.model = MaterialModel::MetalRough;
                m.albedo = Vec3::new(0.9, 0.6, 0.3);
                m.refractivity = 0.8;
                m.roughness = 0.5;
                m.ior = 1.4;
            }
            _ => {}
        }
    }
    assert!(s.materials.iter().filter(|m| m.has_rough_glass()).count() == 2);
    let mut camera = s.cameras[0].clone();
    camera.width = 32;
    camera.height = 32;
    (s, camera)
}

#[test]
fn pt_pt_nee_and_every_bdpt_join_agree_on_rough_glass() {
    let (scene, camera) = rough_glass_cornell();
    let w = camera.width as usize;
    let ctx = gpu();
    // The rough-glass code is compiled in and taken (both glass materials have roughness > 0).
    assert!(SceneFeatures::of(&scene).rough_glass);
    let mut r = Renderer::new(&ctx, &scene, &camera, RenderSettings::new(Integrator::PtNee)).unwrap();
    let reference = render_with(&mut r, Integrator::PtNee, 128);
    assert_agree("rough glass: pt vs pt-nee", &render_with(&mut r, Integrator::Pt, 384), &reference, w);
    for (join, spp) in [(Join::Lvc(0), 48), (Join::Full, 24), (Join::K(1), 48)] {
        let img = render_with(&mut r, Integrator::Bdpt(join), spp);
        assert_agree(&format!("rough glass: {} vs pt-nee", Integrator::Bdpt(join).name()), &img, &reference, w);
    }
    drop(r);
    finish(ctx);
}

// ---- glTF transmissionTexture ---------------------------------------------------------------

/// Writes a glTF quad (z = 0, facing +z, 2 x 2 units, UVs 0..1) whose material has
/// KHR_materials_transmission with factor 1 and a 2 x 2 linear transmission texture of value
/// `texel` (red channel), roughness 0.4, base colour (0.9, 0.7, 0.5).
fn transmission_gltf(texel: u8) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("bidir-materials-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let rgba: Vec<u8> = (0..4).flat_map(|_| [texel, 0, 0, 255]).collect();
    image::save_buffer(dir.join("t.png"), &rgba, 2, 2, image::ExtendedColorType::Rgba8).unwrap();
    let mut bin = Vec::new();
    for p in [[-1.0f32, -1.0, 0.0], [1.0, -1.0, 0.0], [1.0, 1.0, 0.0], [-1.0, 1.0, 0.0]] {
        bin.extend(p.iter().flat_map(|v| v.to_le_bytes()));
    }
    for uv in [[0.0f32, 1.0], [1.0, 1.0], [1.0, 0.0], [0.0, 0.0]] {
        bin.extend(uv.iter().flat_map(|v| v.to_le_bytes()));
    }
    bin.extend([0u16, 1, 2, 0, 2, 3].iter().flat_map(|i| i.to_le_bytes()));
    std::fs::write(dir.join("q.bin"), &bin).unwrap();
    let json = format!(
        r#"{{"asset": {{"version": "2.0"}}, "extensionsUsed": ["KHR_materials_transmission"],
 "scene": 0, "scenes": [{{"nodes": [0]}}], "nodes": [{{"mesh": 0}}],
 "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0, "TEXCOORD_0": 1}}, "indices": 2, "material": 0}}]}}],
 "materials": [{{"name": "glass", "pbrMetallicRoughness": {{"baseColorFactor": [0.9, 0.7, 0.5, 1], "metallicFactor": 0, "roughnessFactor": 0.4}},
   "extensions": {{"KHR_materials_transmission": {{"transmissionFactor": 1, "transmissionTexture": {{"index": 0}}}}}}}}],
 "textures": [{{"source": 0}}], "images": [{{"uri": "t.png"}}],
 "buffers": [{{"uri": "q.bin", "byteLength": {len}}}],
 "bufferViews": [{{"buffer": 0, "byteOffset": 0, "byteLength": 48}}, {{"buffer": 0, "byteOffset": 48, "byteLength": 32}},
   {{"buffer": 0, "byteOffset": 80, "byteLength": 12}}],
 "accessors": [{{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]}},
   {{"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"}},
   {{"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}}]}}"#,
        len = bin.len()
    );
    let path = dir.join("q.gltf");
    std::fs::write(&path, json).unwrap();
    path
}

/// A transmission texture of value t scales the glass fraction: three copies of the loaded
/// quad side by side, in one render (pt, uniform environment of radiance 1, 8 x 8 pixels
/// each): factor 1 x texture 128/255 (as loaded), factor 128/255 without a texture (the same
/// expectation), and factor 1 without a texture (far from it, so the comparison has power).
#[test]
fn gltf_transmission_texture_scales_the_glass_fraction() {
    let path = transmission_gltf(128);
    let loaded = bidir::scene::load(&path, &bidir::scene::LoadOptions { strict: true }).unwrap();
    assert!(loaded.warnings.is_empty(), "warnings: {:?}", loaded.warnings);
    let mut scene = loaded.scene;
    let m = scene.materials[0].clone();
    assert_eq!((m.refractivity, m.model), (1.0, MaterialModel::MetalRough));
    assert!(m.transmission_texture.is_some() && m.has_rough_glass(), "{}", m.describe());
    assert!(m.describe().contains("transmission map"), "{}", m.describe());
    let quad = (scene.positions.clone(), scene.triangles.clone(), scene.uvs.clone().unwrap());
    for (k, refractivity) in [(1u32, 128.0 / 255.0), (2, 1.0)] {
        let base = scene.positions.len() as u32;
        scene.positions.extend(quad.0.iter().map(|p| *p + Vec3::new(-2.5 * k as f32, 0.0, 0.0)));
        scene.uvs.as_mut().unwrap().extend(&quad.2);
        scene.triangles.extend(quad.1.iter().map(|t| t.map(|i| i + base)));
        scene.material_ids.extend(quad.1.iter().map(|_| k));
        scene.materials.push(Material { transmission_texture: None, refractivity, ..m.clone() });
    }
    scene.environment = Some(Environment::uniform(Vec3::ONE));
    // Camera right = forward x up = +x: the quads at x = -5, -2.5, 0 fill the image's thirds
    // left to right (2.5 units per third: tan(fov / 2) = 1.25 / 10).
    let camera = Camera {
        name: "c".into(),
        eye: Vec3::new(-2.5, 0.0, 10.0),
        target: Vec3::new(-2.5, 0.0, 0.0),
        up: Vec3::Y,
        fov_y_deg: 2.0 * 0.125f32.atan().to_degrees(),
        width: 24,
        height: 8,
    };
    let ctx = gpu();
    let img = render(&ctx, &scene, &camera, Integrator::Pt, 256);
    finish(ctx);
    // The middle 6 x 6 pixels of the image's third q (inside its quad).
    let px = |q: usize| -> Vec<f64> {
        (1..7)
            .flat_map(|y| (1..7).map(move |x| (x + 8 * q, y)))
            .map(|(x, y)| img[3 * (y * 24 + x)..][..3].iter().map(|&v| v as f64).sum())
            .collect()
    };
    let (full, factor, textured) = (px(0), px(1), px(2));
    let diff: Vec<f64> = textured.iter().zip(&factor).map(|(a, b)| a - b).collect();
    let (m, se) = mean_and_se(&diff);
    let (level, level_se) = mean_and_se(&factor);
    let (full, _) = mean_and_se(&full);
    eprintln!(
        "transmission texture 128/255 vs factor 128/255: {:+.3} % ± {:.3} % of {level:.4}; factor 1: {full:.4}",
        100.0 * m / level,
        100.0 * se / level
    );
    assert!(m.abs() <= 3.29 * se.max(1e-3 * level), "the texture does not scale the glass fraction as the factor does ({m} ± {se})");
    assert!((full - level).abs() > 10.0 * level_se.max(se), "the glass fraction does not matter here ({full} vs {level} ± {level_se})");
}

// ---- Texture coordinate sets and KHR_texture_transform --------------------------------------

/// A quad with two UV sets whose material reads set 1 through a texture transform (offset
/// (0.5, 0.25), a quarter turn, scale (2, 3)); and a second primitive, sharing the accessors,
/// whose material reads set 0 untransformed. The loaded UVs are the transformed set 1 and the
/// plain set 0, and nothing is warned about.
#[test]
fn gltf_texcoord_sets_and_texture_transform_are_baked_into_the_uvs() {
    let dir = std::env::temp_dir().join(format!("bidir-materials-uv-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    image::save_buffer(dir.join("c.png"), &[200u8, 100, 50, 255].repeat(4), 2, 2, image::ExtendedColorType::Rgba8).unwrap();
    let positions = [[-1.0f32, -1.0, 0.0], [1.0, -1.0, 0.0], [1.0, 1.0, 0.0], [-1.0, 1.0, 0.0]];
    let uv0 = [[0.0f32, 1.0], [1.0, 1.0], [1.0, 0.0], [0.0, 0.0]];
    let uv1 = [[0.1f32, 0.2], [0.7, 0.2], [0.7, 0.9], [0.1, 0.9]];
    let mut bin: Vec<u8> =
        positions.iter().flatten().chain(uv0.iter().flatten()).chain(uv1.iter().flatten()).flat_map(|v| v.to_le_bytes()).collect();
    bin.extend([0u16, 1, 2, 0, 2, 3].iter().flat_map(|i| i.to_le_bytes()));
    std::fs::write(dir.join("uv.bin"), &bin).unwrap();
    let json = format!(
        r#"{{"asset": {{"version": "2.0"}}, "extensionsUsed": ["KHR_texture_transform"],
 "scene": 0, "scenes": [{{"nodes": [0]}}], "nodes": [{{"mesh": 0}}],
 "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0, "TEXCOORD_0": 1, "TEXCOORD_1": 2}}, "indices": 3, "material": 0}},
                            {{"attributes": {{"POSITION": 0, "TEXCOORD_0": 1, "TEXCOORD_1": 2}}, "indices": 3, "material": 1}}]}}],
 "materials": [{{"pbrMetallicRoughness": {{"baseColorTexture": {{"index": 0, "texCoord": 1,
                  "extensions": {{"KHR_texture_transform": {{"offset": [0.5, 0.25], "rotation": 1.5707963267948966, "scale": [2, 3]}}}}}}}}}},
               {{"pbrMetallicRoughness": {{"baseColorTexture": {{"index": 0}}}}}}],
 "textures": [{{"source": 0}}], "images": [{{"uri": "c.png"}}],
 "buffers": [{{"uri": "uv.bin", "byteLength": {len}}}],
 "bufferViews": [{{"buffer": 0, "byteOffset": 0, "byteLength": 48}}, {{"buffer": 0, "byteOffset": 48, "byteLength": 32}},
   {{"buffer": 0, "byteOffset": 80, "byteLength": 32}}, {{"buffer": 0, "byteOffset": 112, "byteLength": 12}}],
 "accessors": [{{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]}},
   {{"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"}},
   {{"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"}},
   {{"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}}]}}"#,
        len = bin.len()
    );
    let path = dir.join("uv.gltf");
    std::fs::write(&path, json).unwrap();
    let loaded = bidir::scene::load(&path, &bidir::scene::LoadOptions { strict: true }).unwrap();
    assert!(loaded.warnings.is_empty(), "warnings: {:?}", loaded.warnings);
    let s = loaded.scene;
    let uvs = s.uvs.as_ref().expect("UVs");
    // uv' = offset + R(quarter turn) S uv, R = [[cos, sin], [-sin, cos]]: (u, v) -> (3 v, -2 u).
    let expect = |[u, v]: [f32; 2]| glam::Vec2::new(0.5 + 3.0 * v, 0.25 - 2.0 * u);
    for (t, &m) in s.triangles.iter().zip(&s.material_ids) {
        for &i in t {
            let p = s.positions[i as usize];
            let k = positions.iter().position(|q| glam::Vec3::from(*q) == p).expect("a quad corner");
            let want = if m == 0 { expect(uv1[k]) } else { glam::Vec2::from(uv0[k]) };
            assert!((uvs[i as usize] - want).length() < 1e-5, "material {m}, corner {k}: uv {} instead of {want}", uvs[i as usize]);
        }
    }
    assert_eq!(s.material_ids.iter().filter(|&&m| m == 0).count(), 2);
}

// ---- Tangents from the file -----------------------------------------------------------------

/// A glTF quad with NORMAL, TEXCOORD_0 and TANGENT (+y, handedness -1: not what the UVs would
/// generate, +x and +1), instanced by a node mirrored in x: the scene keeps the file's tangents,
/// transformed by the node's matrix, with the handedness flipped by the mirror, and the GPU
/// upload takes them instead of generated ones.
#[test]
fn gltf_tangents_from_the_file_are_used() {
    let dir = std::env::temp_dir().join(format!("bidir-materials-tangent-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let positions = [[-1.0f32, -1.0, 0.0], [1.0, -1.0, 0.0], [1.0, 1.0, 0.0], [-1.0, 1.0, 0.0]];
    let normals = [[0.0f32, 0.0, 1.0]; 4];
    let uvs = [[0.0f32, 1.0], [1.0, 1.0], [1.0, 0.0], [0.0, 0.0]];
    let tangents = [[0.0f32, 1.0, 0.0, -1.0]; 4];
    let mut bin: Vec<u8> = positions
        .iter()
        .flatten()
        .chain(normals.iter().flatten())
        .chain(uvs.iter().flatten())
        .chain(tangents.iter().flatten())
        .flat_map(|v| v.to_le_bytes())
        .collect();
    bin.extend([0u16, 1, 2, 0, 2, 3].iter().flat_map(|i| i.to_le_bytes()));
    std::fs::write(dir.join("t.bin"), &bin).unwrap();
    let json = format!(
        r#"{{"asset": {{"version": "2.0"}}, "scene": 0, "scenes": [{{"nodes": [0]}}], "nodes": [{{"mesh": 0, "scale": [-2, 1, 1]}}],
 "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2, "TANGENT": 3}}, "indices": 4}}]}}],
 "buffers": [{{"uri": "t.bin", "byteLength": {len}}}],
 "bufferViews": [{{"buffer": 0, "byteOffset": 0, "byteLength": 48}}, {{"buffer": 0, "byteOffset": 48, "byteLength": 48}},
   {{"buffer": 0, "byteOffset": 96, "byteLength": 32}}, {{"buffer": 0, "byteOffset": 128, "byteLength": 64}},
   {{"buffer": 0, "byteOffset": 192, "byteLength": 12}}],
 "accessors": [{{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]}},
   {{"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"}},
   {{"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"}},
   {{"bufferView": 3, "componentType": 5126, "count": 4, "type": "VEC4"}},
   {{"bufferView": 4, "componentType": 5123, "count": 6, "type": "SCALAR"}}]}}"#,
        len = bin.len()
    );
    let path = dir.join("t.gltf");
    std::fs::write(&path, json).unwrap();
    let loaded = bidir::scene::load(&path, &bidir::scene::LoadOptions { strict: true }).unwrap();
    assert!(loaded.warnings.is_empty(), "warnings: {:?}", loaded.warnings);
    let s = loaded.scene;
    let t = s.tangents.as_ref().expect("the file's tangents are kept");
    assert_eq!(t.len(), s.positions.len());
    for v in t {
        // diag(-2, 1, 1) keeps +y; the mirror flips the handedness -1 to +1.
        assert!((v.truncate() - Vec3::Y).length() < 1e-6 && v.w == 1.0, "{v}");
    }
    assert_eq!(bidir::scene::tangents::generate(&s).as_ref(), Some(t), "the upload must take the file's tangents");
    let mut without = s.clone();
    without.tangents = None;
    let generated = bidir::scene::tangents::generate(&without).unwrap();
    assert!(generated.iter().all(|g| g.truncate().dot(Vec3::Y).abs() < 1e-6), "generated tangents follow u (along x): {generated:?}");
}
