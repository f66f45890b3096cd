//! The Cornell box against the converged reference (`../shared/references/cornell-box`):
//! every integrator and join at 256 spp must match the mean of each channel within 1 % and
//! every 32x32 block mean within 4 %; integrators must agree with each other the same way.
//! Skipped with a message when the reference is absent.

mod common;

use bidir::film::{metrics, read_exr, RgbImage};
use bidir::render::{Integrator, Join, RenderSettings, Renderer};
use bidir::scene::Scene;
use common::{finish, gpu};
use std::path::Path;
use std::sync::OnceLock;

const REFERENCE: &str = "../shared/references/cornell-box/reference.exr";
const SPP: u32 = 256;
/// Plain path tracing finds the light only by chance: at 256 spp its dark-corner blocks
/// scatter by about +-3 % between seeds and at 1024 spp its worst block was still 3.3 % off
/// (H100), too close to the 4 % bound once compared with another noisy image (pt-nee).
const PT_SPP: u32 = 2048;

fn reference() -> Option<RgbImage> {
    if !Path::new(REFERENCE).exists() {
        eprintln!("skipping: {REFERENCE} is absent");
        return None;
    }
    Some(read_exr(Path::new(REFERENCE)).expect("reference.exr reads"))
}

fn render(integrator: Integrator) -> RgbImage {
    render_spp(integrator, SPP)
}

fn render_spp(integrator: Integrator, spp: u32) -> RgbImage {
    let ctx = gpu();
    let scene = Scene::builtin_cornell_box();
    let mut r = Renderer::new(&ctx, &scene, &scene.cameras[0], RenderSettings::new(integrator)).unwrap();
    r.render_spp(spp, |_| {}).unwrap();
    let img = r.image().unwrap();
    assert_eq!(r.nan_samples().unwrap(), 0, "{}: NaN/Inf samples", integrator.name());
    drop(r);
    finish(ctx);
    img
}

/// pt-nee is the yardstick the others are compared with; rendered once per test binary.
fn pt_nee() -> &'static RgbImage {
    static IMG: OnceLock<RgbImage> = OnceLock::new();
    IMG.get_or_init(|| render(Integrator::PtNee))
}

/// Mean per channel within 1 %, and every 32x32 block's mean (over its pixels and channels)
/// within 4 %. Blocks are judged on all channels together: a single near-black channel of a
/// dark block (blue on the red wall, ~0.002) is dominated by the rare light-hitting paths of
/// plain path tracing, and moved by +-5 % between seeds even at 1024 spp — that measures noise,
/// not bias.
fn assert_close(what: &str, a: &RgbImage, b: &RgbImage) {
    let ratio = metrics::mean_ratio(a, b);
    eprintln!("{what}: RMSE {:.5}, mean ratio {:.4} {:.4} {:.4}", metrics::rmse(a, b), ratio[0], ratio[1], ratio[2]);
    for (c, r) in ratio.iter().enumerate() {
        assert!((r - 1.0).abs() < 0.01, "{what}: channel {c} mean ratio {r:.4} is off by more than 1 %");
    }
    let (ba, bb) = (metrics::block_means(a, 32), metrics::block_means(b, 32));
    let mut worst = 0.0f64;
    for ((x, y, ma), (_, _, mb)) in ba.iter().zip(&bb) {
        let (sa, sb) = (ma.iter().sum::<f64>(), mb.iter().sum::<f64>());
        let rel = (sa / sb - 1.0).abs();
        worst = worst.max(rel);
        assert!(rel < 0.04, "{what}: block ({x}, {y}): {sa:.5} vs {sb:.5} ({:+.2} %)", 100.0 * (sa / sb - 1.0));
    }
    eprintln!("{what}: worst 32x32 block {:.2} %", 100.0 * worst);
}

#[test]
fn pt_and_pt_nee_match_reference_and_each_other() {
    let Some(reference) = reference() else { return };
    let pt = render_spp(Integrator::Pt, PT_SPP);
    assert_close("pt vs reference", &pt, &reference);
    assert_close("pt-nee vs reference", pt_nee(), &reference);
    assert_close("pt vs pt-nee", &pt, pt_nee());
}

/// BDPT with `join` against the reference and against pt-nee.
fn check_bdpt(join: Join) {
    let Some(reference) = reference() else { return };
    let img = render(Integrator::Bdpt(join));
    let name = Integrator::Bdpt(join).name();
    assert_close(&format!("{name} vs reference"), &img, &reference);
    assert_close(&format!("{name} vs pt-nee"), &img, pt_nee());
}

#[test]
fn bdpt_full_join_matches_reference_and_pt_nee() {
    check_bdpt(Join::Full);
}

#[test]
fn bdpt_k_step_join_matches_reference() {
    check_bdpt(Join::K(4));
}

#[test]
fn bdpt_single_join_matches_reference() {
    check_bdpt(Join::K(1));
}

#[test]
fn bdpt_light_vertex_cache_matches_reference() {
    check_bdpt(Join::Lvc(0));
}
