//! An external reference for the GGX lobes: the rough Cornell box (`assets/scenes/rough-cornell`:
//! a rough conductor with F = 1 and a rough dielectric sphere, flat-shaded triangle meshes)
//! against Mitsuba 3 (`reference.exr` beside it, made by `mitsuba_reference.py`; its README has
//! the command, version and sample counts). Mitsuba's separable Smith G1 G1 is converted to
//! bidir's height-correlated G2 by that script (the only convention that differs); everything
//! else (D, Fresnel, sampling, the integrator) is Mitsuba's own.
//!
//! Each integrator renders `REPLICATES` independent estimates (seeds 1..=REPLICATES). Their
//! spread gives the standard error of the whole-image mean per channel and of every 16x16
//! block's mean (channels averaged); the reference's standard error comes from its own
//! independent passes (`reference-se.exr`, per pixel and channel). Each statistic is judged
//! by `t = (mean - ref) / sqrt(se^2 + se_ref^2)` (31 degrees of freedom, dominated by ours):
//! - every |t| below `T_MAX` = 5.5 (false alarm ~5e-6 each, ~1e-4 over the 19 statistics);
//! - the blocks' sum of t^2 (scaled by (dof - 2) / dof, so that its mean is that of a
//!   chi-square) against chi-square with 16 degrees of freedom, p above 1e-4: a small bias
//!   spread over many blocks, which no single block shows, fails here;
//! - the bound: every channel mean within 0.5 % of the reference, with power asserted
//!   (the mean's relative standard error below `MEAN_SE_MAX` = 0.2 %, so 0.5 % is 2.5 sigma).
//!
//! Skipped with a message only when the reference is missing (it is committed).

mod common;

use bidir::imaging::{metrics, read_exr, RgbImage};
use bidir::render::{Integrator, Join, RenderSettings, Renderer};
use bidir::scene::Camera;
use common::stats::chi2_sf;
use common::{finish, gpu};
use glam::Vec3;
use std::path::Path;

const SCENE: &str = "assets/scenes/rough-cornell/rough-cornell.obj";
const REFERENCE: &str = "assets/scenes/rough-cornell/reference.exr";
/// Per pixel and channel, the standard error of `REFERENCE` (from its independent passes).
const REFERENCE_SE: &str = "assets/scenes/rough-cornell/reference-se.exr";
const REPLICATES: u32 = 32;
const BLOCK: u32 = 16;
const T_MAX: f64 = 5.5;
/// Smallest p-value of the blocks' chi-square statistic.
const CHI2_P_MIN: f64 = 1e-4;
/// The bound on each channel mean, and the largest relative standard error of the
/// mean that keeps it meaningful (0.5 % >= 2.5 sigma; a 1 % bias fails at once).
const MEAN_TOLERANCE: f64 = 0.005;
const MEAN_SE_MAX: f64 = 0.002;

/// The shared Cornell box camera (`../shared/scenes/cornell-box/README.md`) at 64 x 64, as the
/// reference was rendered.
fn camera() -> Camera {
    Camera {
        name: "cornell".into(),
        eye: Vec3::new(278.0, 273.0, -800.0),
        target: Vec3::new(278.0, 273.0, -799.0),
        up: Vec3::Y,
        fov_y_deg: 39.3077,
        width: 64,
        height: 64,
    }
}

/// The statistics of one image: the three channel means, then each block's mean over its
/// pixels and channels.
fn statistics(img: &RgbImage) -> Vec<f64> {
    let mut s = img.mean().to_vec();
    s.extend(metrics::block_means(img, BLOCK).iter().map(|(_, _, m)| (m[0] + m[1] + m[2]) / 3.0));
    s
}

/// The reference's statistics and their standard errors. Pixels are independent (Mitsuba's
/// `independent` sampler), so variances add over a block's pixels; a pixel's three channels
/// come from the same paths, so their mean's standard error is bounded by the mean of theirs.
fn reference() -> Option<Vec<(f64, f64)>> {
    if !Path::new(REFERENCE).exists() || !Path::new(REFERENCE_SE).exists() {
        eprintln!("skipping: {REFERENCE} or {REFERENCE_SE} is absent (see assets/scenes/rough-cornell/README.md)");
        return None;
    }
    let img = read_exr(Path::new(REFERENCE)).expect("the Mitsuba reference reads");
    let se = read_exr(Path::new(REFERENCE_SE)).expect("its standard errors read");
    assert_eq!((img.width, img.height, se.width, se.height), (64, 64, 64, 64), "reference size");
    let values = statistics(&img);
    let pixels = (img.width * img.height) as f64;
    let mut out: Vec<(f64, f64)> = (0..3)
        .map(|c| {
            let var: f64 = se.data.chunks_exact(3).map(|p| (p[c] as f64).powi(2)).sum();
            (values[c], var.sqrt() / pixels)
        })
        .collect();
    let var = RgbImage { width: se.width, height: se.height, data: se.data.chunks_exact(3).flat_map(pixel_var).collect() };
    let block_var = metrics::block_means(&var, BLOCK);
    let block_pixels = (BLOCK * BLOCK) as f64;
    for (v, (_, _, var)) in values[3..].iter().zip(block_var) {
        // block_means averaged the per-pixel variances; the block mean's variance is that / n.
        out.push((*v, (var[0] / block_pixels).sqrt()));
    }
    Some(out)
}

/// A pixel's channel-mean variance bound, (mean of the three standard errors)^2, in every
/// channel (so that a block mean of it is the block's mean per-pixel variance).
fn pixel_var(p: &[f32]) -> [f32; 3] {
    let se = (p[0] + p[1] + p[2]) / 3.0;
    [se * se; 3]
}

/// Mean and standard error of each statistic over `REPLICATES` renders, and the samples per
/// pixel of each: `spp_on_cpu` on lavapipe (as many as the CI's time budget allows; the power
/// assertion says whether they suffice), 8x as many on a GPU.
fn estimate(integrator: Integrator, spp_on_cpu: u32) -> (Vec<(f64, f64)>, u32) {
    let scene = bidir::scene::load(Path::new(SCENE), &Default::default()).expect("the rough Cornell box loads").scene;
    let ctx = gpu();
    let spp = if ctx.info().device_type == bidir::vk::PhysicalDeviceType::CPU { spp_on_cpu } else { 8 * spp_on_cpu };
    let t0 = std::time::Instant::now();
    let mut r = Renderer::new(&ctx, &scene, &camera(), RenderSettings::new(integrator)).unwrap();
    let t1 = std::time::Instant::now();
    let mut samples: Vec<Vec<f64>> = Vec::new();
    for seed in 1..=REPLICATES {
        r.set_seed(seed).unwrap();
        r.render_spp(spp, |_| {}).unwrap();
        samples.push(statistics(&r.image().unwrap()));
    }
    assert_eq!(r.nan_samples().unwrap(), 0, "{}: NaN/Inf samples", integrator.name());
    eprintln!("{}: set-up {:.2} s, rendering {:.2} s", integrator.name(), (t1 - t0).as_secs_f64(), t1.elapsed().as_secs_f64());
    drop(r);
    finish(ctx);
    let n = samples.len() as f64;
    let stats = (0..samples[0].len())
        .map(|i| {
            let mean = samples.iter().map(|s| s[i]).sum::<f64>() / n;
            let var = samples.iter().map(|s| (s[i] - mean).powi(2)).sum::<f64>() / (n - 1.0);
            (mean, (var / n).sqrt())
        })
        .collect();
    (stats, spp)
}

fn check(integrator: Integrator, spp_on_cpu: u32) {
    let name = integrator.name();
    let Some(reference) = reference() else { return };
    let (est, spp) = estimate(integrator, spp_on_cpu);
    let t: Vec<f64> = est.iter().zip(&reference).map(|((m, se), (r, se_r))| (m - r) / (se * se + se_r * se_r).sqrt()).collect();

    let channels: Vec<String> = (0..3)
        .map(|c| {
            let ((m, se), (r, se_r)) = (est[c], reference[c]);
            format!("{:.4}±{:.4} (ref se {:.4}, t {:+.2})", m / r, se / r, se_r / r, t[c])
        })
        .collect();
    let dof = REPLICATES as f64 - 1.0;
    let block_t = &t[3..];
    let chi2: f64 = block_t.iter().map(|t| t * t).sum::<f64>() * (dof - 2.0) / dof;
    let p = chi2_sf(chi2, block_t.len() as u32);
    let worst = block_t.iter().fold(0.0f64, |w, t| w.max(t.abs()));
    let block_se: Vec<f64> = est[3..].iter().map(|(m, se)| se / m).collect();
    eprintln!(
        "{name} vs Mitsuba: {REPLICATES}x{spp} spp; channel mean ratio {}; blocks: worst |t| {worst:.2}, chi2 {chi2:.1} / {} (p {p:.3}), relative se {:.2}-{:.2} %",
        channels.join(", "),
        block_t.len(),
        100.0 * block_se.iter().cloned().fold(f64::INFINITY, f64::min),
        100.0 * block_se.iter().cloned().fold(0.0, f64::max)
    );
    // The blocks as they lie in the image (row 0 at the top): ratio to Mitsuba and t.
    let cells: Vec<String> = (3..est.len()).map(|i| format!("{:.4} ({:+.1})", est[i].0 / reference[i].0, t[i])).collect();
    for row in cells.chunks((camera().width / BLOCK) as usize) {
        eprintln!("    {}", row.join("  "));
    }

    for c in 0..3 {
        let ((m, se), (r, _)) = (est[c], reference[c]);
        assert!(se / r < MEAN_SE_MAX, "{name}: channel {c} mean has relative se {:.3} %: too noisy to judge 0.5 %", 100.0 * se / r);
        assert!((m / r - 1.0).abs() < MEAN_TOLERANCE, "{name}: channel {c} mean {m:.6} vs Mitsuba {r:.6}: {:+.3} %", 100.0 * (m / r - 1.0));
    }
    for (i, t) in t.iter().enumerate() {
        let what = if i < 3 { format!("channel {i} mean") } else { format!("block {}", i - 3) };
        let ((m, se), (r, _)) = (est[i], reference[i]);
        assert!(t.abs() < T_MAX, "{name}: {what}: {m:.6} vs Mitsuba {r:.6} ({:+.3} %), t = {t:.2} (se {se:.2e})", 100.0 * (m / r - 1.0));
    }
    assert!(p > CHI2_P_MIN, "{name}: blocks' chi-square {chi2:.1} with {} dof, p = {p:.2e}", block_t.len());
}

#[test]
fn pt_nee_matches_mitsuba_on_rough_spheres() {
    check(Integrator::PtNee, 16);
}

#[test]
fn bdpt_matches_mitsuba_on_rough_spheres() {
    check(Integrator::Bdpt(Join::Lvc(0)), 8);
}
