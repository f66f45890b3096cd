//! Whether two renders of one scene have the same expectation, judged against their own
//! noise (block means of the per-pixel difference).

use super::stats;
use bidir::render::{Integrator, Renderer};

/// False-alarm probability of the block test.
pub const ALPHA: f64 = 1e-3;

/// Renders `spp` samples per pixel with `integrator` (switching the renderer to it) and
/// returns the image; NaN/Inf samples fail the test.
pub fn render_with(r: &mut Renderer, integrator: Integrator, spp: u32) -> Vec<f32> {
    if r.settings().integrator != integrator {
        r.set_integrator(integrator).unwrap();
    }
    r.render_spp(spp, |_| {}).unwrap();
    assert_eq!(r.nan_samples().unwrap(), 0, "{}: NaN/Inf samples", integrator.name());
    r.image().unwrap().data
}

/// Mean and its standard error of independent samples.
pub fn mean_and_se(v: &[f64]) -> (f64, f64) {
    let n = v.len() as f64;
    let mean = v.iter().sum::<f64>() / n;
    let var = v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, (var / n).sqrt())
}

/// Whether images a and b have the same expectation: the per-pixel difference (channels
/// summed) averaged over 8x8 blocks, each block's mean against its own standard error; the
/// overall mean must resolve 2 % of the image level.
pub fn assert_agree(what: &str, a: &[f32], b: &[f32], width: usize) {
    assert_agree_blocks(what, a, b, width, 8, 0.02)
}

/// As [`assert_agree`] with `block` x `block` blocks, the overall mean's standard error below
/// `resolve` of the image level (the test's power).
pub fn assert_agree_blocks(what: &str, a: &[f32], b: &[f32], width: usize, block: usize, resolve: f64) {
    let diff: Vec<f64> =
        a.chunks_exact(3).zip(b.chunks_exact(3)).map(|(x, y)| x.iter().zip(y).map(|(p, q)| (p - q) as f64).sum()).collect();
    let level = a.iter().map(|&v| v as f64).sum::<f64>() / (a.len() / 3) as f64;
    let height = diff.len() / width;
    let (mut chi2, mut blocks, mut worst) = (0.0, 0u32, 0.0f64);
    for by in (0..height).step_by(block) {
        for bx in (0..width).step_by(block) {
            let v: Vec<f64> =
                (by..by + block).flat_map(|y| (bx..bx + block).map(move |x| (x, y))).map(|(x, y)| diff[y * width + x]).collect();
            let (m, se) = mean_and_se(&v);
            let z = if se > 0.0 { m / se } else { 0.0 };
            worst = worst.max(z.abs());
            chi2 += z * z;
            blocks += 1;
        }
    }
    let (m, se) = mean_and_se(&diff);
    let p_blocks = stats::chi2_sf(chi2, blocks);
    eprintln!(
        "{what}: mean difference {:+.3} % ± {:.3} % of the image level, blocks X^2 = {chi2:.1} over {blocks} (p = {p_blocks:.4}), worst |z| {worst:.2}",
        100.0 * m / level,
        100.0 * se / level
    );
    assert!(se / level < resolve, "{what}: too noisy to resolve {} % (se {:.3} %)", 100.0 * resolve, 100.0 * se / level);
    assert!(m.abs() < 3.29 * se, "{what}: images differ by {:+.3} % (z = {:.2})", 100.0 * m / level, m / se);
    assert!(p_blocks >= ALPHA, "{what}: block means differ beyond their noise (X^2 = {chi2:.1}, dof {blocks}, p = {p_blocks:.2e})");
}
