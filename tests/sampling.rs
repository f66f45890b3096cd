//! The GLSL sampling routines the integrators use, run on the GPU through the test kernel
//! `glsl/tests/sampling.comp` (which calls the real functions from `glsl/common/`) and checked
//! against their analytic distributions:
//! - `sample_cosine_hemisphere` with Pearson's chi-square test over a (cos θ, φ) grid whose
//!   expected counts are the integral over each cell of the pdf the code reports
//!   (`cosine_hemisphere_pdf`), which must itself integrate to one;
//! - `sample_emitter` (alias-table choice by power, uniform point on the triangle) with
//!   chi-square over emitters and over equal-area sub-triangles of each emitter;
//! - `env_sample` (texel by luminance x solid angle through an alias table, direction uniform
//!   in solid angle inside it) with chi-square over sub-texel cells against the pdf the
//!   code reports, and `env_lookup` agreeing with that pdf;
//! - `sample_dielectric` with binomial tests of the reflection frequency against the exact
//!   Fresnel reflectance, and total internal reflection beyond the critical angle.
//!
//! Every test rejects at significance 1e-3; seeds are fixed, so a pass is reproducible.

mod common;

use bidir::gpu::abi;
use bidir::render::lights::LightTable;
use bidir::scene::{Material, Scene};
use common::sampling_kernel::SamplingKernel;
use common::stats::{self, Fit};
use common::{finish, gpu};
use glam::{DVec3, Vec3, Vec4};
use std::f64::consts::PI;

/// Samples per distribution.
const N: u32 = 1 << 20;
/// Significance level at which every test rejects.
const ALPHA: f64 = 1e-3;

fn dv(v: Vec4) -> DVec3 {
    DVec3::new(v.x as f64, v.y as f64, v.z as f64)
}

/// An orthonormal frame (t, b, n) built here, independently of the kernel's `onb`: the
/// cosine distribution is symmetric about n, so φ is uniform in any frame.
fn frame(n: DVec3) -> (DVec3, DVec3) {
    let helper = if n.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
    let t = helper.cross(n).normalize();
    (t, n.cross(t))
}

// ---- The statistics themselves ------------------------------------------------------------

#[test]
fn chi_square_p_values_match_closed_forms_and_tables() {
    // Even dof have the closed form Q(m, x) = e^-x Σ_{i<m} x^i / i! (DLMF 8.4.10).
    for dof in [2u32, 4, 10, 40] {
        for x in [0.1, 1.0, 3.0, 10.0, 25.0, 60.0, 120.0] {
            let m = dof / 2;
            let (mut term, mut sum) = (1.0, 1.0);
            for i in 1..m {
                term *= (x / 2.0) / i as f64;
                sum += term;
            }
            let exact = (-x / 2.0f64).exp() * sum;
            let got = stats::chi2_sf(x, dof);
            assert!((got - exact).abs() <= 1e-12 + 1e-10 * exact, "dof {dof}, x {x}: {got} vs {exact}");
        }
    }
    // Odd dof and large dof: the 1e-3 critical values of standard tables (NIST/SEMATECH
    // e-Handbook 1.3.6.7.4, three decimals).
    for (dof, crit) in [(1u32, 10.828), (3, 16.266), (5, 20.515), (11, 31.264), (25, 52.620), (100, 149.449)] {
        let p = stats::chi2_sf(crit, dof);
        assert!((p / 1e-3 - 1.0).abs() < 0.003, "dof {dof}: p({crit}) = {p}, expected 1e-3");
    }
    // Chi-square with one dof is a squared standard normal: P(|Z| >= 1.96) = 0.049996.
    assert!((stats::chi2_sf(1.96 * 1.96, 1) - 0.049996).abs() < 1e-5);
    // Large dof against the Wilson–Hilferty approximation (accurate to ~1e-3 relative in p here).
    for dof in [300u32, 1000, 5000] {
        let p = stats::chi2_sf(stats::wilson_hilferty(dof, 3.090232), dof);
        assert!((p / 1e-3 - 1.0).abs() < 0.05, "dof {dof}: {p}");
        let p = stats::chi2_sf(stats::wilson_hilferty(dof, 0.0), dof);
        assert!((p - 0.5).abs() < 0.01, "dof {dof}: median p {p}");
    }
}

#[test]
fn pearson_pools_sparse_cells_and_rejects_impossible_counts() {
    // Perfect agreement: X^2 = 0, p = 1.
    let f = stats::pearson(&[10, 20, 30], &[10.0, 20.0, 30.0]);
    assert_eq!((f.stat, f.dof), (0.0, 2));
    assert!((f.p - 1.0).abs() < 1e-12);
    // Three cells expected 2 each pool into one of 6 (observed 1 + 2 + 4 = 7).
    let f = stats::pearson(&[1, 2, 4, 100], &[2.0, 2.0, 2.0, 100.0]);
    assert_eq!((f.cells, f.dof), (2, 1));
    assert!((f.stat - 1.0 / 6.0).abs() < 1e-12, "{}", f.stat);
    // A count where nothing is expected fails outright.
    assert_eq!(stats::pearson(&[1, 99], &[0.0, 100.0]).p, 0.0);
    // A fair coin tossed 10000 times, 5200 heads: z = 4, p = 6.3e-5.
    let f = stats::binomial(5200, 10_000, 0.5);
    assert!((f.stat - 16.0).abs() < 1e-9 && (f.p - 6.334e-5).abs() < 1e-7, "{f}");
}

// ---- Cosine-weighted hemisphere -----------------------------------------------------------

/// Bins of cos θ (edges at sqrt(i / Z), equal probability under the cosine pdf) and of φ.
const Z_BINS: usize = 16;
const PHI_BINS: usize = 32;
/// Midpoint-rule points per cell edge for integrating the reported pdf; the cosine pdf is
/// linear in cos θ and constant in φ, so the rule is exact for it.
const QUAD: usize = 4;

fn z_edge(i: usize) -> f64 {
    (i as f64 / Z_BINS as f64).sqrt()
}

fn direction(n: DVec3, t: DVec3, b: DVec3, z: f64, phi: f64) -> DVec3 {
    let r = (1.0 - z * z).max(0.0).sqrt();
    n * z + t * (r * phi.cos()) + b * (r * phi.sin())
}

/// Checks sample_cosine_hemisphere about `normal`: chi-square of the samples against the
/// integral of cosine_hemisphere_pdf over each cell, the pdf's integral over the hemisphere
/// and the sphere, unit length and no sample below the surface.
fn check_cosine(s: &SamplingKernel, normal: Vec3, seed: u32) -> Fit {
    let n = normal.as_dvec3().normalize();
    let (t, b) = frame(n);
    let cells = Z_BINS * PHI_BINS;

    // The pdf the code reports, at QUAD x QUAD midpoints of every cell of (cos θ, φ), and at
    // their mirror images below the surface. dω = d(cos θ) dφ.
    let mut dirs = Vec::with_capacity(2 * cells * QUAD * QUAD);
    let mut weights = Vec::with_capacity(cells * QUAD * QUAD);
    for zi in 0..Z_BINS {
        let (z0, z1) = (z_edge(zi), z_edge(zi + 1));
        for pi in 0..PHI_BINS {
            let dphi = 2.0 * PI / PHI_BINS as f64;
            for qz in 0..QUAD {
                for qp in 0..QUAD {
                    let z = z0 + (z1 - z0) * (qz as f64 + 0.5) / QUAD as f64;
                    let phi = dphi * (pi as f64 + (qp as f64 + 0.5) / QUAD as f64);
                    dirs.push(direction(n, t, b, z, phi).as_vec3().extend(0.0));
                    weights.push((z1 - z0) / QUAD as f64 * dphi / QUAD as f64);
                }
            }
        }
    }
    let above = dirs.len();
    for i in 0..above {
        let d = dirs[i].truncate() - 2.0 * dirs[i].truncate().dot(normal.normalize()) * normal.normalize();
        dirs.push(d.extend(0.0));
    }
    let input = s.ctx.upload_buffer("sampling.dirs", &dirs).unwrap();
    let push =
        abi::SamplingTestPush { mode: abi::SAMPLING_COSINE_PDF, count: dirs.len() as u32, a: normal.extend(0.0), ..Default::default() };
    let pdf: Vec<f64> = s.run(push, 1, Some(&input)).iter().map(|v| v.x as f64).collect();
    let mut expected = vec![0.0f64; cells];
    for (k, w) in weights.iter().enumerate() {
        expected[k / (QUAD * QUAD)] += pdf[k] * w;
    }
    let integral: f64 = expected.iter().sum();
    let below: f64 = pdf[above..].iter().zip(&weights).map(|(p, w)| p * w).sum();
    eprintln!("cosine pdf about {normal}: integral over the hemisphere {integral:.7}, below it {below:.3e}");
    assert!((integral - 1.0).abs() < 1e-4, "cosine_hemisphere_pdf integrates to {integral} over the hemisphere, not 1");
    assert!(below == 0.0, "cosine_hemisphere_pdf is nonzero below the surface (integral {below})");
    for e in &mut expected {
        *e *= N as f64;
    }

    // The samples.
    let push = abi::SamplingTestPush { mode: abi::SAMPLING_COSINE, count: N, seed, a: normal.extend(0.0), ..Default::default() };
    let samples = s.run(push, 1, None);
    let mut observed = vec![0u64; cells];
    for v in &samples {
        let d = dv(*v);
        assert!((d.length() - 1.0).abs() < 1e-5, "direction {d} is not unit");
        let z = d.dot(n);
        assert!(z >= 0.0, "direction {d} below the surface about {n}");
        let phi = d.dot(b).atan2(d.dot(t)).rem_euclid(2.0 * PI);
        let zi = ((z * z * Z_BINS as f64) as usize).min(Z_BINS - 1);
        let pi = ((phi / (2.0 * PI) * PHI_BINS as f64) as usize).min(PHI_BINS - 1);
        observed[zi * PHI_BINS + pi] += 1;
    }
    let fit = stats::pearson(&observed, &expected);
    eprintln!("sample_cosine_hemisphere about {normal}: {fit}");
    fit
}

#[test]
fn cosine_hemisphere_matches_its_pdf() {
    let ctx = gpu();
    let s = SamplingKernel::new(&ctx);
    // Axis-aligned, tilted, and tilted into the lower half space (the other branch of the
    // orthonormal basis).
    let fits =
        [check_cosine(&s, Vec3::Z, 1), check_cosine(&s, Vec3::new(0.36, -0.48, 0.8), 2), check_cosine(&s, Vec3::new(-0.64, 0.48, -0.6), 3)];
    for (i, f) in fits.iter().enumerate() {
        assert!(f.p >= ALPHA, "normal {i}: cosine samples do not follow the reported pdf ({f})");
    }
    drop(s);
    finish(ctx);
}

// ---- Emitter sampling ---------------------------------------------------------------------

/// Sub-triangles per emitter edge: m^2 congruent cells of equal area.
const TRI_SPLIT: usize = 8;

/// Rec. 709 luminance, as the emitter weights use.
fn luminance(c: Vec3) -> f64 {
    0.2126 * c.x as f64 + 0.7152 * c.y as f64 + 0.0722 * c.z as f64
}

/// Emitters of different area, radiance and orientation, one that barely emits (its cells
/// are pooled), and a triangle that does not emit (no emitter).
fn lights_scene() -> Scene {
    let p = |x: f32, y: f32, z: f32| Vec3::new(x, y, z);
    let tris: Vec<([Vec3; 3], Vec3)> = vec![
        ([p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0)], Vec3::ONE),
        ([p(-2.0, 1.0, 3.0), p(1.5, 0.5, 2.0), p(0.3, 3.0, 1.0)], Vec3::new(0.2, 0.5, 0.1)),
        ([p(5.0, 5.0, 5.0), p(5.2, 5.0, 5.1), p(5.1, 5.3, 4.9)], Vec3::new(10.0, 8.0, 6.0)),
        ([p(0.0, 0.0, -1.0), p(4.0, 0.0, -1.0), p(0.0, 4.0, -1.0)], Vec3::ZERO),
        ([p(-1.0, -1.0, 2.0), p(1.0, -1.0, 2.0), p(1.0, 1.0, 2.0)], Vec3::new(0.0, 0.0, 3.0)),
        ([p(-1.0, -1.0, 2.0), p(1.0, 1.0, 2.0), p(-1.0, 1.0, 2.0)], Vec3::new(0.0, 0.0, 3.0)),
        ([p(3.0, 0.0, 0.0), p(3.0, 0.1, 0.0), p(3.0, 0.0, 0.1)], Vec3::splat(0.002)),
        ([p(0.0, -3.0, 0.0), p(0.0, -3.0, 2.5), p(2.0, -3.5, 0.5)], Vec3::new(1.0, 0.2, 0.2)),
    ];
    let mut scene = Scene { source: "test:lights".into(), ..Default::default() };
    for (i, (v, le)) in tris.iter().enumerate() {
        scene.positions.extend_from_slice(v);
        scene.triangles.push([3 * i as u32, 3 * i as u32 + 1, 3 * i as u32 + 2]);
        scene.material_ids.push(i as u32);
        scene.materials.push(Material { name: format!("m{i}"), emission: *le, ..Default::default() });
    }
    scene
}

/// Index of the equal-area sub-triangle of the barycentric point (b1, b2): the triangle is
/// cut by lines of constant b1, b2 and b0 at multiples of 1/m into m^2 congruent pieces; the
/// piece is the lattice square (floor(m b1), floor(m b2)) and its half (lower when the
/// fractional parts sum below 1).
fn sub_triangle(b1: f64, b2: f64) -> usize {
    let m = TRI_SPLIT as f64;
    let (x, y) = (b1.clamp(0.0, 1.0) * m, b2.clamp(0.0, 1.0) * m);
    let (i, j) = ((x.floor() as usize).min(TRI_SPLIT - 1), (y.floor() as usize).min(TRI_SPLIT - 1));
    let upper = (x - i as f64) + (y - j as f64) >= 1.0;
    // Lower pieces have i + j <= m - 1, upper ones i + j <= m - 2; rounding on the far edge
    // can push a point just past it, into the nearest lower piece.
    let (i, j, upper) = if i + j > TRI_SPLIT - 1 || (upper && i + j > TRI_SPLIT - 2) {
        let j = j.min(TRI_SPLIT - 1 - i.min(TRI_SPLIT - 1));
        (i.min(TRI_SPLIT - 1), j, false)
    } else {
        (i, j, upper)
    };
    2 * (i * TRI_SPLIT + j) + upper as usize
}

fn sub_triangle_valid(cell: usize) -> bool {
    let (upper, ij) = (cell % 2 == 1, cell / 2);
    let (i, j) = (ij / TRI_SPLIT, ij % TRI_SPLIT);
    if upper {
        i + j + 2 <= TRI_SPLIT
    } else {
        i + j < TRI_SPLIT
    }
}

#[test]
fn emitter_sampling_follows_power_and_area() {
    let scene = lights_scene();
    // The expected choice probabilities, from the scene (not from the table).
    let mut tris = Vec::new(); // (v0, e1, e2, probability-to-be)
    for (t, tri) in scene.triangles.iter().enumerate() {
        let le = scene.materials[scene.material_ids[t] as usize].emission;
        let [v0, v1, v2] = tri.map(|i| scene.positions[i as usize].as_dvec3());
        let power = luminance(le) * 0.5 * (v1 - v0).cross(v2 - v0).length();
        if power > 0.0 {
            tris.push((v0, v1 - v0, v2 - v0, power));
        }
    }
    let total: f64 = tris.iter().map(|t| t.3).sum();
    let prob: Vec<f64> = tris.iter().map(|t| t.3 / total).collect();
    let table = LightTable::build(&scene);
    assert_eq!(table.emitters.len(), tris.len(), "one emitter per emitting triangle");

    let ctx = gpu();
    let s = SamplingKernel::new(&ctx);
    let emitters = ctx.upload_buffer("sampling.emitters", &table.emitters).unwrap();
    let alias = ctx.upload_buffer("sampling.alias", &table.alias).unwrap();
    let count = tris.len() as u32;
    let push = abi::SamplingTestPush { mode: abi::SAMPLING_EMITTER, count: N, seed: 7, emitter_count: count, ..Default::default() };
    let out = s.run_lights(push, 2, None, Some((&emitters, &alias)));

    let cells = 2 * TRI_SPLIT * TRI_SPLIT;
    let mut chosen = vec![0u64; tris.len()];
    let mut joint = vec![0u64; tris.len() * cells];
    for pair in out.chunks_exact(2) {
        let (p, idx) = (dv(pair[0]), pair[0].w);
        let e = idx as usize;
        assert!(idx == e as f32 && e < tris.len(), "choose_emitter returned {idx}");
        let (v0, e1, e2, _) = tris[e];
        // The point lies on emitter e (the one choose_emitter picked with the same number):
        // barycentrics by least squares in the triangle's plane, then the distance off it.
        let r = p - v0;
        let (a, bb, c) = (e1.dot(e1), e1.dot(e2), e2.dot(e2));
        let det = a * c - bb * bb;
        let (r1, r2) = (r.dot(e1), r.dot(e2));
        let b1 = (c * r1 - bb * r2) / det;
        let b2 = (a * r2 - bb * r1) / det;
        let scale = e1.length().max(e2.length());
        let off = (r - b1 * e1 - b2 * e2).length();
        assert!(off < 1e-5 * (scale + v0.length()), "point {p} is {off} off emitter {e}");
        assert!(b1 > -1e-5 && b2 > -1e-5 && b1 + b2 < 1.0 + 1e-5, "point {p} outside emitter {e} (barycentrics {b1}, {b2})");
        // Its reported front normal and choice probability.
        let n = dv(pair[1]);
        assert!((n - e1.cross(e2).normalize()).length() < 1e-5, "emitter {e}: normal {n}");
        assert!((pair[1].w as f64 / prob[e] - 1.0).abs() < 1e-5, "emitter {e}: pick {} vs {}", pair[1].w, prob[e]);
        chosen[e] += 1;
        joint[e * cells + sub_triangle(b1, b2)] += 1;
    }

    let expected: Vec<f64> = prob.iter().map(|p| p * N as f64).collect();
    let choice = stats::pearson(&chosen, &expected);
    eprintln!("emitter choice: observed {chosen:?}\n  expected {:?}\n  {choice}", expected.iter().map(|e| e.round()).collect::<Vec<_>>());
    let per_cell = 1.0 / (TRI_SPLIT * TRI_SPLIT) as f64;
    let expected_joint: Vec<f64> =
        (0..joint.len()).map(|k| if sub_triangle_valid(k % cells) { prob[k / cells] * N as f64 * per_cell } else { 0.0 }).collect();
    let points = stats::pearson(&joint, &expected_joint);
    eprintln!("emitter x equal-area sub-triangle ({} pieces each): {points}, {} cells after pooling", TRI_SPLIT * TRI_SPLIT, points.cells);
    assert!(choice.p >= ALPHA, "emitters are not chosen in proportion to their power ({choice})");
    assert!(points.p >= ALPHA, "points are not uniform over the chosen emitters ({points})");
    drop((s, emitters, alias));
    finish(ctx);
}

#[test]
fn sub_triangles_tile_the_triangle_equally() {
    // A fine lattice of barycentric points hits every valid piece equally often (each piece
    // has the same area), and no invalid one: the binning itself is right.
    let cells = 2 * TRI_SPLIT * TRI_SPLIT;
    let mut hits = vec![0u64; cells];
    let k = 64 * TRI_SPLIT;
    for i in 0..k {
        for j in 0..k - i {
            // Centroids of the k^2 lattice sub-triangles.
            for (di, dj) in [(1.0 / 3.0, 1.0 / 3.0), (2.0 / 3.0, 2.0 / 3.0)] {
                let (b1, b2) = ((i as f64 + di) / k as f64, (j as f64 + dj) / k as f64);
                if b1 + b2 < 1.0 {
                    hits[sub_triangle(b1, b2)] += 1;
                }
            }
        }
    }
    let valid: Vec<u64> = (0..cells).filter(|&c| sub_triangle_valid(c)).map(|c| hits[c]).collect();
    assert_eq!(valid.len(), TRI_SPLIT * TRI_SPLIT);
    assert!(valid.iter().all(|&h| h == valid[0]), "{valid:?}");
    assert_eq!(valid.iter().sum::<u64>(), hits.iter().sum::<u64>());
}

// ---- Smooth dielectric --------------------------------------------------------------------

/// Exact Fresnel reflectance of unpolarised light at a smooth dielectric, eta = n_i / n_t
/// (pbrt-v4 eq. 9.6 with Snell's law eq. 9.2); 1 beyond the critical angle.
fn fresnel(cos_i: f64, eta: f64) -> f64 {
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if sin2_t >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    // In terms of the indices n_i = eta, n_t = 1.
    let r_par = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    let r_perp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    0.5 * (r_par * r_par + r_perp * r_perp)
}

#[test]
fn dielectric_reflects_with_fresnel_probability() {
    let ctx = gpu();
    let s = SamplingKernel::new(&ctx);
    let ior = 1.5f64;
    let n = DVec3::new(0.36, -0.48, 0.8);
    let (t, _) = frame(n);
    let mut fits = Vec::new();
    // From outside (eta = 1 / 1.5) and from inside (eta = 1.5, critical angle 41.81°).
    let cases: Vec<(f64, f64)> = [0.0, 30.0, 60.0, 80.0, 88.0]
        .iter()
        .map(|&a| (1.0 / ior, a))
        .chain([0.0, 25.0, 40.0, 41.5, 42.0, 60.0, 85.0].iter().map(|&a| (ior, a)))
        .collect();
    for (k, &(eta, deg)) in cases.iter().enumerate() {
        let theta = deg.to_radians();
        let d = (t * theta.sin() - n * theta.cos()).normalize();
        let cos_i = -d.dot(n);
        let push = abi::SamplingTestPush {
            mode: abi::SAMPLING_DIELECTRIC,
            count: N,
            seed: 100 + k as u32,
            a: d.as_vec3().extend(eta as f32),
            b: n.as_vec3().extend(0.0),
            ..Default::default()
        };
        let out = s.run(push, 1, None);
        let f = fresnel(cos_i, eta);
        let mirror = d - 2.0 * d.dot(n) * n;
        let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
        let mut reflected = 0u64;
        for v in &out {
            let w = dv(*v);
            if v.w == 0.0 {
                reflected += 1;
                assert!((w - mirror).length() < 1e-5, "eta {eta} at {deg}°: reflection {w} vs {mirror}");
            } else {
                // Snell's law in vector form (pbrt-v4 eq. 9.4): eta d + (eta cos_i - cos_t) n.
                let cos_t = (1.0 - sin2_t).sqrt();
                let refr = eta * d + (eta * cos_i - cos_t) * n;
                assert!((w - refr).length() < 1e-5, "eta {eta} at {deg}°: refraction {w} vs {refr}");
                assert!((v.w as f64 / (eta * eta) - 1.0).abs() < 1e-5, "radiance scale {} vs eta^2 {}", v.w, eta * eta);
            }
        }
        let freq = reflected as f64 / N as f64;
        if f >= 1.0 {
            eprintln!("eta {eta:.4}, {deg:4}°: total internal reflection, reflected {reflected} of {N}");
            assert_eq!(reflected, N as u64, "eta {eta} at {deg}° is beyond the critical angle: every sample must reflect");
        } else {
            let fit = stats::binomial(reflected, N as u64, f);
            eprintln!("eta {eta:.4}, {deg:4}°: F = {f:.6}, reflected {freq:.6} ({fit})");
            fits.push(fit);
        }
    }
    let all = stats::combine(&fits);
    eprintln!("all angles: {all}");
    for f in &fits {
        assert!(f.p >= ALPHA / fits.len() as f64, "reflection frequency differs from the exact Fresnel reflectance ({f})");
    }
    assert!(all.p >= ALPHA, "reflection frequencies differ from the exact Fresnel reflectance ({all})");
    drop(s);
    finish(ctx);
}

// ---- Environment sampling --------------------------------------------------------------------

/// A 16 x 8 map with a smooth gradient and one hot texel, turned 30 degrees: `env_sample`'s
/// directions fall into 2 x 2 sub-cells of each texel (halves in phi and in cos theta, equal
/// solid angle) as often as the pdf it reports says (pdf_w times the cell's solid angle), and
/// `env_lookup` reports the same pdf for the direction drawn.
#[test]
fn environment_sampling_matches_its_pdf() {
    use bidir::render::env::EnvTable;
    use bidir::scene::{Aabb, Environment};
    let (w, h) = (16u32, 8u32);
    let texels = (0..w * h)
        .map(|i| {
            let (x, y) = ((i % w) as f32, (i / w) as f32);
            let g = 0.05 + 0.1 * x + 0.3 * y;
            if (x, y) == (11.0, 2.0) {
                Vec3::new(40.0, 30.0, 20.0)
            } else {
                Vec3::new(g, 0.5 * g, 0.2)
            }
        })
        .collect();
    let mut env = Environment::from_texels("test:gradient+hot", w, h, texels);
    env.rotate_deg = 30.0;
    let bounds = Aabb { min: Vec3::splat(-1.0), max: Vec3::ONE };
    let table = EnvTable::build(&env, &bounds, 1.0).unwrap();

    let ctx = gpu();
    let s = SamplingKernel::new(&ctx);
    let genv = ctx.upload_buffer("sampling.env", std::slice::from_ref(&table.env)).unwrap();
    let texel_buf = ctx.upload_buffer("sampling.env_texels", &table.texels).unwrap();
    let alias = ctx.upload_buffer("sampling.env_alias", &table.alias).unwrap();
    let push = abi::SamplingTestPush { mode: abi::SAMPLING_ENV, count: N, seed: 11, ..Default::default() };
    let out = s.run_env(push, 2, None, None, Some([&genv, &texel_buf, &alias]));

    let rot = (env.rotate_deg as f64).to_radians();
    let mut counts = vec![0u64; (w * h * 4) as usize];
    let mut mismatched = 0u64;
    for pair in out.chunks_exact(2) {
        let d = dv(pair[0]);
        assert!((d.length() - 1.0).abs() < 1e-5, "direction {d} is not unit");
        let (pdf, looked_up) = (pair[0].w as f64, pair[1].w as f64);
        if (pdf / looked_up - 1.0).abs() > 1e-5 {
            mismatched += 1; // a direction rounded onto a neighbouring texel's edge
        }
        // Texel and sub-cell, computed here from the conventions (src/scene/env.rs).
        let phi = (PI + d.x.atan2(-d.z) + rot).rem_euclid(2.0 * PI);
        let theta = d.y.clamp(-1.0, 1.0).acos();
        let fx = phi / (2.0 * PI) * w as f64;
        let fy = theta / PI * h as f64;
        let (x, y) = ((fx as u32).min(w - 1), (fy as u32).min(h - 1));
        let sub_x = ((fx - x as f64) >= 0.5) as u32;
        let (c0, c1) = ((PI * y as f64 / h as f64).cos(), (PI * (y + 1) as f64 / h as f64).cos());
        let sub_y = ((c0 - d.y) / (c0 - c1) >= 0.5) as u32;
        counts[(((y * w + x) * 4) + sub_y * 2 + sub_x) as usize] += 1;
    }
    // Vulkan lets sin and cos err by up to 2^-11 (absolute) and acos/atan inherit it, so a
    // direction drawn within ~1e-3 radians of a texel edge may be looked up in the
    // neighbouring texel: about 1e-4 of them here on lavapipe. More would be a mapping bug.
    eprintln!("env_lookup found another texel's pdf for {mismatched} of {N} directions");
    assert!(mismatched <= N as u64 / 1000, "env_lookup disagrees with env_sample's pdf for {mismatched} of {N} directions");
    let expected: Vec<f64> = (0..counts.len())
        .map(|k| {
            let t = k / 4;
            table.texels[t].pdf_w as f64 * env.texel_solid_angle(t as u32 / w) as f64 / 4.0 * N as f64
        })
        .collect();
    let fit = stats::pearson(&counts, &expected);
    eprintln!("environment sampling, {} sub-texel cells: {fit}, {} cells after pooling", counts.len(), fit.cells);
    assert!(fit.p >= ALPHA, "environment directions do not follow their pdf ({fit})");
    // pdf_w is proportional to luminance (the solid angle cancels): the hot texel against
    // its neighbour, from the map's values.
    let hot = (2 * w + 11) as usize;
    let lum_ratio = luminance(env.texels[hot]) / luminance(env.texels[hot + 1]);
    let pdf_ratio = table.texels[hot].pdf_w as f64 / table.texels[hot + 1].pdf_w as f64;
    assert!((pdf_ratio / lum_ratio - 1.0).abs() < 1e-4, "hot texel pdf ratio {pdf_ratio} vs luminance ratio {lum_ratio}");
    drop((s, genv, texel_buf, alias));
    finish(ctx);
}

/// A sun (a 2 degree disk of uniform radiance, the alias table's extra cell) inside one
/// sub-texel cell of a gradient map: the directions fall into the sub-texel cells, with the
/// sun's cell split into inside and outside the disk, as often as the reported pdf says.
#[test]
fn environment_sampling_with_a_sun_matches_its_pdf() {
    use bidir::render::env::EnvTable;
    use bidir::scene::{Aabb, Environment, Sun};
    let (w, h) = (16u32, 8u32);
    let texels = (0..w * h).map(|i| Vec3::new(0.1 + 0.05 * (i % w) as f32, 0.2, 0.1 + 0.1 * (i / w) as f32)).collect();
    let mut env = Environment::from_texels("test:gradient+sun", w, h, texels);
    // The centre of sub-cell (0, 0) of texel (5, 3): phi in the left half, cos theta in the
    // upper half of the texel's range.
    let (c0, c1) = ((PI * 3.0 / 8.0).cos(), (PI * 4.0 / 8.0).cos());
    let cos_c = c0 - 0.25 * (c0 - c1);
    let phi = 5.25 * 2.0 * PI / 16.0 - PI;
    let sin_c = (1.0 - cos_c * cos_c).sqrt();
    let dir = Vec3::new((sin_c * phi.sin()) as f32, cos_c as f32, (-sin_c * phi.cos()) as f32);
    let sun = Sun { direction: dir, irradiance: Vec3::new(3.0, 2.5, 2.0), angle_deg: 2.0 };
    env.sun = Some(sun);
    let table = EnvTable::build(&env, &Aabb { min: Vec3::splat(-1.0), max: Vec3::ONE }, 1.0).unwrap();
    assert_eq!(table.alias.len() as u32, w * h + 1);

    let ctx = gpu();
    let s = SamplingKernel::new(&ctx);
    let genv = ctx.upload_buffer("sampling.env", std::slice::from_ref(&table.env)).unwrap();
    let texel_buf = ctx.upload_buffer("sampling.env_texels", &table.texels).unwrap();
    let alias = ctx.upload_buffer("sampling.env_alias", &table.alias).unwrap();
    let push = abi::SamplingTestPush { mode: abi::SAMPLING_ENV, count: N, seed: 13, ..Default::default() };
    let out = s.run_env(push, 2, None, None, Some([&genv, &texel_buf, &alias]));

    let cos_max = sun.cos_max() as f64;
    let sun_cell = ((3 * w + 5) * 4) as usize;
    let inside = (w * h * 4) as usize; // the extra cell: inside the sun's disk
    let mut counts = vec![0u64; inside + 1];
    let mut mismatched = 0u64;
    for pair in out.chunks_exact(2) {
        let d = dv(pair[0]);
        if (pair[0].w as f64 / pair[1].w as f64 - 1.0).abs() > 1e-5 {
            mismatched += 1;
        }
        if d.dot(dir.as_dvec3()) >= cos_max {
            counts[inside] += 1;
            continue;
        }
        let phi = (PI + d.x.atan2(-d.z)).rem_euclid(2.0 * PI);
        let fx = phi / (2.0 * PI) * w as f64;
        let fy = d.y.clamp(-1.0, 1.0).acos() / PI * h as f64;
        let (x, y) = ((fx as u32).min(w - 1), (fy as u32).min(h - 1));
        let (a, b) = ((PI * y as f64 / h as f64).cos(), (PI * (y + 1) as f64 / h as f64).cos());
        let sub = ((fx - x as f64) >= 0.5) as u32 + 2 * (((a - d.y) / (a - b)) >= 0.5) as u32;
        counts[((y * w + x) * 4 + sub) as usize] += 1;
    }
    eprintln!("env_lookup found another texel's pdf for {mismatched} of {N} directions");
    assert!(mismatched <= N as u64 / 1000);
    let omega_sun = 2.0 * PI * (1.0 - cos_max);
    let mut expected: Vec<f64> =
        (0..inside).map(|k| table.texels[k / 4].pdf_w as f64 * env.texel_solid_angle((k / 4) as u32 / w) as f64 / 4.0 * N as f64).collect();
    let texel_pdf = table.texels[sun_cell / 4].pdf_w as f64;
    expected[sun_cell] -= texel_pdf * omega_sun * N as f64;
    expected.push((texel_pdf + table.env.sun_pdf_w as f64) * omega_sun * N as f64);
    let fit = stats::pearson(&counts, &expected);
    eprintln!("environment + sun sampling: {fit}; in the disk {} of {N} (expected {:.0})", counts[inside], expected[inside]);
    assert!(fit.p >= ALPHA, "environment + sun directions do not follow their pdf ({fit})");
    drop((s, genv, texel_buf, alias));
    finish(ctx);
}

/// rng.glsl's numbers on the CPU, operation for operation: the PCG hash, Burley's (2020)
/// nested uniform scramble and per-group index shuffle, Sobol' points by their matrix product
/// (`bidir::gpu::sobol::sobol`, not the kernels' shortcuts), the hash chain past the Sobol'
/// dimensions.
mod rng_twin {
    use bidir::gpu::sobol::sobol;

    pub fn pcg_hash(v: u32) -> u32 {
        let state = v.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
        let word = ((state >> ((state >> 28) + 4)) ^ state).wrapping_mul(277_803_737);
        (word >> 22) ^ word
    }

    fn laine_karras(mut x: u32, seed: u32) -> u32 {
        x = x.wrapping_add(seed);
        for m in [0x6c50_b47c_u32, 0xb82f_1e52, 0xc7af_e638, 0x8d22_f6e6] {
            x ^= x.wrapping_mul(m);
        }
        x
    }

    fn scramble(x: u32, seed: u32) -> u32 {
        laine_karras(x.reverse_bits(), seed).reverse_bits()
    }

    /// The first `n` numbers of (pixel, sample) under `sobol_dims` (SPEC_SAMPLER's value):
    /// the path reaches its next vertex before number i where bit i of `vertex_starts` is set
    /// (from its second, SOBOL_FIRST_VERTEX's Sobol' dimensions end), then a group of four
    /// dimensions starts where that of `group_starts` is (the next dimension rounded up to a
    /// multiple of four, but not past the Sobol' dimensions).
    pub fn numbers(pixel: u32, sample: u32, seed: u32, sobol_dims: u32, vertex_starts: u32, group_starts: u32, n: usize) -> Vec<u32> {
        let s = pcg_hash(pixel ^ pcg_hash(seed));
        let mut state = if sobol_dims > 0 { s } else { pcg_hash(s ^ pcg_hash(sample)) };
        let mut out = Vec::with_capacity(n);
        let mut dim = 0u32;
        let mut vertex = 0;
        for i in 0..n as u32 {
            if vertex_starts & (1 << i) != 0 {
                vertex += 1;
                if sobol_dims == bidir::gpu::abi::SOBOL_FIRST_VERTEX && vertex >= 2 && dim < sobol_dims {
                    dim = sobol_dims;
                }
            }
            if group_starts & (1 << i) != 0 && sobol_dims > 0 && dim < sobol_dims {
                dim = dim.next_multiple_of(4).min(sobol_dims);
            }
            // As rng.glsl, the dimension stops counting one past the Sobol' dimensions.
            let d = dim;
            if sobol_dims > 0 && d <= sobol_dims {
                dim += 1;
            }
            if sobol_dims > 0 && d < sobol_dims {
                let group_seed = pcg_hash(state ^ pcg_hash(d / 4));
                let shuffled = scramble(sample, group_seed);
                let k = d % 4;
                out.push(scramble(sobol(shuffled, k as usize), pcg_hash(group_seed ^ (k + 1))));
                continue;
            }
            if sobol_dims > 0 && d == sobol_dims {
                state = pcg_hash(state ^ pcg_hash(sample ^ 0x5bd1_e995));
            }
            state = pcg_hash(state);
            out.push(state);
        }
        out
    }
}

/// index_below (rng.glsl), which picks an emitter, an environment cell, a punctual light and a
/// light vertex: the index is the high word of u n for every u and n (so each index below n
/// takes floor or ceil of 2^32 / n of the u's, every one reachable however large n), and what
/// is left of u within the index is the low word over 2^32 to 24 bits. The inputs: the first
/// and last u of indices spread over [0, n) for n past 2^24 (an 8192 x 4096 map with its sun,
/// a 4000 x 1999 one, half of 2^32) and small n, where an index from a float in [0, 1), with
/// its 24 bits, misses half the cells of the first map and gives the second's cells one to
/// three values each; and random pairs.
#[test]
fn every_index_below_n_is_drawn_in_proportion() {
    let ctx = gpu();
    {
        let s = SamplingKernel::new(&ctx);
        let mut pcg = common::Pcg::new(29);
        let mut pairs: Vec<(u32, u32)> = Vec::new();
        for n in [8192 * 4096 + 1, 4000 * 1999, 1 << 31, (1 << 24) + 3, 1000, 3, 1] {
            for j in 0..64u64 {
                let spread = (j * (n as u64 - 1) / 63) as u32;
                let k = if j % 2 == 1 { (spread | 1).min(n - 1) } else { spread };
                // The first u of index k, ceil(k 2^32 / n), and the last, one before k + 1's.
                let first = ((k as u64) << 32).div_ceil(n as u64);
                let last = (((k as u64 + 1) << 32).div_ceil(n as u64) - 1).min(u32::MAX as u64);
                pairs.push((first as u32, n));
                pairs.push((last as u32, n));
            }
            pairs.push((u32::MAX, n));
            pairs.push((0, n));
        }
        for _ in 0..2048 {
            pairs.push((pcg.next_u32(), pcg.next_u32().max(1)));
        }
        let input: Vec<Vec4> = pairs.iter().map(|&(u, n)| Vec4::new(f32::from_bits(u), f32::from_bits(n), 0.0, 0.0)).collect();
        let input = ctx.upload_buffer("sampling.index_pairs", &input).unwrap();
        let push = abi::SamplingTestPush { mode: abi::SAMPLING_INDEX, count: pairs.len() as u32, seed: 1, ..Default::default() };
        let out = s.run(push, 1, Some(&input));
        let mut odd_cells = 0;
        for (&(u, n), v) in pairs.iter().zip(&out) {
            let product = u as u64 * n as u64;
            let (index, rest) = ((product >> 32) as u32, ((product as u32) >> 8) as f32 / 16_777_216.0);
            assert!(index < n, "u {u:#x}, n {n}: index {index} past n");
            assert_eq!(v.x.to_bits(), index, "u {u:#x}, n {n}: index_below gives {}, the high word of u n is {index}", v.x.to_bits());
            assert_eq!(v.y, rest, "u {u:#x}, n {n}: what is left of u is {}, not {rest}", v.y);
            odd_cells += (n == 8192 * 4096 + 1 && index % 2 == 1) as u32;
        }
        // The inputs reach odd cells of the largest map, which a 24-bit float never does.
        assert!(odd_cells >= 32, "only {odd_cells} odd cells of the 8192 x 4096 map among the inputs");
    }
    finish(ctx);
}

/// The cursor of glsl/common/ballot.glsl, by which the resampled connections' lanes find the
/// lanes that read their group's candidates (connect_resampled): the lanes of a 128-bit ballot
/// from a start lane, taken lowest first until none is left, on ballots of every density, with bits at the words'
/// edges and starts on every lane (NVIDIA's 32-lane subgroups take a one-word form instead;
/// the devices here have no wider subgroups, so this is where the wide form is tested).
#[test]
fn ballot_cursor_takes_the_lanes_from_a_start_in_order() {
    let ctx = gpu();
    {
        let s = SamplingKernel::new(&ctx);
        let mut pcg = common::Pcg::new(31);
        let mut ballots: Vec<[u32; 4]> =
            vec![[1, 0, 0, 0], [0, 0, 0, 1 << 31], [u32::MAX; 4], [0x8000_0001, 1, 0x8000_0000, 0], [0, 0xffff_0000, 0, 0xffff], [0; 4]];
        for density in [1u32, 2, 8, 16, 31] {
            for _ in 0..256 {
                // Each bit set with probability density / 32.
                let mut b = [0u32; 4];
                for w in b.iter_mut() {
                    for bit in 0..32 {
                        if pcg.below(32) < density {
                            *w |= 1 << bit;
                        }
                    }
                }
                ballots.push(b);
            }
        }
        let input: Vec<Vec4> = ballots
            .iter()
            .map(|b| Vec4::new(f32::from_bits(b[0]), f32::from_bits(b[1]), f32::from_bits(b[2]), f32::from_bits(b[3])))
            .collect();
        let input = ctx.upload_buffer("sampling.ballots", &input).unwrap();
        let push = abi::SamplingTestPush { mode: abi::SAMPLING_BALLOT_CURSOR, count: ballots.len() as u32, seed: 1, ..Default::default() };
        let out = s.run(push, 1, Some(&input));
        let mut starts = std::collections::HashSet::new();
        for (i, (b, v)) in ballots.iter().zip(&out).enumerate() {
            let start = (37 * i as u32) % 129;
            let lanes: Vec<u32> = (start..128u32).filter(|&l| b[(l / 32) as usize] & (1 << (l % 32)) != 0).collect();
            // Every lane taken in order until none is left, folded as the shader folds them.
            let order = lanes.iter().fold(0u32, |h, &l| h.wrapping_mul(31).wrapping_add(l + 1));
            let want = [lanes.first().copied().unwrap_or(128), lanes.get(1).copied().unwrap_or(128), lanes.len() as u32, order];
            let got = [v.x.to_bits(), v.y.to_bits(), v.z.to_bits(), v.w.to_bits()];
            assert_eq!(got, want, "ballot {b:08x?} from lane {start}: (first, second, taken, order)");
            starts.insert(start);
        }
        assert_eq!(starts.len(), 129, "every start lane, 0 to 128");
    }
    finish(ctx);
}

/// The 8-byte form in which BDPT's wavefront camera pass keeps a shadow ray's contribution
/// (glsl/common/packed_contrib.glsl): each channel the nearest float with 13 (red, green) or
/// 14 (blue) bits of mantissa, so within 2^-14 (2^-15) of the value and as often above as below
/// it; a rounded value rounds to itself; the packed form holds the rounded value exactly; zero
/// stays zero, a negative zero unpacks as zero; a negative, NaN or infinite channel unpacks as a NaN, which the pass counts as a
/// bad contribution, and the megakernels' rounding (contrib_round) keeps its sign, NaN or
/// infinity. Over channels from 1e-30 to 1e30.
#[test]
fn shadow_contributions_pack_to_the_nearest_with_14_bits() {
    let ctx = gpu();
    {
        let s = SamplingKernel::new(&ctx);
        let mut pcg = common::Pcg::new(37);
        let mut input: Vec<Vec4> = Vec::new();
        for _ in 0..8192 {
            let mut v = [0.0f32; 3];
            for x in v.iter_mut() {
                let e = pcg.below(60) as i32 - 30;
                *x = (1.0 + pcg.below(1 << 23) as f32 / (1 << 23) as f32) * 10f32.powi(e);
            }
            input.push(Vec4::new(v[0], v[1], v[2], 0.0));
        }
        input.push(Vec4::ZERO);
        // Values already on the grid, halfway between two of its points, and at its ends.
        input.push(Vec4::new(f32::from_bits(0x3f80_0400), f32::from_bits(0x3f80_0200), f32::from_bits(0x3f80_0100), 0.0));
        input.push(Vec4::new(f32::from_bits(0x3f80_01ff), f32::from_bits(0x3f80_05ff), f32::from_bits(0x3f80_00ff), 0.0));
        input.push(Vec4::new(f32::MIN_POSITIVE, 1.0e-45, f32::MAX / 2.0, 0.0));
        let good = input.len();
        // Negative zeros: +0 packed (the sign bit is not packed and must not spill into the
        // next channel).
        input.push(Vec4::new(-0.0, 1.0, -0.0, 0.0));
        input.push(Vec4::new(1.0, -0.0, 3.0, 0.0));
        let zeros = input.len();
        // (A NaN whose mantissa is all ones would round up into the next exponent: kept.)
        for bad in [
            Vec4::new(-1.5, 1.0, 1.0, 0.0),
            Vec4::new(1.0, f32::NAN, 1.0, 0.0),
            Vec4::new(1.0, 1.0, f32::INFINITY, 0.0),
            Vec4::new(f32::from_bits(u32::MAX), 1.0, 1.0, 0.0),
        ] {
            input.push(bad);
        }
        let buffer = ctx.upload_buffer("sampling.contribs", &input).unwrap();
        let push = abi::SamplingTestPush { mode: abi::SAMPLING_CONTRIB_PACK, count: input.len() as u32, seed: 1, ..Default::default() };
        let out = s.run(push, 3, Some(&buffer));
        // The nearest float with `keep` bits of mantissa (ties away from zero), by the bits.
        let nearest = |x: f32, keep: u32| {
            let drop = 23 - keep;
            f32::from_bits(((x.to_bits() + (1 << (drop - 1))) >> drop) << drop)
        };
        let (mut up, mut down, mut sum) = (0u32, 0u32, 0.0f64);
        for (i, c) in input[..good].iter().enumerate() {
            let (r, unpacked, words) = (out[3 * i], out[3 * i + 1], out[3 * i + 2]);
            for k in 0..3 {
                assert_eq!(
                    unpacked[k].to_bits(),
                    r[k].to_bits(),
                    "{c:?} channel {k}: the packed form holds {}, rounding gives {}",
                    unpacked[k],
                    r[k]
                );
            }
            for (k, keep) in [13u32, 13, 14].into_iter().enumerate() {
                let (x, y) = (c[k], r[k]);
                assert_eq!(
                    y.to_bits(),
                    nearest(x, keep).to_bits(),
                    "{c:?} channel {k}: rounded to {y:e}, the nearest with {keep} bits is {:e}",
                    nearest(x, keep)
                );
                if x > 0.0 {
                    let rel = (y as f64 - x as f64) / x as f64;
                    assert!(
                        rel.abs() <= 0.5f64.powi(keep as i32 + 1) * (1.0 + 1e-6) || x < f32::MIN_POSITIVE,
                        "{c:?} channel {k}: relative error {rel:e}"
                    );
                    if x >= f32::MIN_POSITIVE && y != x {
                        sum += rel;
                        if y > x {
                            up += 1
                        } else {
                            down += 1
                        }
                    }
                }
            }
            assert_eq!([words.z.to_bits(), words.w.to_bits()], [r.x.to_bits(), r.y.to_bits()], "{c:?}: a rounded value rounds to itself");
        }
        assert_eq!(out[3 * (good - 4) + 1].truncate(), Vec3::ZERO, "zero packs as zero");
        let n = up + down;
        eprintln!("{n} channels rounded: {up} up, {down} down, mean relative error {:e}", sum / n as f64);
        // As often up as down (binomial, p = 1/2: 5 standard deviations), and no drift in the
        // mean beyond 5 standard errors of a uniform error of half a unit (2^-14 / sqrt(3)).
        assert!((up as f64 - n as f64 / 2.0).abs() < 5.0 * (n as f64 / 4.0).sqrt(), "{up} rounded up, {down} down");
        assert!(
            (sum / n as f64).abs() < 5.0 * 0.5f64.powi(14) / 3f64.sqrt() / (n as f64).sqrt(),
            "mean relative error {:e}",
            sum / n as f64
        );
        for (i, c) in input.iter().enumerate().take(zeros).skip(good) {
            let (r, unpacked) = (out[3 * i], out[3 * i + 1]);
            assert_eq!(r.truncate().to_array().map(f32::to_bits), c.truncate().to_array().map(f32::to_bits), "{c:?}: rounding keeps it");
            assert_eq!(
                unpacked.truncate().to_array().map(f32::to_bits),
                c.truncate().abs().to_array().map(f32::to_bits),
                "{c:?} unpacks as {unpacked:?}"
            );
        }
        for (i, c) in input.iter().enumerate().skip(zeros) {
            let (r, unpacked) = (out[3 * i], out[3 * i + 1]);
            assert!(unpacked.x.is_nan(), "{c:?} unpacks as {unpacked:?}, not as a NaN (a bad contribution)");
            for k in 0..3 {
                let keeps = if c[k].is_nan() { r[k].is_nan() } else { r[k].to_bits() == c[k].to_bits() || (c[k] < 0.0 && r[k] == c[k]) };
                assert!(keeps, "{c:?} channel {k}: contrib_round gives {}", r[k]);
            }
        }
    }
    finish(ctx);
}

/// The arithmetic the watertight triangle test's CPU twin (src/bvh/intersect.rs) assumes of the
/// device: under `precise`, every fma() rounds one way, once or twice (`device_fma`, which the
/// hit-for-hit tests in tests/traversal.rs ask), and a b + c is never contracted into one.
#[test]
fn precise_fma_rounds_one_way_and_a_product_plus_a_sum_twice() {
    let ctx = gpu();
    let fma = common::sampling_kernel::device_fma(&ctx);
    eprintln!("the device's precise fma(): {fma:?}");
    finish(ctx);
}

/// Why each sampling decision starts a group (rng_start_group) and draws its 2D numbers
/// first or after one other: over a pixel's first 4^m samples (m = 2 to 5), a group's
/// dimensions 0 and 1, and 1 and 2, put one point in each of the 2^m x 2^m cells of the unit
/// square for each of 16 pixels (each pair a (0, 2)-sequence, as Owen scrambling keeps it), while
/// dimensions 2 and 3 of a group, or two dimensions in different groups, leave cells empty at
/// some m. Computed by rng.glsl's CPU twin, which the test below holds to the kernels bit for
/// bit.
#[test]
fn a_group_s_leading_pairs_are_stratified_in_2d() {
    // With a group started before number 2, numbers 2 to 5 are dimensions 4 to 7 (a group)
    // and number 6 is dimension 8 (the next).
    let stratified = |pixel: u32, pair: (usize, usize)| {
        (2..=5u32).all(|m| {
            let mut hit = vec![0u32; 1 << (2 * m)];
            for sample in 0..1u32 << (2 * m) {
                let n = rng_twin::numbers(pixel, sample, 3, 12, 0, 1 << 2, 8);
                hit[((n[pair.0] >> (32 - m)) << m | n[pair.1] >> (32 - m)) as usize] += 1;
            }
            hit.iter().all(|&h| h == 1)
        })
    };
    for pixel in 0..16 {
        for (pair, dims) in [((2, 3), "0 and 1"), ((3, 4), "1 and 2")] {
            assert!(stratified(pixel, pair), "pixel {pixel}: a group's dimensions {dims} leave a cell empty");
        }
        for (pair, dims) in [((4, 5), "2 and 3 of a group"), ((5, 6), "7 and 8 (two groups)")] {
            assert!(!stratified(pixel, pair), "pixel {pixel}: dimensions {dims} are stratified in 2D at every m tried");
        }
    }
}

/// The kernels' random numbers are rng.glsl's definition bit for bit (its Sobol' points
/// computed by shortcuts, each against the matrix product), path vertices and groups of
/// dimensions started among them: independent, two and ten Sobol' dimensions (a group start
/// cut short where the hash chain begins), the default (Sobol' for the first vertex) and
/// Sobol' everywhere, over sample indices with every bit in use.
#[test]
fn kernel_random_numbers_equal_their_cpu_twin_bit_for_bit() {
    let ctx = gpu();
    {
        let count = 4096u32;
        let mut pcg = common::Pcg::new(13);
        let samples: Vec<u32> = (0..count).map(|i| if i < 64 { i } else { pcg.next_u32() }).collect();
        let input: Vec<Vec4> = samples.iter().map(|&s| Vec4::new(f32::from_bits(s), 0.0, 0.0, 0.0)).collect();
        let input = ctx.upload_buffer("sampling.rng_samples", &input).unwrap();
        for sobol_dims in [abi::SAMPLER_INDEPENDENT, 2, 10, abi::SOBOL_FIRST_VERTEX, abi::SOBOL_ALL_DIMS] {
            let spec = bidir::vk::Spec { id: abi::SPEC_SAMPLER, value: sobol_dims };
            let k = SamplingKernel::with_specs(&ctx, &[spec]);
            let push = abi::SamplingTestPush { mode: abi::SAMPLING_RNG, count, seed: 7, ..Default::default() };
            let out = k.run(push, 4, Some(&input));
            let mut wrong = 0;
            for i in 0..count {
                let want = rng_twin::numbers(
                    i / 8,
                    samples[i as usize],
                    7,
                    sobol_dims,
                    abi::SAMPLING_RNG_VERTEX_STARTS,
                    abi::SAMPLING_RNG_GROUP_STARTS,
                    16,
                );
                let got: Vec<u32> = out[4 * i as usize..4 * i as usize + 4].iter().flat_map(|v| v.to_array().map(f32::to_bits)).collect();
                if got != want {
                    if wrong < 3 {
                        eprintln!("sampler {sobol_dims}: pixel {} sample {:#x}: GPU {got:x?}, CPU {want:x?}", i / 8, samples[i as usize]);
                    }
                    wrong += 1;
                }
            }
            assert_eq!(
                wrong, 0,
                "sampler with {sobol_dims} Sobol' dimensions: {wrong} of {count} invocations' numbers differ from rng.glsl's CPU twin"
            );
        }
    }
    finish(ctx);
}
