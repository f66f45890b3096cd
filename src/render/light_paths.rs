//! `--light-paths auto`: BDPT's light paths per pixel chosen per scene from pilot passes.
//!
//! How many light paths an iteration traces per pixel trades the light pass's cost against the
//! strategies it feeds (light tracing, the connections to the light vertex cache). Measured on
//! the NVIDIA H200 (docs/results.md, "Light paths per pixel, again"): the Cornell box's error at
//! equal time is flat from 0.5 to 2 light paths per pixel, a box whose light hides above a
//! panel wants 2 (0.78x the MSE of 1), the caustic scene 0.5 (0.93x). No scene property read
//! before rendering says which, so the renderer measures it: it renders its first passes at
//! each ratio of [`AUTO_RATIOS`] in turn, twice, estimates each ratio's variance per sample
//! from the difference of its two passes and its cost per sample from their times, and keeps
//! the ratio with the least variance x time where it beats the starting ratio's by a clear
//! margin ([`SWITCH_MARGIN`]). Every pass is an unbiased estimate whatever its ratio, so the
//! pilot passes stay in the image.
//!
//! ```
//! use bidir::render::light_paths::{choose, Pilot};
//! // Variance per sample and seconds per sample of three ratios: 2 is the most efficient.
//! let pilots = [
//!     Pilot { ratio: 0.5, variance: 4.0, seconds_per_spp: 1.0 },
//!     Pilot { ratio: 1.0, variance: 2.5, seconds_per_spp: 1.2 },
//!     Pilot { ratio: 2.0, variance: 1.2, seconds_per_spp: 1.6 },
//! ];
//! assert_eq!(choose(&pilots, 1.0), Some(2.0));
//! ```

use super::RenderSettings;
use crate::imaging::part::Accumulation;

/// The light paths per pixel `--light-paths auto` tries, in the order its pilot renders them.
pub const AUTO_RATIOS: [f32; 3] = [0.5, 1.0, 2.0];

/// Pilot passes per ratio (their difference estimates its variance).
pub const PILOT_ROUNDS: u32 = 2;

/// The fewest samples (pixels x samples per pixel) a pilot pass holds; shorter renders keep
/// their ratio. The scenes where the ratio matters carry their light on rare paths, so a
/// pass's squared differences are heavy-tailed: on lavapipe, a 64 x 64 box whose light hides
/// above a panel measured ratio 0.5's variance at 0.051-0.085 in three renders of 40-sample
/// passes (160 thousand samples each), and 96 x 96 passes of 6 samples chose 2, 1 and 0.5 in
/// three renders of the same scene. A pass of 2^22 samples (256 x 256 at 64 samples per
/// pixel) holds 25 times the 160 thousand, which should narrow such swings about five-fold
/// (as the square root of the samples), under the switch's 10 % margin.
pub const MIN_PILOT_SAMPLES: u64 = 1 << 22;

/// Share of a time budget (`render_time`) or of the samples asked for (`render_spp`) the
/// pilot passes take in all.
pub const PILOT_SHARE: f64 = 0.12;

/// The light paths per pixel the store must hold for `settings`.
pub fn capacity_ratio(settings: &RenderSettings) -> f32 {
    if settings.light_path_auto {
        AUTO_RATIOS.iter().copied().fold(settings.light_path_ratio, f32::max)
    } else {
        settings.light_path_ratio
    }
}

/// What the pilot measured for one ratio.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pilot {
    pub ratio: f32,
    /// Variance of one sample per pixel, summed over the channels and averaged over pixels.
    pub variance: f64,
    /// Seconds a pass took per sample per pixel.
    pub seconds_per_spp: f64,
}

impl Pilot {
    /// Variance x time: the MSE a render at this ratio reaches in one second.
    pub fn cost(&self) -> f64 {
        self.variance * self.seconds_per_spp
    }
}

/// A ratio other than the starting one must beat its variance x time by this share: a pilot
/// of a few samples is a noisy measure, and a wrong switch costs more than the gains it
/// chases (H200, docs/results.md: the caustic scene's MSE at equal time is 1.33x at 2 light
/// paths per pixel against its best, 0.5; the hidden light's 1.86x at 0.5 against its best,
/// 2; at 1 neither is more than 1.28x off).
pub const SWITCH_MARGIN: f64 = 0.1;

/// The ratio to render with: the starting `current` one unless another's pilot reached a
/// variance x time [`SWITCH_MARGIN`] below it (then the least such); `None` where `current`
/// measured nothing finite and positive (an image without noise, or without light) and no
/// other did either.
pub fn choose(pilots: &[Pilot], current: f32) -> Option<f32> {
    let valid = |p: &&Pilot| p.cost().is_finite() && p.cost() > 0.0;
    let best = pilots.iter().filter(valid).min_by(|a, b| a.cost().total_cmp(&b.cost()))?;
    match pilots.iter().filter(valid).find(|p| p.ratio == current) {
        Some(c) if best.cost() > (1.0 - SWITCH_MARGIN) * c.cost() => Some(current),
        _ => Some(best.ratio),
    }
}

/// The image one pass added (`spp` samples per pixel): the difference of the film's sums
/// after and before it, as an average per sample (camera sums over their sample counts, light
/// tracing's splats over `spp`), three floats per pixel.
pub fn pass_image(before: &Accumulation, after: &Accumulation, spp: u32) -> Vec<f32> {
    let n = before.camera.len().min(after.camera.len());
    let mut out = vec![0f32; 3 * n];
    for i in 0..n {
        let (a, b) = (after.camera[i], before.camera[i]);
        let count = (a[3] - b[3]).max(1.0);
        for k in 0..3 {
            let mut v = (a[k] - b[k]) / count;
            if let (Some(la), Some(lb)) = (&after.light, &before.light) {
                v += (la[i][k] - lb[i][k]) / spp.max(1) as f64;
            }
            out[3 * i + k] = v as f32;
        }
    }
    out
}

/// Pixel groups of [`variance_per_sample`]'s median of means.
pub const VARIANCE_GROUPS: usize = 7;

/// Variance of one sample per pixel from two independent passes of `spp` samples each:
/// E|A - B|^2 = 2 Var(one pass) = 2 Var(one sample) / spp, summed over the channels. Averaged
/// over the pixels as a median of means: the mean over each of [`VARIANCE_GROUPS`] groups of
/// pixels (pixel i in group i mod the count), then their median, so that a single bright
/// outlier of a pass of few samples does not decide the choice. Pixels where either pass is
/// not finite are left out; NaN where none is left.
pub fn variance_per_sample(a: &[f32], b: &[f32], spp: u32) -> f64 {
    let mut sums = [(0.0f64, 0usize); VARIANCE_GROUPS];
    for (i, (pa, pb)) in a.chunks_exact(3).zip(b.chunks_exact(3)).enumerate() {
        if pa.iter().chain(pb).all(|v| v.is_finite()) {
            let g = &mut sums[i % VARIANCE_GROUPS];
            g.0 += pa.iter().zip(pb).map(|(x, y)| (*x as f64 - *y as f64).powi(2)).sum::<f64>();
            g.1 += 1;
        }
    }
    let mut means: Vec<f64> = sums.iter().filter(|g| g.1 > 0).map(|g| g.0 / g.1 as f64).collect();
    if means.is_empty() {
        return f64::NAN;
    }
    means.sort_by(f64::total_cmp);
    means[means.len() / 2] * spp as f64 / 2.0
}

/// Samples per pixel of each pilot pass for a render of `spp` samples: together the passes
/// take about [`PILOT_SHARE`] of them; 0 (no pilot: the ratio stays) where that is less than
/// one sample per pass.
pub fn pilot_spp_for_samples(spp: u32) -> u32 {
    let passes = (AUTO_RATIOS.len() as u32 * PILOT_ROUNDS) as f64;
    (spp as f64 * PILOT_SHARE / passes).floor() as u32
}

/// Seconds of each pilot pass for a render of `budget` seconds: together the passes take
/// about [`PILOT_SHARE`] of it.
pub fn pilot_pass_seconds(budget: f64) -> f64 {
    budget * PILOT_SHARE / (AUTO_RATIOS.len() as u32 * PILOT_ROUNDS) as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    fn acc(camera: Vec<[f64; 4]>, light: Option<Vec<[f64; 3]>>, spp: u64) -> Accumulation {
        Accumulation { width: camera.len() as u32, height: 1, camera, light, spp, first_hit: None }
    }

    #[test]
    fn a_pass_image_is_the_difference_per_sample() {
        let before = acc(vec![[1.0, 2.0, 3.0, 2.0]], Some(vec![[4.0, 0.0, 0.0]]), 2);
        let after = acc(vec![[7.0, 2.0, 3.0, 5.0]], Some(vec![[10.0, 3.0, 0.0]]), 5);
        // camera: (7 - 1) / 3 = 2; light: (10 - 4) / 3 = 2 and 3 / 3 = 1
        assert_eq!(pass_image(&before, &after, 3), vec![4.0, 1.0, 0.0]);
    }

    #[test]
    fn the_variance_of_two_passes_scales_to_one_sample() {
        // 7 x 10 pixels, each differing by 2 in its red channel: 4 per pixel, x spp 8 / 2.
        let n = VARIANCE_GROUPS * 10;
        let a: Vec<f32> = (0..n).flat_map(|_| [1.0, 0.0, 5.0]).collect();
        let b: Vec<f32> = (0..n).flat_map(|_| [3.0, 0.0, 5.0]).collect();
        assert_eq!(variance_per_sample(&a, &b, 8), 16.0);
        // One outlier moves one group's mean, not the median; a NaN pixel is left out.
        let mut c = a.clone();
        c[0] = 1000.0;
        c[3 * 5 + 1] = f32::NAN;
        assert_eq!(variance_per_sample(&c, &b, 8), 16.0);
        // Four of the seven groups twice as far apart: the median is theirs.
        let d: Vec<f32> = (0..n).flat_map(|i| [if i % VARIANCE_GROUPS < 4 { 7.0 } else { 1.0 }, 0.0, 5.0]).collect();
        assert_eq!(variance_per_sample(&d, &b, 8), 64.0);
        assert!(variance_per_sample(&[f32::NAN; 3], &[0.0; 3], 1).is_nan());
    }

    #[test]
    fn choose_switches_only_for_a_clear_gain_and_skips_what_measured_nothing() {
        let p = |ratio, variance, seconds_per_spp| Pilot { ratio, variance, seconds_per_spp };
        // 2 is 5 % better than 1: not enough to leave it; 20 % better: taken.
        assert_eq!(choose(&[p(0.5, 2.0, 1.0), p(1.0, 1.5, 1.2), p(2.0, 1.0, 1.71)], 1.0), Some(1.0));
        assert_eq!(choose(&[p(0.5, 2.0, 1.0), p(1.0, 1.5, 1.2), p(2.0, 1.0, 1.44)], 1.0), Some(2.0));
        // The least of several clear gains.
        assert_eq!(choose(&[p(0.5, 1.0, 1.0), p(1.0, 1.5, 1.2), p(2.0, 1.0, 1.44)], 1.0), Some(0.5));
        // Nothing measured at the current ratio: the best valid one.
        assert_eq!(choose(&[p(0.5, f64::NAN, 1.0), p(1.0, 0.0, 1.0), p(2.0, 3.0, 1.0)], 1.0), Some(2.0));
        assert_eq!(choose(&[p(0.5, 0.0, 1.0)], 1.0), None);
    }

    #[test]
    fn pilot_sizes() {
        assert_eq!(pilot_spp_for_samples(1000), 20);
        assert_eq!(pilot_spp_for_samples(40), 0);
        assert!((pilot_pass_seconds(1.0) - 0.02).abs() < 1e-12);
    }

    #[test]
    fn the_store_holds_the_largest_ratio_tried() {
        let mut s = RenderSettings::new(crate::render::Integrator::Bdpt(crate::render::Join::DEFAULT));
        assert_eq!(capacity_ratio(&s), 1.0);
        s.light_path_auto = true;
        assert_eq!(capacity_ratio(&s), 2.0);
        s.light_path_ratio = 3.0;
        assert_eq!(capacity_ratio(&s), 3.0);
    }
}
