//! Settings that cannot reach the wrong kernel: combinations the integrators cannot honour are
//! clear errors from `Renderer::new`, not quietly wrong images.

mod common;

use bidir::bvh::BvhLayout;
use bidir::render::{Integrator, Join, RenderError, RenderSettings, Renderer};
use bidir::scene::Scene;
use common::{finish, gpu};

/// The integrator kernels include only the binary traversal of 64-byte nodes: a compressed
/// wide or quantised binary BVH would have its nodes read as those.
#[test]
fn wide_bvh_layout_is_refused_by_every_integrator() {
    let ctx = gpu();
    let scene = Scene::builtin_cornell_box();
    for layout in [BvhLayout::Cwbvh, BvhLayout::Bvh2q] {
        for integrator in [Integrator::Pt, Integrator::PtNee, Integrator::Bdpt(Join::Full), Integrator::Bdpt(Join::Lvc(0))] {
            let mut settings = RenderSettings::new(integrator);
            settings.bvh.layout = layout;
            match Renderer::new(&ctx, &scene, &scene.cameras[0], settings) {
                Err(RenderError::Unsupported(msg)) => {
                    assert!(msg.contains(layout.name()) && msg.contains("binary"), "{}: unhelpful message: {msg}", integrator.name())
                }
                Err(e) => panic!("{}: wrong error: {e}", integrator.name()),
                Ok(_) => panic!("{}: a {} BVH was accepted by kernels that traverse 64-byte nodes", integrator.name(), layout.name()),
            }
        }
    }
    finish(ctx);
}
