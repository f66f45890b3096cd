//! Benchmarks (not tests): where a render's GPU time goes (per-kernel timestamps), traversal speed (GPU-timestamped, warmed up, repeated, median
//! reported) and convergence runs (RMSE against a reference over render time, with charts).

pub mod chart;
pub mod converge;
pub mod driver_rt;
pub mod json;
pub mod render;
pub mod traversal;

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
