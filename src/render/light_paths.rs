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
//! the ratio with the least variance x time. Every pass is an unbiased estimate whatever its
//! ratio, so the pilot passes stay in the image.
//!
//! ```
//! use bidir::render::light_paths::{choose, Pilot};
//! // Variance per sample and seconds per sample of three ratios: 2 is the most efficient.
//! let pilots = [
//!     Pilot { ratio: 0.5, variance: 4.0, seconds_per_spp: 1.0 },
//!     Pilot { ratio: 1.0, variance: 2.5, seconds_per_spp: 1.2 },
//!     Pilot { ratio: 2.0, variance: 1.2, seconds_per_spp: 1.6 },
//! ];
//! assert_eq!(choose(&pilots), Some(2.0));
//! ```

use super::RenderSettings;
use crate::imaging::part::Accumulation;

/// The light paths per pixel `--light-paths auto` tries, in the order its pilot renders them.
pub const AUTO_RATIOS: [f32; 3] = [0.5, 1.0, 2.0];

/// Pilot passes per ratio (their difference estimates its variance).
pub const PILOT_ROUNDS: u32 = 2;

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

/// The ratio whose pilot reached the least variance x time; `None` where none measured a
/// finite, positive one (an image without noise, or without light).
pub fn choose(pilots: &[Pilot]) -> Option<f32> {
    pilots.iter().filter(|p| p.cost().is_finite() && p.cost() > 0.0).min_by(|a, b| a.cost().total_cmp(&b.cost())).map(|p| p.ratio)
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

/// Variance of one sample per pixel from two independent passes of `spp` samples each:
/// E|A - B|^2 = 2 Var(one pass) = 2 Var(one sample) / spp, summed over the channels and
/// averaged over the pixels. Pixels where either pass is not finite are left out.
pub fn variance_per_sample(a: &[f32], b: &[f32], spp: u32) -> f64 {
    let (mut sum, mut pixels) = (0.0f64, 0usize);
    for (pa, pb) in a.chunks_exact(3).zip(b.chunks_exact(3)) {
        if pa.iter().chain(pb).all(|v| v.is_finite()) {
            sum += pa.iter().zip(pb).map(|(x, y)| (*x as f64 - *y as f64).powi(2)).sum::<f64>();
            pixels += 1;
        }
    }
    if pixels == 0 {
        return f64::NAN;
    }
    sum / pixels as f64 * spp as f64 / 2.0
}

/// Samples per pixel of each pilot pass for a render of `spp` samples: together the passes
/// take about [`PILOT_SHARE`] of them; 0 (no pilot: the ratio stays) where that is less than
/// one sample per pass.
pub fn pilot_spp_for_samples(spp: u32) -> u32 {
    let passes = (AUTO_RATIOS.len() as u32 * PILOT_ROUNDS) as f64;
    (spp as f64 * PILOT_SHARE / passes).floor() as u32
}

/// Samples per pixel of each pilot pass for a render of `budget` seconds when one sample per
/// pixel takes `seconds_per_spp` at the starting ratio: together the passes take about
/// [`PILOT_SHARE`] of the budget (at least one sample each).
pub fn pilot_spp_for_time(budget: f64, seconds_per_spp: f64) -> u32 {
    let passes = (AUTO_RATIOS.len() as u32 * PILOT_ROUNDS) as f64;
    let spp = budget * PILOT_SHARE / passes / seconds_per_spp.max(1e-9);
    (spp.floor() as u32).max(1)
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
        // Two pixels; per channel differences 2 and 0: mean over pixels of 4 + 0 = 2, x spp 8 / 2.
        let a = [1.0, 0.0, 0.0, 5.0, 5.0, 5.0];
        let b = [3.0, 0.0, 0.0, 5.0, 5.0, 5.0];
        assert_eq!(variance_per_sample(&a, &b, 8), 8.0);
        // A NaN pixel is left out.
        let c = [1.0, 0.0, 0.0, f32::NAN, 5.0, 5.0];
        assert_eq!(variance_per_sample(&c, &b, 8), 16.0);
        assert!(variance_per_sample(&[f32::NAN; 3], &[0.0; 3], 1).is_nan());
    }

    #[test]
    fn choose_takes_the_least_variance_times_time_and_skips_what_measured_nothing() {
        let p = |ratio, variance, seconds_per_spp| Pilot { ratio, variance, seconds_per_spp };
        assert_eq!(choose(&[p(0.5, 2.0, 1.0), p(1.0, 1.5, 1.2), p(2.0, 1.2, 1.8)]), Some(1.0));
        assert_eq!(choose(&[p(0.5, f64::NAN, 1.0), p(1.0, 0.0, 1.0), p(2.0, 3.0, 1.0)]), Some(2.0));
        assert_eq!(choose(&[p(0.5, 0.0, 1.0)]), None);
    }

    #[test]
    fn pilot_sizes() {
        assert_eq!(pilot_spp_for_samples(1000), 20);
        assert_eq!(pilot_spp_for_samples(40), 0);
        assert_eq!(pilot_spp_for_time(1.0, 0.001), 20);
        assert_eq!(pilot_spp_for_time(0.1, 1.0), 1);
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
