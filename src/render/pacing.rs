//! How long a pass of `spp` samples per pixel takes: `overhead + spp * per_spp`, fitted to the
//! last two passes of different sizes. Time-budgeted rendering sizes its passes from it, so a
//! render reaches the GPU's steady rate after one small calibration pass instead of ramping up
//! from one sample per pixel, and its last pass ends near the deadline.

/// A linear model of pass time, learnt from measured passes.
#[derive(Clone, Copy, Debug, Default)]
pub struct PassModel {
    /// Fixed cost of a pass (submission, fence wait, host work), seconds.
    overhead_s: f64,
    /// Cost of one more sample per pixel, seconds.
    per_spp_s: f64,
    /// The last pass measured: (spp, seconds).
    last: Option<(u32, f64)>,
    /// The longest pass measured, seconds.
    longest_s: f64,
}

/// How many times longer than the longest pass measured a budgeted pass may be
/// ([`PassModel::spp_within_budget`]).
const MAX_PASS_GROWTH: f64 = 4.0;

impl PassModel {
    /// Whether at least one pass has been measured.
    pub fn known(&self) -> bool {
        self.last.is_some()
    }

    /// Learns from a pass of `spp` samples per pixel that took `seconds`.
    pub fn record(&mut self, spp: u32, seconds: f64) {
        let seconds = seconds.max(1e-9);
        let fit = self.last.and_then(|(s0, t0)| {
            if s0 == spp {
                return None;
            }
            let per = (seconds - t0) / (spp as f64 - s0 as f64);
            // A first pass slowed by one-time costs would make the slope too shallow and the
            // next pass too long: the overhead may explain at most half of the larger pass.
            let (s_big, t_big) = if spp > s0 { (spp, seconds) } else { (s0, t0) };
            let per = per.max(0.5 * t_big / s_big as f64);
            (per > 0.0).then(|| (per, (t_big - s_big as f64 * per).max(0.0)))
        });
        match fit {
            Some((per, overhead)) => {
                self.per_spp_s = per;
                self.overhead_s = overhead;
            }
            // One size only (or timing noise): all of it per sample, an overestimate that
            // makes the next pass smaller than it could be, never larger.
            None if self.last.is_none_or(|(s0, _)| s0 != spp) || self.per_spp_s <= 0.0 => {
                self.per_spp_s = seconds / spp.max(1) as f64;
                self.overhead_s = 0.0;
            }
            // The same size again: keep the fit, refreshing the per-sample cost.
            None => self.per_spp_s = ((seconds - self.overhead_s) / spp.max(1) as f64).max(1e-12),
        }
        self.last = Some((spp, seconds));
        self.longest_s = self.longest_s.max(seconds);
    }

    /// Predicted seconds of a pass of `spp`.
    pub fn seconds(&self, spp: u32) -> f64 {
        self.overhead_s + spp as f64 * self.per_spp_s
    }

    /// As [`spp_within`](Self::spp_within) for a pass of a time budget of `budget` seconds
    /// with `seconds` left: the pass also takes at most `MAX_PASS_GROWTH` (4) times the longest
    /// pass measured, or a quarter of the budget if that is more. A model fitted to small
    /// passes, extrapolated to a pass many times their size, ran 13 % long on the H200 (the
    /// caustic scene at 128², 0.1 s: fitted to passes of 1 and 61 spp, a last pass of 1,491
    /// took 104.9 ms for a predicted 93.0; session 13), so a budget grows its passes in steps
    /// whose times the model has nearly seen.
    pub fn spp_within_budget(&self, seconds: f64, budget: f64) -> u32 {
        self.spp_within(seconds.min((MAX_PASS_GROWTH * self.longest_s).max(0.25 * budget)))
    }

    /// Most samples per pixel a pass may have to end within `seconds` (0 where even one would
    /// not).
    pub fn spp_within(&self, seconds: f64) -> u32 {
        if self.per_spp_s <= 0.0 {
            return 0;
        }
        ((seconds - self.overhead_s) / self.per_spp_s).floor().clamp(0.0, u32::MAX as f64) as u32
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_pass_sizes_recover_overhead_and_rate() {
        let mut m = PassModel::default();
        assert!(!m.known());
        m.record(1, 0.010 + 0.001);
        // One pass: everything is charged to the sample (conservative).
        assert!((m.seconds(1) - 0.011).abs() < 1e-12);
        m.record(100, 0.010 + 0.100);
        assert!((m.overhead_s - 0.010).abs() < 1e-9 && (m.per_spp_s - 0.001).abs() < 1e-9);
        assert_eq!(m.spp_within(0.110), 100);
        assert_eq!(m.spp_within(0.005), 0);
    }

    #[test]
    fn budgeted_passes_grow_at_most_four_times_the_longest_or_to_a_quarter() {
        let mut m = PassModel::default();
        m.record(1, 0.0016);
        m.record(61, 0.0053);
        // 93 ms left of 100: the model alone would fill them (~1,490 spp); the pass is held to
        // a quarter of the budget (more than 4 x 5.3 ms).
        let all = m.spp_within(0.093);
        let capped = m.spp_within_budget(0.093, 0.1);
        assert!(all > 1400 && capped == m.spp_within(0.025), "{all} {capped}");
        // Once that 25 ms pass is measured, up to 100 ms: what is left (93 ms) again.
        m.record(capped, m.seconds(capped));
        assert!(4.0 * m.seconds(capped) > 0.093);
        assert_eq!(m.spp_within_budget(0.093, 0.1), all);
        // A longest pass of 5.3 ms and a budget of 10 ms: at most 21.2 ms (the quarter is less).
        let mut m = PassModel::default();
        m.record(1, 0.0016);
        m.record(61, 0.0053);
        assert_eq!(m.spp_within_budget(0.05, 0.01), m.spp_within(4.0 * 0.0053));
        // With a long budget, the quarter governs.
        assert_eq!(m.spp_within_budget(2.0, 2.0), m.spp_within(0.5));
    }

    #[test]
    fn noisy_or_repeated_sizes_stay_sane() {
        let mut m = PassModel::default();
        m.record(10, 0.02);
        m.record(20, 0.01); // faster with more samples: noise, not a negative cost
        assert!(m.per_spp_s > 0.0 && m.overhead_s >= 0.0);
        m.record(20, 0.02);
        assert!(m.per_spp_s > 0.0);
    }
}
