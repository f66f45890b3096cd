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
