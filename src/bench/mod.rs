//! Benchmarks (not tests): where a render's GPU time goes (per-kernel timestamps), traversal speed (GPU-timestamped, warmed up, repeated, median
//! reported) and convergence runs (RMSE against a reference over render time, with charts).

pub mod chart;
pub mod converge;
pub mod driver_rt;
pub mod json;
pub mod render;
pub mod traversal;

/// Median of a non-empty sample (sorted copy).
/// The least time the untimed warm-up runs of a benchmark take (when any are asked for): a GPU
/// left idle (a slow BVH build, the gap between two processes) runs at its idle clock, and a few
/// runs of milliseconds do not raise it again (`bench traversal` on the H200, session 26;
/// `bench render` on an H100, session 44: one fresh process in four timed 68 ms, not 19).
pub const WARMUP_TIME: std::time::Duration = std::time::Duration::from_secs(1);

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
