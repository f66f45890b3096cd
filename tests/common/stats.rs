//! Goodness-of-fit statistics for the sampling tests: Pearson's chi-square test with pooling
//! of sparse cells, and its p-value through the regularised upper incomplete gamma function
//! (written here from its series and continued fraction; checked in tests/sampling.rs).
#![allow(dead_code)]

/// ln Γ(k / 2) for k >= 1, exact up to rounding: Γ(1/2) = √π, Γ(1) = 1 and Γ(a + 1) = a Γ(a)
/// (DLMF 5.4.6, 5.5.1). Chi-square with k degrees of freedom needs only these.
pub fn ln_gamma_half(k: u32) -> f64 {
    assert!(k >= 1);
    let (mut a, mut ln) = if k % 2 == 0 { (1.0, 0.0) } else { (0.5, 0.5 * std::f64::consts::PI.ln()) };
    while a < k as f64 / 2.0 {
        ln += a.ln();
        a += 1.0;
    }
    ln
}

/// Regularised upper incomplete gamma function Q(a, x) = Γ(a, x) / Γ(a), given ln Γ(a).
/// For x < a + 1 from the power series of the lower function, P(a, x) = x^a e^-x / Γ(a + 1) *
/// Σ_n x^n / ((a + 1) ... (a + n)) (DLMF 8.7.1, 8.2.7), Q = 1 - P; otherwise from Legendre's
/// continued fraction Γ(a, x) = x^a e^-x / (x + 1 - a - 1 (1 - a) / (x + 3 - a - 2 (2 - a) /
/// (x + 5 - a - ...))) (DLMF 8.9.2, even part), evaluated forward by the modified Lentz
/// method.
pub fn gamma_q(a: f64, x: f64, ln_gamma_a: f64) -> f64 {
    assert!(a > 0.0 && x.is_finite());
    if x <= 0.0 {
        return 1.0;
    }
    let prefactor = (a * x.ln() - x - ln_gamma_a).exp(); // x^a e^-x / Γ(a)
    if x < a + 1.0 {
        let (mut term, mut sum, mut n) = (1.0 / a, 1.0 / a, 0.0);
        while term > sum * 1e-17 {
            n += 1.0;
            term *= x / (a + n);
            sum += term;
        }
        // sum = Σ_n x^n / (a (a + 1) ... (a + n)), so P = x^a e^-x / Γ(a) * sum.
        return (1.0 - prefactor * sum).max(0.0);
    }
    let tiny = 1e-300;
    let mut f = x + 1.0 - a;
    if f.abs() < tiny {
        f = tiny;
    }
    let (mut c, mut d) = (f, 0.0);
    for i in 1..10_000 {
        let i = i as f64;
        let an = -i * (i - a);
        let bn = x + 2.0 * i + 1.0 - a;
        d = bn + an * d;
        if d.abs() < tiny {
            d = tiny;
        }
        c = bn + an / c;
        if c.abs() < tiny {
            c = tiny;
        }
        d = 1.0 / d;
        let delta = c * d;
        f *= delta;
        if (delta - 1.0).abs() < 1e-16 {
            break;
        }
    }
    prefactor / f
}

/// P(X >= x) for X chi-square distributed with `dof` degrees of freedom: Q(dof / 2, x / 2).
pub fn chi2_sf(x: f64, dof: u32) -> f64 {
    if x.is_infinite() {
        return 0.0;
    }
    gamma_q(dof as f64 / 2.0, x / 2.0, ln_gamma_half(dof))
}

/// Wilson–Hilferty approximation of the chi-square quantile with `dof` degrees of freedom at
/// standard normal quantile `z`: dof (1 - 2 / (9 dof) + z sqrt(2 / (9 dof)))^3 (a cross-check
/// of `chi2_sf` for large dof).
pub fn wilson_hilferty(dof: u32, z: f64) -> f64 {
    let k = dof as f64;
    let h = 2.0 / (9.0 * k);
    k * (1.0 - h + z * h.sqrt()).powi(3)
}

/// The outcome of a goodness-of-fit test.
#[derive(Clone, Copy, Debug)]
pub struct Fit {
    /// The test statistic (Pearson's X^2).
    pub stat: f64,
    pub dof: u32,
    /// P(X^2 >= stat) under the null hypothesis.
    pub p: f64,
    /// Cells after pooling.
    pub cells: usize,
}

impl std::fmt::Display for Fit {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "X^2 = {:.2}, dof = {}, p = {:.4}", self.stat, self.dof, self.p)
    }
}

/// Pearson's chi-square test of observed counts against expected counts, X^2 = Σ (O - E)^2 /
/// E over cells, with (cells - 1) degrees of freedom (the total is fixed). Cells expected to
/// hold fewer than `min_expected` (5, the usual rule) are pooled, smallest first, into groups
/// reaching it; a group left short joins the smallest regular cell. A count in a cell of
/// expected zero is an outright failure (X^2 = inf). Expected counts are not renormalised: a
/// pdf that does not integrate to the total fails here too.
pub fn pearson(observed: &[u64], expected: &[f64]) -> Fit {
    assert_eq!(observed.len(), expected.len());
    let mut order: Vec<usize> = (0..expected.len()).collect();
    order.sort_by(|&a, &b| expected[a].total_cmp(&expected[b]));
    let mut cells: Vec<(f64, f64)> = Vec::new(); // (observed, expected)
    let mut pool = (0.0, 0.0);
    let min_expected = 5.0;
    for &i in &order {
        let (o, e) = (observed[i] as f64, expected[i]);
        if e <= 0.0 {
            if o > 0.0 {
                return Fit { stat: f64::INFINITY, dof: 1, p: 0.0, cells: 0 };
            }
            continue;
        }
        if e >= min_expected && pool.1 == 0.0 {
            cells.push((o, e));
            continue;
        }
        pool = (pool.0 + o, pool.1 + e);
        if pool.1 >= min_expected {
            cells.push(pool);
            pool = (0.0, 0.0);
        }
    }
    if pool.1 > 0.0 {
        match cells.first_mut() {
            Some(c) => {
                c.0 += pool.0;
                c.1 += pool.1;
            }
            None => cells.push(pool),
        }
    }
    let stat: f64 = cells.iter().map(|&(o, e)| (o - e) * (o - e) / e).sum();
    let dof = (cells.len().max(2) - 1) as u32;
    Fit { stat, dof, p: chi2_sf(stat, dof), cells: cells.len() }
}

/// Two-sided binomial test by the normal approximation: `k` successes in `n` trials of
/// probability `p` give z^2 = (k - n p)^2 / (n p (1 - p)), chi-square with one degree of
/// freedom (Pearson's X^2 for two cells). Needs n p (1 - p) well above 5.
pub fn binomial(k: u64, n: u64, p: f64) -> Fit {
    let (k, n) = (k as f64, n as f64);
    let var = n * p * (1.0 - p);
    assert!(var > 25.0, "normal approximation needs n p (1 - p) >> 1 (have {var})");
    let stat = (k - n * p).powi(2) / var;
    Fit { stat, dof: 1, p: chi2_sf(stat, 1), cells: 2 }
}

/// Several independent tests combined: the sum of chi-square statistics is chi-square with
/// the sum of their degrees of freedom.
pub fn combine(fits: &[Fit]) -> Fit {
    let stat = fits.iter().map(|f| f.stat).sum();
    let dof = fits.iter().map(|f| f.dof).sum();
    Fit { stat, dof, p: chi2_sf(stat, dof), cells: fits.iter().map(|f| f.cells).sum() }
}

/// Mean and standard error of each statistic over independent replicates
/// (`samples[replicate][statistic]`).
pub fn replicate_mean_se(samples: &[Vec<f64>]) -> Vec<(f64, f64)> {
    let n = samples.len() as f64;
    (0..samples[0].len())
        .map(|i| {
            let mean = samples.iter().map(|s| s[i]).sum::<f64>() / n;
            let var = samples.iter().map(|s| (s[i] - mean).powi(2)).sum::<f64>() / (n - 1.0);
            (mean, (var / n).sqrt())
        })
        .collect()
}
