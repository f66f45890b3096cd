//! glTF material extensions rendered, on scenes written as glTF by the test and loaded with
//! `--strict`. KHR_materials_volume: Beer-Lambert absorption inside closed meshes
//! (docs/integrators.md, "Volumes"):
//!
//! 1. A slab of thickness d = 2 (a closed box) of transmitting glass with attenuationColor c
//!    and attenuationDistance 2 (sigma_a = −ln(c) / 2, so exp(−sigma_a d) = c) in front of a
//!    one-sided emitter of radiance Le that absorbs everything, seen at normal incidence. An
//!    incoherent sum over the internal reflections (each round trip R² T²) gives, per channel,
//!    L = Le (1 − R)² T / (1 − R² T²) with T = exp(−sigma_a d) and R = ((n − 1) / (n + 1))²;
//!    index-matched (n = 1, R = 0): L = Le T exactly, a deterministic estimate for every
//!    integrator; n = 1.5: a Fresnel coin at each face, judged within 4 standard errors.
//! 2. pt, pt-nee and BDPT (the light vertex cache: its joins are the full join's) agree on a small room with a
//!    partly transmitting, absorbing glass cube holding a diffuse cube: camera and light
//!    vertices on the glass' inner faces connect through the volume (both ends inside), and
//!    the segments between the inner cube and the glass are attenuated from either end.
//!
//! KHR_materials_specular (docs/integrators.md, "Glossy materials"): a quad seen at 70° from
//! its normal in a uniform environment of radiance 1:
//! 3. specularFactor 0 leaves a pure Lambertian base: every pixel's expectation is the base
//!    colour, per channel, within 4 standard errors (at the default specularFactor 1 the coat
//!    moves it by several percent: the test shows the difference it resolves);
//! 4. over a black base the reflection is the coat's alone, specularFactor times
//!    Schlick(F0, F90 = 1) times GGX, and the same random numbers take the same paths: it is
//!    exactly linear in specularFactor (0.5 gives half; specularTexture's alpha scales it) and
//!    affine in F0 (specularColorFactor times the sRGB specularColorTexture, clamped to 1),
//!    checked to float rounding.
//!
//! KHR_materials_clearcoat (docs/integrators.md, "Clear coat"):
//! 5. the same quad renders, with pt-nee, pt and BDPT, the directional albedo that the BSDF's
//!    own sampling (glsl/tests/sampling.comp) gives for the coat's factors and textures;
//!    clearcoatFactor 0 is the bare material;
//! 6. pt, BDPT and VCM agree with pt-nee on a room with coated cubes;
//! 7. bad factors and texture indices are errors naming the material.

mod common;

use bidir::gpu_data::SceneFeatures;
use bidir::render::gpu_scene::gpu_material;
use bidir::render::{Integrator, Join, RenderSettings, Renderer};
use bidir::scene::{load, Camera, Environment, LoadOptions, Material, MaterialModel, Scene};
use bidir::vk::Context;
use common::agree::{assert_agree, mean_and_se, render_with};
use common::gltf_out::{self, Mesh};
use common::sampling_kernel::SamplingKernel;
use common::{finish, gpu};
use glam::Vec3;

const LE: f64 = 2.0;
const COLOUR: [f32; 3] = [0.5, 0.7, 0.9];
const THICKNESS: f32 = 2.0;

/// A glTF material: transmission `transmission` (the rest diffuse under a GGX coat), `ior`,
/// roughness 0 (smooth glass), base colour `base`, and a volume of attenuationColor `colour`
/// over attenuationDistance `distance`.
fn glass(transmission: f32, ior: f32, base: [f32; 3], colour: [f32; 3], distance: f32) -> String {
    format!(
        r#"{{"name": "glass", "pbrMetallicRoughness": {{"baseColorFactor": [{}, {}, {}, 1], "metallicFactor": 0, "roughnessFactor": 0}},
  "extensions": {{"KHR_materials_transmission": {{"transmissionFactor": {transmission}}}, "KHR_materials_ior": {{"ior": {ior}}},
   "KHR_materials_volume": {{"thicknessFactor": 1, "attenuationColor": [{}, {}, {}], "attenuationDistance": {distance}}}}}}}"#,
        base[0], base[1], base[2], colour[0], colour[1], colour[2]
    )
}

fn diffuse(name: &str, c: [f32; 3]) -> String {
    format!(
        r#"{{"name": "{name}", "pbrMetallicRoughness": {{"baseColorFactor": [{}, {}, {}, 1], "metallicFactor": 0, "roughnessFactor": 1}}}}"#,
        c[0], c[1], c[2]
    )
}

fn emitter(strength: f64) -> String {
    format!(
        r#"{{"name": "emitter", "pbrMetallicRoughness": {{"baseColorFactor": [0, 0, 0, 1], "metallicFactor": 0, "roughnessFactor": 1}},
  "emissiveFactor": [1, 1, 1], "extensions": {{"KHR_materials_emissive_strength": {{"emissiveStrength": {strength}}}}}}}"#
    )
}

const EXTENSIONS: [&str; 4] =
    ["KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_volume", "KHR_materials_emissive_strength"];

/// Loads a written glTF strictly: no warnings.
fn load_strict(path: &std::path::Path) -> Scene {
    let loaded = load(path, &LoadOptions { strict: true }).unwrap_or_else(|e| panic!("{e}"));
    assert!(loaded.warnings.is_empty(), "warnings: {:?}", loaded.warnings);
    loaded.scene
}

/// Bad extension values are errors naming the file, the material and the extension.
#[test]
fn bad_volume_and_specular_values_are_errors() {
    let quad = || [Mesh::quad(Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z, 0)];
    let cases = [
        ("distance", glass(1.0, 1.5, [1.0; 3], COLOUR, -1.0), "KHR_materials_volume"),
        ("colour", glass(1.0, 1.5, [1.0; 3], [1.5, 0.5, 0.5], 1.0), "KHR_materials_volume"),
        (
            "specular",
            r#"{"name": "glass", "extensions": {"KHR_materials_specular": {"specularFactor": 2}}}"#.to_owned(),
            "KHR_materials_specular",
        ),
    ];
    for (name, material, what) in cases {
        let path = gltf_out::write(&format!("bad-{name}"), &quad(), &[material], &EXTENSIONS, &[]);
        let e = load(&path, &LoadOptions { strict: true }).map(|_| ()).expect_err(name).to_string();
        assert!(e.contains("bad-") && e.contains("material 0 \"glass\"") && e.contains(what), "{name}: {e}");
    }
}

/// The slab [-4, 4] x [-4, 4] x [-1, 1], the emitter z = -3 facing +z, and a camera at
/// z = 10 looking down -z with a 0.5° field of view: rays at most 0.36° off normal, so paths
/// in the glass are longer than d by a factor below 1 + 2e-5 and R changes by less than 1e-8.
fn slab(ior: f32) -> (Scene, Camera) {
    let meshes = [
        Mesh::cuboid(Vec3::new(-4.0, -4.0, -1.0), Vec3::new(4.0, 4.0, 1.0), 0),
        Mesh::quad(Vec3::new(-30.0, -30.0, -3.0), Vec3::X * 60.0, Vec3::Y * 60.0, Vec3::Z, 1),
    ];
    let path =
        gltf_out::write(&format!("slab-{ior}"), &meshes, &[glass(1.0, ior, [1.0; 3], COLOUR, THICKNESS), emitter(LE)], &EXTENSIONS, &[]);
    let mut scene = load_strict(&path);
    // glTF's metal-rough model always has a specular coat, which would reflect the slab's
    // reflection of the emitter back through it: make the emitter a black thesis material.
    scene.materials[1].model = MaterialModel::Thesis;
    let m = &scene.materials[0];
    assert!(m.has_volume() && m.describe().contains("volume"), "{}", m.describe());
    for (c, s) in COLOUR.iter().zip(m.absorption.to_array()) {
        assert!((s - -c.ln() / THICKNESS).abs() < 1e-6, "sigma_a {} from colour {COLOUR:?}", m.absorption);
    }
    assert!(SceneFeatures::of(&scene).volume);
    let camera = Camera {
        name: "slab".into(),
        eye: Vec3::new(0.0, 0.0, 10.0),
        target: Vec3::ZERO,
        up: Vec3::Y,
        fov_y_deg: 0.5,
        width: 16,
        height: 16,
    };
    (scene, camera)
}

/// Per channel: the image mean over Le and its standard error (pixels are independent).
fn channel_means(img: &[f32]) -> [(f64, f64); 3] {
    [0, 1, 2].map(|c| mean_and_se(&img.chunks_exact(3).map(|p| p[c] as f64 / LE).collect::<Vec<_>>()))
}

/// Renders the slab with pt, pt-nee and BDPT and checks each channel against
/// (1 − R)² T / (1 − R² T²): within 4 standard errors plus `float_tol` (relative).
fn check_slab(ctx: &Context, ior: f32, spp: u32, float_tol: f64) {
    let (scene, camera) = slab(ior);
    let r = ((ior as f64 - 1.0) / (ior as f64 + 1.0)).powi(2);
    let mut renderer = Renderer::new(ctx, &scene, &camera, RenderSettings::new(Integrator::Pt)).unwrap();
    for integrator in [Integrator::Pt, Integrator::PtNee, Integrator::Bdpt(Join::Lvc(0))] {
        let img = render_with(&mut renderer, integrator, spp);
        for (c, (mean, se)) in channel_means(&img).into_iter().enumerate() {
            let t = COLOUR[c] as f64;
            let expect = (1.0 - r).powi(2) * t / (1.0 - r * r * t * t);
            let tol = 4.0 * se + float_tol * expect;
            eprintln!(
                "ior {ior}, {}: channel {c}: {mean:.6} vs {expect:.6} ({:+.4} %), tolerance {:.4} %",
                integrator.name(),
                100.0 * (mean / expect - 1.0),
                100.0 * tol / expect
            );
            // The test has power: the tolerance must resolve a tenth of the absorption itself.
            assert!(tol < 0.1 * (1.0 - t) * expect, "{}: too noisy ({:.3} %)", integrator.name(), 100.0 * tol / expect);
            assert!(
                (mean - expect).abs() <= tol,
                "ior {ior}, {}, channel {c}: {mean:.6} vs {expect:.6} (tolerance {tol:.6})",
                integrator.name()
            );
        }
    }
}

/// Index-matched (n = 1), every path is the straight line through the slab, so each estimate
/// is exact up to float rounding (1e-4: the segment lengths lose a few ulps to the ray
/// offsets); at n = 1.5 the Fresnel coin at each face makes it noisy and 4 SE is the
/// tolerance.
#[test]
fn absorbing_slab_transmits_exp_minus_sigma_d_times_fresnel() {
    let ctx = gpu();
    check_slab(&ctx, 1.0, 4, 1e-4);
    check_slab(&ctx, 1.5, 48, 0.0);
    finish(ctx);
}

/// A floor, a back wall and a ceiling light; on the floor a glass cube (70 % smooth
/// transmission, the rest diffuse, IOR 1.5, absorbing) holding a small red diffuse cube.
fn room() -> (Scene, Camera) {
    let meshes = [
        Mesh::quad(Vec3::new(-3.0, 0.0, -3.0), Vec3::X * 6.0, Vec3::Z * 6.0, Vec3::Y, 1),
        Mesh::quad(Vec3::new(-3.0, 0.0, -3.0), Vec3::X * 6.0, Vec3::Y * 5.0, Vec3::Z, 1),
        Mesh::quad(Vec3::new(-1.5, 4.0, -1.5), Vec3::X * 3.0, Vec3::Z * 3.0, -Vec3::Y, 3),
        Mesh::cuboid(Vec3::new(-1.0, 0.2, -1.0), Vec3::new(1.0, 2.2, 1.0), 0),
        Mesh::cuboid(Vec3::new(-0.35, 0.5, -0.35), Vec3::new(0.35, 1.2, 0.35), 2),
    ];
    let materials = [
        glass(0.7, 1.5, [0.95, 0.9, 0.8], [0.3, 0.6, 0.9], 1.0),
        diffuse("white", [0.8; 3]),
        diffuse("red", [0.8, 0.3, 0.2]),
        emitter(6.0),
    ];
    let scene = load_strict(&gltf_out::write("room", &meshes, &materials, &EXTENSIONS, &[]));
    assert!(SceneFeatures::of(&scene).volume);
    let camera = Camera {
        name: "room".into(),
        eye: Vec3::new(0.0, 1.6, 5.0),
        target: Vec3::new(0.0, 1.1, 0.0),
        up: Vec3::Y,
        fov_y_deg: 40.0,
        width: 32,
        height: 32,
    };
    (scene, camera)
}

#[test]
fn pt_pt_nee_and_bdpt_agree_through_an_absorbing_glass_cube() {
    let (scene, camera) = room();
    let w = camera.width as usize;
    let ctx = gpu();
    let mut r = Renderer::new(&ctx, &scene, &camera, RenderSettings::new(Integrator::PtNee)).unwrap();
    let reference = render_with(&mut r, Integrator::PtNee, 96);
    assert_agree("volume: pt vs pt-nee", &render_with(&mut r, Integrator::Pt, 192), &reference, w);
    assert_agree("volume: bdpt vs pt-nee", &render_with(&mut r, Integrator::Bdpt(Join::Lvc(0)), 40), &reference, w);
    drop(r);
    finish(ctx);
}

// ---- KHR_materials_specular ------------------------------------------------------------------

const BASE: [f32; 3] = [0.6, 0.45, 0.3];
/// specularColorFactor of most cases.
const TINT: &str = "[1, 0.8, 0.6]";

/// Renders (`integrator`, `spp`) a 16x16 view of a large quad (facing +z) of material
/// `material` (glTF JSON, using `extension`, reading `textures`) seen at 70° from its normal
/// in a uniform white environment; returns the per-channel means and standard errors, the
/// direction toward the eye and the loaded scene.
fn furnace_quad(
    ctx: &Context,
    name: &str,
    material: String,
    extension: &str,
    textures: &[[u8; 4]],
    integrator: Integrator,
    spp: u32,
) -> ([(f64, f64); 3], Vec3, Scene) {
    let quad = Mesh::quad(Vec3::new(-20.0, -20.0, 0.0), Vec3::X * 40.0, Vec3::Y * 40.0, Vec3::Z, 0);
    let mut scene = load_strict(&gltf_out::write(name, &[quad], &[material], &[extension], textures));
    scene.environment = Some(Environment::uniform(Vec3::ONE));
    let a = 70f32.to_radians();
    let eye = Vec3::new(0.0, -a.sin(), a.cos()) * 10.0;
    let camera = Camera { name: "quad".into(), eye, target: Vec3::ZERO, up: Vec3::Z, fov_y_deg: 5.0, width: 16, height: 16 };
    let mut r = Renderer::new(ctx, &scene, &camera, RenderSettings::new(integrator)).unwrap();
    let img = render_with(&mut r, integrator, spp);
    drop(r);
    ([0, 1, 2].map(|c| mean_and_se(&img.chunks_exact(3).map(|p| p[c] as f64).collect::<Vec<_>>())), eye.normalize(), scene)
}

/// `furnace_quad` (pt-nee, `spp`) of a metal-rough material with base colour `base`, roughness
/// 0.4 and the KHR_materials_specular object `{specular}` (JSON members), reading `textures`.
fn specular_quad(ctx: &Context, base: [f32; 3], specular: &str, textures: &[[u8; 4]], spp: u32) -> [(f64, f64); 3] {
    let material = format!(
        r#"{{"name": "coat", "pbrMetallicRoughness": {{"baseColorFactor": [{}, {}, {}, 1], "metallicFactor": 0, "roughnessFactor": 0.4}},
  "extensions": {{"KHR_materials_specular": {{{specular}}}}}}}"#,
        base[0], base[1], base[2]
    );
    let name = format!("specular-{}", specular.chars().filter(char::is_ascii_alphanumeric).collect::<String>());
    let (means, _, scene) = furnace_quad(ctx, &name, material, "KHR_materials_specular", textures, Integrator::PtNee, spp);
    let m = &scene.materials[0];
    assert!(m.describe().contains("specular"), "{}", m.describe());
    assert_eq!(m.specular_texture.is_some() || m.specular_colour_texture.is_some(), !textures.is_empty(), "{}", m.describe());
    means
}

/// What the kernels read: the coat's F0 before the clamp, F0(ior) x specularColorFactor;
/// specularFactor and the texture slots pass through.
#[test]
fn specular_colour_scales_the_coat_f0() {
    let m = Material {
        model: MaterialModel::MetalRough,
        ior: 1.5,
        specular: 0.7,
        specular_colour: Vec3::new(100.0, 0.8, 0.6),
        specular_colour_texture: Some(2),
        ..Default::default()
    };
    let g = gpu_material(&m);
    assert!((g.specular_f0 - Vec3::new(4.0, 0.032, 0.024)).abs().max_element() < 1e-6, "{}", g.specular_f0);
    assert_eq!((g.specular, g.specular_texture, g.specular_colour_texture), (0.7, 0, 3));
}

/// sRGB-encoded 8-bit value to linear (the sRGB transfer function, IEC 61966-2-1).
fn srgb(v: u8) -> f64 {
    let c = v as f64 / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

#[test]
fn specular_factor_colour_and_textures_scale_the_coat_and_zero_leaves_the_lambertian_base() {
    let ctx = gpu();
    // 3. specularFactor 0: the base colour exactly, in expectation.
    let lambert = specular_quad(&ctx, BASE, &format!(r#""specularFactor": 0, "specularColorFactor": {TINT}"#), &[], 16);
    let coated = specular_quad(&ctx, BASE, &format!(r#""specularColorFactor": {TINT}"#), &[], 16);
    for c in 0..3 {
        let ((mean, se), (with_coat, coat_se)) = (lambert[c], coated[c]);
        let rho = BASE[c] as f64;
        eprintln!(
            "specular 0, channel {c}: {mean:.5} ± {se:.5} vs base {rho:.3} ({:+.3} %); specular 1: {with_coat:.5} ± {coat_se:.5} ({:+.2} %)",
            100.0 * (mean / rho - 1.0),
            100.0 * (with_coat / rho - 1.0)
        );
        assert!((mean - rho).abs() <= 4.0 * se, "specularFactor 0, channel {c}: {mean} ± {se} is not the Lambertian {rho}");
        // The test resolves what the coat does: specularFactor 1 is far from the base.
        assert!((with_coat - rho).abs() > 4.0 * (se + coat_se), "channel {c}: the coat's effect is not resolved");
    }
    // 4. Black base: the coat alone, weight x Schlick(F0, F90 = 1) x GGX with every path the
    // same (the same random numbers; the lobe choice is the coat's whatever its weight), so
    // the reflection is linear in specularFactor and affine in F0: L(F0) = L(0) + F0 / F0_1
    // (L(F0_1) - L(0)). Exact up to float rounding (1e-4).
    let full = specular_quad(&ctx, [0.0; 3], &format!(r#""specularColorFactor": {TINT}"#), &[], 2);
    let half = specular_quad(&ctx, [0.0; 3], &format!(r#""specularFactor": 0.5, "specularColorFactor": {TINT}"#), &[], 2);
    // specularTexture's alpha (linear) scales specularFactor: 64 / 255.
    let alpha = specular_quad(
        &ctx,
        [0.0; 3],
        &format!(r#""specularColorFactor": {TINT}, "specularTexture": {{"index": 0}}"#),
        &[[255, 255, 255, 64]],
        2,
    );
    let f0_zero = specular_quad(&ctx, [0.0; 3], r#""specularColorFactor": [0, 0, 0]"#, &[], 2);
    // specularColorTexture (sRGB) scales specularColorFactor before the clamp to 1: red
    // 0.04 x 40 x 1 clamps to 1, green and blue are 0.04 x srgb(128), 0.04 x srgb(64).
    let texel = [255u8, 128, 64, 255];
    let coloured = specular_quad(&ctx, [0.0; 3], r#""specularColorFactor": [40, 1, 1], "specularColorTexture": {"index": 0}"#, &[texel], 2);
    let tint = [1.0, 0.8, 0.6];
    for c in 0..3 {
        let (l1, l0) = (full[c].0, f0_zero[c].0);
        let f0_1 = 0.04 * tint[c];
        let f0 = (0.04 * [40.0, 1.0, 1.0][c] * srgb(texel[c])).min(1.0);
        let expect = l0 + f0 / f0_1 * (l1 - l0);
        eprintln!(
            "black base, channel {c}: specular 1 {l1:.6}, 0.5 {:.6} (ratio {:.6}), alpha 64 {:.6} (ratio {:.6}); F0 0: {l0:.6}, F0 {f0:.4}: {:.6} vs {expect:.6}",
            half[c].0,
            half[c].0 / l1,
            alpha[c].0,
            alpha[c].0 / l1,
            coloured[c].0
        );
        assert!(l1 > 0.01 && l1 > l0, "channel {c}: no coat reflection ({l1}, F0 0: {l0})");
        assert!((half[c].0 / l1 - 0.5).abs() < 1e-4, "channel {c}: specularFactor 0.5 gives {} of {l1}", half[c].0);
        assert!((alpha[c].0 / l1 - 64.0 / 255.0).abs() < 1e-4, "channel {c}: specularTexture alpha 64 gives {} of {l1}", alpha[c].0);
        assert!((coloured[c].0 / expect - 1.0).abs() < 1e-4, "channel {c}: specularColorTexture: {} vs {expect}", coloured[c].0);
    }
    finish(ctx);
}

// ---- KHR_materials_clearcoat -----------------------------------------------------------------

/// `furnace_quad` of a metal-rough material with base colour `base`, `metallic`, roughness 0.5
/// and the KHR_materials_clearcoat object `{clearcoat}` (JSON members) reading `textures`.
fn clearcoat_quad(
    ctx: &Context,
    base: [f32; 3],
    metallic: f32,
    clearcoat: &str,
    textures: &[[u8; 4]],
    integrator: Integrator,
    spp: u32,
) -> ([(f64, f64); 3], Vec3) {
    let material = format!(
        r#"{{"name": "clearcoat", "pbrMetallicRoughness": {{"baseColorFactor": [{}, {}, {}, 1], "metallicFactor": {metallic}, "roughnessFactor": 0.5}},
  "extensions": {{"KHR_materials_clearcoat": {{{clearcoat}}}}}}}"#,
        base[0], base[1], base[2]
    );
    let name = format!("clearcoat-{}", clearcoat.chars().filter(char::is_ascii_alphanumeric).collect::<String>());
    let (means, wo, _) = furnace_quad(ctx, &name, material, "KHR_materials_clearcoat", textures, integrator, spp);
    (means, wo)
}

/// The directional albedo toward `wo` of the glTF material of `clearcoat_quad` (roughness 0.5,
/// ior 1.5) under a clear coat of weight `cc` and roughness `cc_roughness`, as the BSDF's own
/// sampling estimates it (glsl/tests/sampling.comp: the mean of f cos / pdf over 2^20 samples):
/// per channel, mean and standard error.
fn coated_albedo(ctx: &Context, base: [f32; 3], metallic: f32, cc: f32, cc_roughness: f32, wo: Vec3) -> [(f64, f64); 3] {
    let kernel = SamplingKernel::new(ctx);
    let base = Vec3::from(base);
    let push = bidir::gpu::abi::SamplingTestPush {
        mode: bidir::gpu::abi::SAMPLING_GLOSSY,
        count: 1 << 20,
        seed: 5,
        a: wo.extend(0.0),
        b: Vec3::Z.extend(0.0),
        c: ((1.0 - metallic) * base).extend(1.0),
        d: Vec3::splat(0.04).lerp(base, metallic).extend(1.0),
        e: glam::Vec4::new(0.04, 0.25, cc, (cc_roughness * cc_roughness).max(1e-3)),
        ..Default::default()
    };
    let out = kernel.run(push, 2, None);
    [0, 1, 2].map(|c| mean_and_se(&out.chunks_exact(2).map(|s| s[1][c] as f64).collect::<Vec<_>>()))
}

/// A clear coat rendered: in a uniform environment of radiance 1 a quad's pixels are the
/// material's directional albedo toward the eye, so pt-nee, pt and BDPT each agree, per
/// channel within 4 standard errors, with the albedo the BSDF's own sampling gives (the
/// kernels read the factors, the textures' R and G channels and the extension as the BSDF
/// tests take them); clearcoatFactor 0 renders the material without the extension (to float
/// rounding).
#[test]
fn clear_coat_renders_the_bsdfs_albedo() {
    let ctx = gpu();
    /// A material under test: the extension's JSON members, its texture, and the coat's
    /// weight and roughness those give.
    struct Case {
        what: &'static str,
        base: [f32; 3],
        metallic: f32,
        json: &'static str,
        textures: Vec<[u8; 4]>,
        clearcoat: f32,
        roughness: f32,
    }
    let cases = [
        Case {
            what: "dielectric, smooth coat",
            base: BASE,
            metallic: 0.0,
            json: r#""clearcoatFactor": 1, "clearcoatRoughnessFactor": 0.1"#,
            textures: vec![],
            clearcoat: 1.0,
            roughness: 0.1,
        },
        Case {
            what: "metal, rough partial coat",
            base: [0.9, 0.7, 0.3],
            metallic: 1.0,
            json: r#""clearcoatFactor": 0.7, "clearcoatRoughnessFactor": 0.4"#,
            textures: vec![],
            clearcoat: 0.7,
            roughness: 0.4,
        },
        Case {
            what: "textured coat",
            base: BASE,
            metallic: 0.0,
            json: r#""clearcoatFactor": 1, "clearcoatTexture": {"index": 0}, "clearcoatRoughnessFactor": 0.6, "clearcoatRoughnessTexture": {"index": 0}"#,
            textures: vec![[128, 100, 0, 255]],
            clearcoat: 128.0 / 255.0,
            roughness: 0.6 * 100.0 / 255.0,
        },
    ];
    for Case { what, base, metallic, json, textures, clearcoat, roughness } in &cases {
        for (integrator, spp) in [(Integrator::PtNee, 16), (Integrator::Pt, 64), (Integrator::Bdpt(Join::Lvc(0)), 16)] {
            let (img, wo) = clearcoat_quad(&ctx, *base, *metallic, json, textures, integrator, spp);
            let albedo = coated_albedo(&ctx, *base, *metallic, *clearcoat, *roughness, wo);
            for c in 0..3 {
                let ((mean, se), (expect, expect_se)) = (img[c], albedo[c]);
                eprintln!("{what}, {}, channel {c}: {mean:.5} ± {se:.5}, albedo {expect:.5} ± {expect_se:.5}", integrator.name());
                let tol = 4.0 * (se * se + expect_se * expect_se).sqrt();
                assert!(
                    (mean - expect).abs() <= tol,
                    "{what}, {}, channel {c}: rendered {mean} ± {se}, the BSDF's albedo {expect} ± {expect_se}",
                    integrator.name()
                );
            }
        }
    }
    // The coat is resolved: over a dark dielectric (whose own reflection is small; over BASE
    // at 70° the coat's reflection and the light it keeps from the base nearly cancel) the
    // smooth coat changes the pixels by far more than the tolerance.
    let dark = [0.1; 3];
    let coat = r#""clearcoatFactor": 1, "clearcoatRoughnessFactor": 0.1"#;
    let (coated, _) = clearcoat_quad(&ctx, dark, 0.0, coat, &[], Integrator::PtNee, 16);
    let (zero, _) = clearcoat_quad(&ctx, dark, 0.0, r#""clearcoatFactor": 0, "clearcoatRoughnessFactor": 0.1"#, &[], Integrator::PtNee, 16);
    let (bare, _) = clearcoat_quad(&ctx, dark, 0.0, "", &[], Integrator::PtNee, 16);
    eprintln!("dark dielectric at 70°: bare {:.5} ± {:.5}, coated {:.5} ± {:.5}", bare[0].0, bare[0].1, coated[0].0, coated[0].1);
    for c in 0..3 {
        // The same kernels and random numbers; the passes' sums may round differently.
        assert!(
            (zero[c].0 - bare[c].0).abs() <= 1e-6 * bare[c].0,
            "channel {c}: clearcoatFactor 0 gives {}, the bare material {}",
            zero[c].0,
            bare[c].0
        );
        assert!((coated[c].0 - bare[c].0).abs() > 8.0 * (coated[c].1 + bare[c].1), "channel {c}: the coat's effect is not resolved");
    }
    finish(ctx);
}

/// The extension's factors are checked (a factor outside [0, 1], or not a number, is an
/// error naming the material), its texture index too, and clearcoatNormalTexture, which is
/// not read, is one warning; `bidir info`'s description names the coat and its maps.
#[test]
fn clear_coat_input_is_checked() {
    let quad = || Mesh::quad(Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z, 0);
    let material = |json: &str| format!(r#"{{"name": "cc", "extensions": {{"KHR_materials_clearcoat": {{{json}}}}}}}"#);
    for (json, words) in [
        (r#""clearcoatFactor": 1.5"#, "clearcoatFactor and clearcoatRoughnessFactor in [0, 1]; got 1.5, 0"),
        (r#""clearcoatFactor": 1, "clearcoatRoughnessFactor": -0.1"#, "got 1, -0.1"),
        (r#""clearcoatFactor": "high""#, "must be numbers"),
        (r#""clearcoatFactor": 1, "clearcoatTexture": {"index": 7}"#, "clearcoatTexture has no valid texture index"),
    ] {
        let name = format!("bad-cc-{}", json.chars().filter(char::is_ascii_alphanumeric).collect::<String>());
        let path = gltf_out::write(&name, &[quad()], &[material(json)], &["KHR_materials_clearcoat"], &[]);
        let e = load(&path, &LoadOptions::default()).map(|_| ()).unwrap_err().to_string();
        assert!(e.contains("material 0 \"cc\"") && e.contains(words), "{json}: {e}");
    }
    let path = gltf_out::write(
        "cc-normal",
        &[quad()],
        &[material(r#""clearcoatFactor": 1, "clearcoatTexture": {"index": 0}, "clearcoatNormalTexture": {"index": 0}"#)],
        &["KHR_materials_clearcoat"],
        &[[255, 255, 255, 255]],
    );
    let loaded = load(&path, &LoadOptions::default()).unwrap();
    assert_eq!(loaded.warnings.len(), 1, "{:?}", loaded.warnings);
    assert!(loaded.warnings[0].contains("clearcoatNormalTexture is not read"), "{:?}", loaded.warnings);
    let m = &loaded.scene.materials[0];
    assert_eq!((m.clearcoat, m.clearcoat_roughness, m.clearcoat_texture.is_some()), (1.0, 0.0, true));
    assert!(m.describe().contains("clear coat (KHR_materials_clearcoat)") && m.describe().contains("clear coat map"), "{}", m.describe());
    assert!(SceneFeatures::of(&loaded.scene).clearcoat);
}

/// pt, BDPT (the light vertex cache, and the full join) and VCM agree with pt-nee in a room
/// lit by a ceiling light, with a red dielectric cube under a smooth clear coat and a gold
/// metal cube under a rough one: the coat's lobe is sampled, evaluated and weighted (forward
/// and reverse pdfs) consistently by every strategy.
#[test]
fn integrators_agree_on_clear_coated_cubes() {
    let coated = |name: &str, base: [f32; 3], metallic: f32, cc: f32, cr: f32| {
        format!(
            r#"{{"name": "{name}", "pbrMetallicRoughness": {{"baseColorFactor": [{}, {}, {}, 1], "metallicFactor": {metallic}, "roughnessFactor": 0.5}},
  "extensions": {{"KHR_materials_clearcoat": {{"clearcoatFactor": {cc}, "clearcoatRoughnessFactor": {cr}}}}}}}"#,
            base[0], base[1], base[2]
        )
    };
    let meshes = [
        Mesh::quad(Vec3::new(-3.0, 0.0, -3.0), Vec3::X * 6.0, Vec3::Z * 6.0, Vec3::Y, 0),
        Mesh::quad(Vec3::new(-3.0, 0.0, -3.0), Vec3::X * 6.0, Vec3::Y * 5.0, Vec3::Z, 0),
        Mesh::quad(Vec3::new(-1.5, 4.0, -1.5), Vec3::X * 3.0, Vec3::Z * 3.0, -Vec3::Y, 1),
        Mesh::cuboid(Vec3::new(-1.8, 0.0, -1.0), Vec3::new(-0.2, 1.6, 0.6), 2),
        Mesh::cuboid(Vec3::new(0.3, 0.0, -0.6), Vec3::new(1.6, 1.3, 0.7), 3),
    ];
    let materials = [
        diffuse("white", [0.8; 3]),
        emitter(6.0),
        coated("red", [0.8, 0.2, 0.15], 0.0, 1.0, 0.05),
        coated("gold", [1.0, 0.8, 0.35], 1.0, 0.8, 0.3),
    ];
    let scene = load_strict(&gltf_out::write(
        "clearcoat-room",
        &meshes,
        &materials,
        &["KHR_materials_clearcoat", "KHR_materials_emissive_strength"],
        &[],
    ));
    assert!(SceneFeatures::of(&scene).clearcoat);
    let camera = Camera {
        name: "room".into(),
        eye: Vec3::new(0.5, 2.5, 5.0),
        target: Vec3::new(0.0, 0.8, 0.0),
        up: Vec3::Y,
        fov_y_deg: 40.0,
        width: 32,
        height: 32,
    };
    let w = camera.width as usize;
    let ctx = gpu();
    let mut r = Renderer::new(&ctx, &scene, &camera, RenderSettings::new(Integrator::PtNee)).unwrap();
    let reference = render_with(&mut r, Integrator::PtNee, 128);
    assert_agree("clear coat: pt vs pt-nee", &render_with(&mut r, Integrator::Pt, 256), &reference, w);
    assert_agree("clear coat: bdpt vs pt-nee", &render_with(&mut r, Integrator::Bdpt(Join::Lvc(0)), 64), &reference, w);
    assert_agree("clear coat: bdpt:full vs pt-nee", &render_with(&mut r, Integrator::Bdpt(Join::Full), 48), &reference, w);
    let vcm = Integrator::Vcm(bidir::render::vcm::VcmMode::FULL);
    assert_agree("clear coat: vcm vs pt-nee", &render_with(&mut r, vcm, 48), &reference, w);
    drop(r);
    finish(ctx);
}
