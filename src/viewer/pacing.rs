//! How many samples per pixel each frame renders, and the numbers in the window title.
//!
//! A frame renders one batch of whole samples per pixel: the batch grows while the render
//! pass takes less than [`RENDER_SHARE`] of the frame budget and shrinks when it takes more,
//! so a fast GPU stays busy and frames stay near the budget. The batch never drops below one
//! sample per pixel: on a slow device (lavapipe: ~100 ms or more per sample at 256x256) a
//! frame is one sample and the window answers input once per such frame. Rendering part of
//! the image per frame would keep it more responsive there, but needs tiling support in
//! every integrator kernel; not done.

use std::time::Duration;

/// Share of the frame budget the render pass aims for; the rest is left to the tonemap,
/// the copy and presentation. The vsync wait is not measured against it (it would shrink
/// the batch every frame).
pub const RENDER_SHARE: f64 = 0.8;
/// Largest batch (samples per pixel per frame).
pub const MAX_SPP: u32 = 1024;

/// Sizes batches of samples to a frame budget.
#[derive(Clone, Debug)]
pub struct Pacer {
    budget: Duration,
    spp: u32,
}

impl Pacer {
    pub fn new(budget: Duration) -> Pacer {
        Pacer { budget, spp: 1 }
    }

    /// Samples per pixel for the next frame.
    pub fn spp(&self) -> u32 {
        self.spp
    }

    /// Starts again from one sample per pixel (another integrator costs differently).
    pub fn restart(&mut self) {
        self.spp = 1;
    }

    /// Records that a batch of `spp` samples took `render` and sizes the next one: in
    /// proportion to the time left, at most doubling or halving per frame.
    pub fn update(&mut self, spp: u32, render: Duration) {
        let target = self.budget.as_secs_f64() * RENDER_SHARE;
        let took = render.as_secs_f64();
        let spp = spp.max(1);
        let ideal = if took > 0.0 { spp as f64 * target / took } else { 2.0 * spp as f64 };
        let lo = (spp / 2).max(1) as f64;
        let hi = (spp * 2).min(MAX_SPP) as f64;
        self.spp = ideal.clamp(lo, hi).floor().max(1.0) as u32;
    }
}

/// Running frame statistics for the title: exponential moving averages, so the numbers
/// settle within a few frames yet follow a change (another integrator, a bigger window).
#[derive(Clone, Debug, Default)]
pub struct FrameStats {
    frame_ms: Option<f64>,
    samples_per_s: Option<f64>,
}

impl FrameStats {
    const WEIGHT: f64 = 0.2;

    /// A frame of `time` that rendered `samples` samples (pixels x spp).
    pub fn add(&mut self, time: Duration, samples: u64) {
        let ms = time.as_secs_f64() * 1e3;
        let rate = samples as f64 / time.as_secs_f64().max(1e-9);
        let ema = |old: Option<f64>, new: f64| Some(old.map_or(new, |o| o + Self::WEIGHT * (new - o)));
        self.frame_ms = ema(self.frame_ms, ms);
        self.samples_per_s = ema(self.samples_per_s, rate);
    }

    pub fn frame_ms(&self) -> f64 {
        self.frame_ms.unwrap_or(0.0)
    }

    pub fn msamples_per_s(&self) -> f64 {
        self.samples_per_s.unwrap_or(0.0) / 1e6
    }

    /// The window title.
    pub fn title(&self, integrator: &str, spp: u32, exposure: f32) -> String {
        let mut t =
            format!("bidir view - {integrator} - {spp} spp - {:.1} ms/frame - {:.2} Msamples/s", self.frame_ms(), self.msamples_per_s());
        if exposure != 0.0 {
            t += &format!(" - exposure {exposure:+.1}");
        }
        t
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ms(x: f64) -> Duration {
        Duration::from_secs_f64(x / 1e3)
    }

    #[test]
    fn batches_follow_the_budget() {
        let mut p = Pacer::new(ms(16.0));
        // A fast device: 1 ms per spp grows to the budget's render share, doubling per frame.
        let mut sizes = vec![];
        for _ in 0..8 {
            let spp = p.spp();
            p.update(spp, ms(spp as f64));
            sizes.push(p.spp());
        }
        assert_eq!(&sizes[..4], &[2, 4, 8, 12]);
        assert_eq!(*sizes.last().unwrap(), 12);
        // A slow device: never below one sample per pixel.
        let mut p = Pacer::new(ms(16.0));
        p.update(1, ms(150.0));
        assert_eq!(p.spp(), 1);
        // Slower frames halve at most.
        let mut p = Pacer { budget: ms(16.0), spp: 64 };
        p.update(64, ms(1000.0));
        assert_eq!(p.spp(), 32);
        p.restart();
        assert_eq!(p.spp(), 1);
    }

    #[test]
    fn stats_average_and_title() {
        let mut s = FrameStats::default();
        s.add(ms(100.0), 65_536);
        assert!((s.frame_ms() - 100.0).abs() < 1e-9);
        assert!((s.msamples_per_s() - 0.65536).abs() < 1e-9);
        s.add(ms(200.0), 65_536);
        assert!((s.frame_ms() - 120.0).abs() < 1e-9);
        let t = s.title("pt-nee", 12, 0.5);
        assert!(t.contains("pt-nee") && t.contains("12 spp") && t.contains("120.0 ms/frame") && t.contains("exposure +0.5"), "{t}");
    }
}
