//! How long a pass of `spp` samples per pixel takes: `overhead x pieces + spp x per_spp`, fitted
//! to the last two passes of different sizes. A piece is the part of one BDPT iteration a pass
//! covers (iterations start at multiples of the sample slices, `Renderer::pass_at`): each carries
//! the launches' tails and host round trips of a whole iteration, about 3 ms on an H200 against
//! 0.12 ms a sample on the 256² Cornell box (docs/results.md, "a pass piece's fixed cost"); a pass
//! of the other integrators is one piece. Time-budgeted rendering sizes its passes from it, so a
//! render reaches the GPU's steady rate after one small calibration pass instead of ramping up
//! from one sample per pixel, and its last pass ends near the deadline.

/// A linear model of pass time, learnt from measured passes.
#[derive(Clone, Copy, Debug, Default)]
pub struct PassModel {
    /// Fixed cost of a pass piece (submission, fence wait, host work, launches' tails), seconds.
    overhead_s: f64,
    /// Cost of one more sample per pixel, seconds.
    per_spp_s: f64,
    /// Samples of an iteration, where passes are cut into pieces at its multiples (BDPT with
    /// more than one sample slice); 0: a pass is one piece.
    iteration: u32,
    /// The last pass measured: (spp, pieces, seconds).
    last: Option<(u32, u32, f64)>,
    /// The longest pass measured, seconds.
    longest_s: f64,
}

/// How many times longer than the longest pass measured a budgeted pass may be
/// ([`PassModel::spp_within_budget`]).
const MAX_PASS_GROWTH: f64 = 4.0;

impl PassModel {
    /// A model for passes cut into pieces at multiples of `iteration` samples (0 or 1: a pass
    /// is one piece; with one slice an iteration's fixed cost is part of each sample's).
    pub fn new(iteration: u32) -> Self {
        PassModel { iteration: if iteration > 1 { iteration } else { 0 }, ..Default::default() }
    }

    /// Whether at least one pass has been measured.
    pub fn known(&self) -> bool {
        self.last.is_some()
    }

    /// Pieces of a pass of samples `first..first + spp`: the iterations it touches.
    pub fn pieces(&self, first: u32, spp: u32) -> u32 {
        match (self.iteration, spp) {
            (_, 0) => 0,
            (0, _) => 1,
            (n, _) => (first + spp - 1) / n - first / n + 1,
        }
    }

    /// Learns from a pass of samples `first..first + spp` that took `seconds`.
    pub fn record(&mut self, first: u32, spp: u32, seconds: f64) {
        let seconds = seconds.max(1e-9);
        let pieces = self.pieces(first, spp).max(1);
        let fit = self.last.and_then(|(s0, p0, t0)| {
            // Two passes: t = overhead x pieces + per_spp x spp, solved.
            let det = pieces as f64 * s0 as f64 - p0 as f64 * spp as f64;
            if det == 0.0 {
                return None;
            }
            let per = (pieces as f64 * t0 - p0 as f64 * seconds) / det;
            // A first pass slowed by one-time costs would make the slope too shallow and the
            // next pass too long: the overhead may explain at most half of the larger pass.
            let (s_big, p_big, t_big) = if spp > s0 { (spp, pieces, seconds) } else { (s0, p0, t0) };
            let per = per.max(0.5 * t_big / s_big as f64);
            (per > 0.0).then(|| (per, ((t_big - s_big as f64 * per) / p_big as f64).max(0.0)))
        });
        match fit {
            Some((per, overhead)) => {
                self.per_spp_s = per;
                self.overhead_s = overhead;
            }
            // One size only (or timing noise): all of it per sample, an overestimate that
            // makes the next pass smaller than it could be, never larger.
            None if self.last.is_none_or(|(s0, p0, _)| (s0, p0) != (spp, pieces)) || self.per_spp_s <= 0.0 => {
                self.per_spp_s = seconds / spp.max(1) as f64;
                self.overhead_s = 0.0;
            }
            // The same size again: keep the fit, refreshing the per-sample cost.
            None => self.per_spp_s = ((seconds - self.overhead_s * pieces as f64) / spp.max(1) as f64).max(1e-12),
        }
        self.last = Some((spp, pieces, seconds));
        self.longest_s = self.longest_s.max(seconds);
    }

    /// Predicted seconds of a pass of samples `first..first + spp`.
    pub fn seconds(&self, first: u32, spp: u32) -> f64 {
        self.overhead_s * self.pieces(first, spp) as f64 + spp as f64 * self.per_spp_s
    }

    /// As [`spp_within`](Self::spp_within) for a pass of a time budget of `budget` seconds
    /// with `seconds` left: the pass also takes at most `MAX_PASS_GROWTH` (4) times the longest
    /// pass measured, or a quarter of the budget if that is more. A model fitted to small
    /// passes, extrapolated to a pass many times their size, ran 13 % long on the H200 (the
    /// caustic scene at 128², 0.1 s: fitted to passes of 1 and 61 spp, a last pass of 1,491
    /// took 104.9 ms for a predicted 93.0; session 13), so a budget grows its passes in steps
    /// whose times the model has nearly seen. A pass held back by that limit, not by the
    /// budget, ends on an iteration's boundary where it reaches one, so that the next pass
    /// does not pay the fixed cost of the same iteration again.
    pub fn spp_within_budget(&self, first: u32, seconds: f64, budget: f64) -> u32 {
        let held = (MAX_PASS_GROWTH * self.longest_s).max(0.25 * budget);
        let spp = self.spp_within(first, seconds.min(held));
        if self.iteration > 0 && held < seconds {
            let boundary = (first + spp) / self.iteration * self.iteration;
            if boundary > first {
                return boundary - first;
            }
        }
        spp
    }

    /// Samples of the next pass of a render of `budget` seconds with `left` seconds left, from
    /// sample `first` (`started`: a pass has been rendered), or None where the render should
    /// stop: one calibration sample while nothing has been measured, then as many as
    /// [`spp_within_budget`](Self::spp_within_budget) allows; one sample where none fits but
    /// it would overshoot the budget by at most 10 %.
    pub fn budgeted_spp(&self, first: u32, started: bool, left: f64, budget: f64) -> Option<u32> {
        if !self.known() {
            return Some(1);
        }
        match self.spp_within(first, left) {
            0 if started && self.seconds(first, 1) - left > 0.1 * budget => None,
            0 => Some(1),
            _ => Some(self.spp_within_budget(first, left, budget).max(1)),
        }
    }

    /// Most samples per pixel a pass from sample `first` may have to end within `seconds` (0
    /// where even one would not).
    pub fn spp_within(&self, first: u32, seconds: f64) -> u32 {
        if self.per_spp_s <= 0.0 {
            return 0;
        }
        // Without pieces, the linear model solved; with them, the largest count whose pieces'
        // and samples' costs fit (the time grows with the count).
        let linear = ((seconds - self.overhead_s) / self.per_spp_s).floor().clamp(0.0, u32::MAX as f64) as u32;
        if self.iteration == 0 || linear == 0 {
            return linear;
        }
        let (mut lo, mut hi) = (0u32, linear);
        while lo < hi {
            let mid = lo + (hi - lo).div_ceil(2);
            if self.seconds(first, mid) <= seconds {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        lo
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_pass_sizes_recover_overhead_and_rate() {
        let mut m = PassModel::default();
        assert!(!m.known());
        m.record(0, 1, 0.010 + 0.001);
        // One pass: everything is charged to the sample (conservative).
        assert!((m.seconds(1, 1) - 0.011).abs() < 1e-12);
        m.record(1, 100, 0.010 + 0.100);
        assert!((m.overhead_s - 0.010).abs() < 1e-9 && (m.per_spp_s - 0.001).abs() < 1e-9);
        assert_eq!(m.spp_within(101, 0.110), 100);
        assert_eq!(m.spp_within(101, 0.005), 0);
    }

    #[test]
    fn budgeted_passes_grow_at_most_four_times_the_longest_or_to_a_quarter() {
        let mut m = PassModel::default();
        m.record(0, 1, 0.0016);
        m.record(1, 61, 0.0053);
        // 93 ms left of 100: the model alone would fill them (~1,490 spp); the pass is held to
        // a quarter of the budget (more than 4 x 5.3 ms).
        let all = m.spp_within(62, 0.093);
        let capped = m.spp_within_budget(62, 0.093, 0.1);
        assert!(all > 1400 && capped == m.spp_within(62, 0.025), "{all} {capped}");
        // Once that 25 ms pass is measured, up to 100 ms: what is left (93 ms) again.
        m.record(62, capped, m.seconds(62, capped));
        assert!(4.0 * m.seconds(62, capped) > 0.093);
        assert_eq!(m.spp_within_budget(62, 0.093, 0.1), all);
        // A longest pass of 5.3 ms and a budget of 10 ms: at most 21.2 ms (the quarter is less).
        let mut m = PassModel::default();
        m.record(0, 1, 0.0016);
        m.record(1, 61, 0.0053);
        assert_eq!(m.spp_within_budget(62, 0.05, 0.01), m.spp_within(62, 4.0 * 0.0053));
        // With a long budget, the quarter governs.
        assert_eq!(m.spp_within_budget(62, 2.0, 2.0), m.spp_within(62, 0.5));
    }

    #[test]
    fn noisy_or_repeated_sizes_stay_sane() {
        let mut m = PassModel::default();
        m.record(0, 10, 0.02);
        m.record(10, 20, 0.01); // faster with more samples: noise, not a negative cost
        assert!(m.per_spp_s > 0.0 && m.overhead_s >= 0.0);
        m.record(30, 20, 0.02);
        assert!(m.per_spp_s > 0.0);
    }

    #[test]
    fn pieces_count_the_iterations_a_pass_touches() {
        let m = PassModel::new(128);
        assert_eq!([m.pieces(0, 1), m.pieces(0, 128), m.pieces(0, 129), m.pieces(127, 2), m.pieces(72, 399)], [1, 1, 2, 2, 4]);
        assert_eq!(m.pieces(5, 0), 0);
        // One slice, or integrators without iterations: a pass is one piece.
        assert_eq!([PassModel::new(1).pieces(3, 500), PassModel::default().pieces(3, 500)], [1, 1]);
    }

    /// Passes whose costs follow t = 3 ms x pieces + 0.12 ms x spp (the H200's BDPT passes on
    /// the 256² Cornell box, 128 samples an iteration) teach the model both terms, and it
    /// predicts a pass of several pieces.
    #[test]
    fn pieces_and_samples_are_told_apart() {
        let cost = |m: &PassModel, first, spp| 0.003 * m.pieces(first, spp) as f64 + 0.00012 * spp as f64;
        let mut m = PassModel::new(128);
        m.record(1, 10, cost(&m, 1, 10));
        m.record(84, 300, cost(&m, 84, 300));
        assert!((m.overhead_s - 0.003).abs() < 1e-9 && (m.per_spp_s - 0.00012).abs() < 1e-9, "{m:?}");
        assert!((m.seconds(384, 1000) - cost(&m, 384, 1000)).abs() < 1e-9);
        // The most samples within a time, by the pieces they take: 18.36 ms is one whole
        // iteration from a boundary, but only 103 where it starts a sample earlier (two pieces).
        assert_eq!(m.spp_within(384, 0.01836 + 1e-9), 128);
        assert_eq!(m.spp_within(383, 0.01836 + 1e-9), 103);
    }

    /// A pass held back by the growth limit ends on an iteration's boundary where it reaches
    /// one; the last pass, sized by what is left, does not.
    #[test]
    fn held_passes_end_on_a_boundary() {
        // Passes of 0.5 ms a piece and 0.12 ms a sample, 128 samples an iteration.
        let cost = |first, spp| 0.0005 * PassModel::new(128).pieces(first, spp) as f64 + 0.00012 * spp as f64;
        let mut m = PassModel::new(128);
        m.record(1, 10, cost(1, 10));
        m.record(11, 73, cost(11, 73));
        // 81 ms left of 100: held to four times the longest pass (37 ms), which reaches past
        // sample 256 but not 384: the pass ends at 256.
        let held_s = 4.0 * cost(11, 73);
        let held = m.spp_within(84, held_s);
        assert!(84 + held > 256 && 84 + held < 384, "{held}");
        assert_eq!(m.spp_within_budget(84, 0.081, 0.1), 256 - 84);
        // 20 ms left: all of it, wherever it ends.
        assert_eq!(m.spp_within_budget(84, 0.020, 0.1), m.spp_within(84, 0.020));
        // From sample 300 the held pass reaches past 512, not 640: it ends at 512.
        assert_eq!(m.spp_within_budget(300, 0.081, 0.1), 512 - 300);
        // From a boundary, whole iterations.
        assert_eq!(m.spp_within_budget(256, 0.081, 0.1), 256);
    }

    /// A time-budgeted render over passes that cost what the H200's BDPT passes cost on the
    /// 256² Cornell box (3 ms a piece, 0.12 ms a sample; its first pass 2.4 ms, its second 1 ms
    /// more for submissions the launch counts did not foresee) renders its first 0.1 s at more
    /// of the steady rate when the model knows the pieces: 90 % or more of the 6,972 spp/s of
    /// whole iterations, where a model of one overhead a pass reached 87 % (619 spp).
    #[test]
    fn a_budget_of_pieces_runs_near_the_steady_rate() {
        let budget = 0.1;
        let steady = 128.0 / (0.003 + 128.0 * 0.00012);
        let pieces = |first, spp| PassModel::new(128).pieces(first, spp) as f64;
        let simulate = |mut m: PassModel| {
            let (mut t, mut spp, mut pass) = (0.0, 0u32, 0);
            while let Some(n) = m.budgeted_spp(spp, spp > 0, budget - t, budget) {
                if spp > 0 && budget - t <= 0.0 {
                    break;
                }
                let took = match pass {
                    0 => 0.0024,
                    1 => 0.001 + 0.003 * pieces(spp, n) + 0.00012 * n as f64,
                    _ => 0.003 * pieces(spp, n) + 0.00012 * n as f64,
                };
                m.record(spp, n, took);
                (t, spp, pass) = (t + took, spp + n, pass + 1);
            }
            (spp, t)
        };
        let (spp, t) = simulate(PassModel::new(128));
        let rate = spp as f64 / t / steady;
        assert!(rate >= 0.9 && t <= 1.1 * budget, "{spp} spp in {t} s: {rate}");
        let (spp1, t1) = simulate(PassModel::new(1));
        assert!(spp1 < spp && t1 <= 1.1 * budget, "{spp1} spp in {t1} s");
    }
}
