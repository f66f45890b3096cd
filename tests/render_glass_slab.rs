//! Dielectric sanity: a camera with a narrow field of view looks, at normal incidence,
//! through a thick glass slab (a closed box of 12 triangles, IOR 1.5) at a large one-sided
//! emitter of radiance Le that absorbs everything (albedo 0); nothing else is in the scene.
//! With the normal-incidence reflectance R = ((n - 1) / (n + 1))^2, light crosses the two
//! faces after any even number of internal reflections (an incoherent sum):
//!     L = Le (1 - R)^2 Σ_k R^2k = Le (1 - R)^2 / (1 - R^2) = Le (1 - R) / (1 + R),
//! 0.923077 Le for n = 1.5, where a renderer that drops the internal reflections gives
//! (1 - R)^2 Le = 0.9216 Le (0.16 % less). Radiance picks up eta^2 entering the glass and
//! gives it back leaving, so the emitter's radiance is seen unscaled apart from R.
//! Every integrator, with unbounded depth, must match within 4 standard errors of its image
//! mean, a band that must itself be at most 0.5 % wide.

mod common;

use bidir::render::{Integrator, Join, RenderSettings, Renderer};
use bidir::scene::{Camera, Material, Scene};
use common::{finish, gpu};
use glam::Vec3;
use std::time::Instant;

const IOR: f32 = 1.5;
const LE: f32 = 2.0;

/// Appends the quad (c, c + e1, c + e1 + e2, c + e2), front (CCW) side toward `front`.
fn quad(s: &mut Scene, c: Vec3, e1: Vec3, e2: Vec3, front: Vec3, material: u32) {
    let (e1, e2) = if e1.cross(e2).dot(front) > 0.0 { (e1, e2) } else { (e2, e1) };
    let b = s.positions.len() as u32;
    s.positions.extend([c, c + e1, c + e1 + e2, c + e2]);
    s.triangles.extend([[b, b + 1, b + 2], [b, b + 2, b + 3]]);
    s.material_ids.extend([material; 2]);
}

/// The slab [-4, 4] x [-4, 4] x [-1, 1] (faces outward), the emitter z = -3 facing +z, and a
/// camera at z = 10 looking down -z with a 4° field of view: every primary ray meets the
/// slab's front and back faces within 0.5 of the axis and the emitter far from its edges.
/// Those rays are up to 2.8° off normal, which changes R by less than 1e-7 (negligible), so
/// every pixel is an estimate of the same value.
fn slab_scene(size: u32) -> Scene {
    let mut s = Scene { source: "test:glass-slab".into(), ..Default::default() };
    s.materials.push(Material { name: "glass".into(), albedo: Vec3::ZERO, refractivity: 1.0, ior: IOR, ..Default::default() });
    s.materials.push(Material { name: "emitter".into(), albedo: Vec3::ZERO, emission: Vec3::splat(LE), ..Default::default() });
    let (lo, hi) = (Vec3::new(-4.0, -4.0, -1.0), Vec3::new(4.0, 4.0, 1.0));
    let d = hi - lo;
    for axis in 0..3 {
        let (u, v) = (Vec3::AXES[(axis + 1) % 3] * d[(axis + 1) % 3], Vec3::AXES[(axis + 2) % 3] * d[(axis + 2) % 3]);
        let n = Vec3::AXES[axis];
        quad(&mut s, lo, u, v, -n, 0);
        quad(&mut s, lo + n * d[axis], u, v, n, 0);
    }
    assert_eq!(s.triangles.len(), 12);
    quad(&mut s, Vec3::new(-30.0, -30.0, -3.0), Vec3::X * 60.0, Vec3::Y * 60.0, Vec3::Z, 1);
    s.cameras.push(Camera {
        name: "slab".into(),
        eye: Vec3::new(0.0, 0.0, 10.0),
        target: Vec3::ZERO,
        up: Vec3::Y,
        fov_y_deg: 4.0,
        width: size,
        height: size,
    });
    s
}

/// Renders and returns (mean / Le, relative standard error of that mean).
fn render(integrator: Integrator, size: u32, spp: u32) -> (f64, f64) {
    let ctx = gpu();
    let scene = slab_scene(size);
    let t = Instant::now();
    let mut r = Renderer::new(&ctx, &scene, &scene.cameras[0], RenderSettings::new(integrator)).unwrap();
    r.render_spp(spp, |_| {}).unwrap();
    let img = r.image().unwrap();
    assert_eq!(r.nan_samples().unwrap(), 0);
    // Pixel values (channels are equal: white light, colourless glass); pixels are
    // independent estimates, so the standard error of their mean is sd / sqrt(pixels).
    let px: Vec<f64> = img.data.chunks_exact(3).map(|c| (c[0] as f64 + c[1] as f64 + c[2] as f64) / (3.0 * LE as f64)).collect();
    let n = px.len() as f64;
    let mean = px.iter().sum::<f64>() / n;
    let var = px.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0);
    let se = (var / n).sqrt() / mean;
    eprintln!(
        "{}: {size}x{size}, {spp} spp in {:.1} s: mean {mean:.6} Le, relative SE {:.4} %",
        integrator.name(),
        t.elapsed().as_secs_f64(),
        100.0 * se
    );
    drop(r);
    finish(ctx);
    (mean, se)
}

fn check(integrator: Integrator, size: u32, spp: u32, must_resolve: bool) {
    let r = ((IOR as f64 - 1.0) / (IOR as f64 + 1.0)).powi(2);
    let expect = (1.0 - r) / (1.0 + r);
    let no_internal = (1.0 - r) * (1.0 - r);
    let (mean, se) = render(integrator, size, spp);
    let tol = 4.0 * se;
    let err = mean / expect - 1.0;
    let gap = 1.0 - no_internal / expect;
    eprintln!(
        "{}: expected {expect:.6} ({:+.3} %), tolerance 4 SE = {:.3} %; without internal reflections {no_internal:.6} ({}resolved: gap {:.3} %)",
        integrator.name(),
        100.0 * err,
        100.0 * tol,
        if tol < gap { "" } else { "not " },
        100.0 * gap
    );
    assert!(tol <= 0.005, "{}: too noisy to test 0.5 % (4 SE = {:.3} %): raise spp", integrator.name(), 100.0 * tol);
    if must_resolve {
        assert!(
            tol < gap,
            "{}: 4 SE ({:.3} %) does not resolve the internal reflections ({:.3} %): raise spp",
            integrator.name(),
            100.0 * tol,
            100.0 * gap
        );
    }
    assert!(
        err.abs() <= tol,
        "{}: slab transmission {mean:.6} vs {expect:.6} ({:+.3} %, 4 SE {:.3} %)",
        integrator.name(),
        100.0 * err,
        100.0 * tol
    );
}

#[test]
fn glass_slab_pt() {
    check(Integrator::Pt, 64, 256, true);
}

#[test]
fn glass_slab_pt_nee() {
    check(Integrator::PtNee, 64, 256, true);
}

#[test]
fn glass_slab_bdpt_full() {
    check(Integrator::Bdpt(Join::Full), 64, 256, true);
}

#[test]
fn glass_slab_bdpt_single() {
    check(Integrator::Bdpt(Join::K(1)), 64, 256, true);
}
