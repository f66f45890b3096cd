//! Chi-square tests of direction sampling on the sphere: cells in (cos θ, φ) about a normal,
//! refined geometrically about the pdf's peaks, and Gauss–Legendre quadrature of the kernel's
//! own pdf over each cell (the expected counts). φ is measured in the plane of the normal's
//! frame, relative to the direction opposite the incident one's azimuth (mirror and refracted
//! peaks both lie at φ = 0).

use glam::{DVec3, Vec4};
use std::f64::consts::PI;

/// Gauss–Legendre nodes and weights on [-1, 1] (8 points) per cell edge: cells grow
/// geometrically away from a peak, so the pdf changes by a factor of a few across one, which
/// a midpoint rule resolves only to ~1e-4 of the total (enough to fail a million-sample
/// test); Gauss–Legendre is exact for polynomials of degree 15.
pub const GAUSS: [(f64, f64); 8] = [
    (-0.9602898564975363, 0.1012285362903763),
    (-0.7966664774136267, 0.2223810344533745),
    (-0.525532409916329, 0.313706645877887),
    (-0.1834346424956498, 0.362683783378362),
    (0.1834346424956498, 0.362683783378362),
    (0.525532409916329, 0.313706645877887),
    (0.7966664774136267, 0.2223810344533745),
    (0.9602898564975363, 0.1012285362903763),
];
/// Quadrature nodes per cell and axis.
pub const QUAD: usize = GAUSS.len();

pub fn dv(v: Vec4) -> DVec3 {
    DVec3::new(v.x as f64, v.y as f64, v.z as f64)
}

/// An orthonormal frame (t, b) about n, built here independently of the kernel's.
pub fn frame(n: DVec3) -> (DVec3, DVec3) {
    let helper = if n.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
    let t = helper.cross(n).normalize();
    (t, n.cross(t))
}

/// Edges in [lo, hi] refined geometrically about each peak: peak ± first · 2^k (with lo, hi
/// and the peaks themselves).
pub fn edges_about(peaks: &[f64], lo: f64, hi: f64, first: f64) -> Vec<f64> {
    let mut e = vec![lo, hi];
    for &at in peaks {
        let mut step = first;
        while step < hi - lo {
            e.extend([at - step, at + step].into_iter().filter(|x| *x > lo && *x < hi));
            step *= 2.0;
        }
        if at > lo && at < hi {
            e.push(at);
        }
    }
    e.sort_by(f64::total_cmp);
    e.dedup();
    e
}

/// The interval of `edges` holding x (clamped to the first and last).
pub fn bin(edges: &[f64], x: f64) -> usize {
    edges.partition_point(|&e| e <= x).clamp(1, edges.len() - 1) - 1
}

/// Cells of the sphere about a normal: z = cos θ edges times φ edges.
pub struct Cells {
    pub n: DVec3,
    pub t: DVec3,
    pub b: DVec3,
    pub z_edges: Vec<f64>,
    pub phi_edges: Vec<f64>,
}

impl Cells {
    pub fn new(n: DVec3, z_edges: Vec<f64>, phi_edges: Vec<f64>) -> Cells {
        let (t, b) = frame(n);
        Cells { n, t, b, z_edges, phi_edges }
    }

    /// Number of cells (the failure cell of a chi-square test comes after them).
    pub fn count(&self) -> usize {
        (self.z_edges.len() - 1) * (self.phi_edges.len() - 1)
    }

    /// The direction at z = cos θ and φ relative to the plane of incidence.
    fn dir(&self, z: f64, rel_phi: f64) -> DVec3 {
        let phi = PI + rel_phi;
        let r = (1.0 - z * z).max(0.0).sqrt();
        self.n * z + self.t * (r * phi.cos()) + self.b * (r * phi.sin())
    }

    /// (wo, wi) pairs at every cell's QUAD x QUAD nodes, cell by cell, for the kernel's pdf
    /// evaluation, and each node's weight (its share of the cell's dz dφ).
    pub fn quadrature(&self, wo: DVec3) -> (Vec<Vec4>, Vec<f64>) {
        let (ze, pe) = (&self.z_edges, &self.phi_edges);
        let mut pairs = Vec::with_capacity(2 * self.count() * QUAD * QUAD);
        let mut weights = Vec::with_capacity(self.count() * QUAD * QUAD);
        for zi in 0..ze.len() - 1 {
            let (z0, z1) = (ze[zi], ze[zi + 1]);
            for pi in 0..pe.len() - 1 {
                let (p0, p1) = (pe[pi], pe[pi + 1]);
                for (xz, wz) in GAUSS {
                    for (xp, wp) in GAUSS {
                        let z = 0.5 * (z0 + z1) + 0.5 * (z1 - z0) * xz;
                        let p = 0.5 * (p0 + p1) + 0.5 * (p1 - p0) * xp;
                        pairs.push(wo.as_vec3().extend(0.0));
                        pairs.push(self.dir(z, p).as_vec3().extend(0.0));
                        weights.push(0.25 * (z1 - z0) * (p1 - p0) * wz * wp);
                    }
                }
            }
        }
        (pairs, weights)
    }

    /// Per-cell integrals of the pdf values `pdf` at the nodes of `quadrature` (same order),
    /// with one more (zero) entry for the failure cell.
    pub fn integrate(&self, pdf: impl Fn(usize) -> f64, weights: &[f64]) -> Vec<f64> {
        let mut expected = vec![0.0f64; self.count() + 1];
        for (k, w) in weights.iter().enumerate() {
            expected[k / (QUAD * QUAD)] += pdf(k) * w;
        }
        expected
    }

    /// The cell of unit direction d.
    pub fn cell(&self, d: DVec3) -> usize {
        let rel = d.dot(self.b).atan2(d.dot(self.t)).rem_euclid(2.0 * PI) - PI;
        bin(&self.z_edges, d.dot(self.n)) * (self.phi_edges.len() - 1) + bin(&self.phi_edges, rel)
    }
}
