//! Benchmarks (not tests): where a render's GPU time goes (per-kernel timestamps), traversal speed (GPU-timestamped, warmed up, repeated, median
//! reported) and convergence runs (RMSE against a reference over render time, with charts).

pub mod chart;
pub mod converge;
pub mod driver_rt;
pub mod json;
pub mod render;
pub mod traversal;

/// The least time the untimed warm-up runs of a benchmark take (when any are asked for): a GPU
/// left idle (a slow BVH build) runs at its idle clock, and a few runs of milliseconds do not
/// raise it again (`bench traversal` on the H200, session 26); and a fresh process's first tenth
/// of a second of GPU work can run slow at full clocks (`bench render` on H100s, session 44: 13 of
/// 30 processes took 33-88 ms instead of 19 after one warm-up run, none of 20 after 1 s;
/// docs/results.md, "A fresh process's slow first tenth of a second").
pub const WARMUP_TIME: std::time::Duration = std::time::Duration::from_secs(1);

/// Whether a benchmark that asked for `warmup` untimed runs, has done `done` since `start`,
/// runs another: until it has done `warmup` and, where `warmup` > 0, for at least WARMUP_TIME.
pub fn warming_up(done: usize, warmup: usize, start: std::time::Instant) -> bool {
    done < warmup || (warmup > 0 && start.elapsed() < WARMUP_TIME)
}

/// Median of a non-empty sample (sorted copy).
pub fn median(xs: &[f64]) -> f64 {
    let mut v = xs.to_vec();
    v.sort_by(|a, b| a.total_cmp(b));
    let n = v.len();
    if n == 0 {
        return f64::NAN;
    }
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::{Duration, Instant};

    #[test]
    fn warm_up_takes_its_runs_and_then_its_time() {
        let now = Instant::now();
        assert!(!warming_up(0, 0, now), "no warm-up asked for: none, however early");
        assert!(warming_up(1, 2, now), "fewer runs than asked for");
        assert!(warming_up(2, 2, now), "the runs asked for, but not yet WARMUP_TIME");
        let long_ago = now.checked_sub(WARMUP_TIME + Duration::from_millis(10)).expect("a machine up for over a second");
        assert!(!warming_up(2, 2, long_ago), "the runs and the time");
        assert!(warming_up(1, 2, long_ago), "the time, but not the runs");
    }
}
