//! Settings that cannot reach the wrong kernel: combinations the integrators cannot honour are
//! clear errors from `Renderer::new`, not quietly wrong images.

mod common;

use bidir::bvh::BvhLayout;
use bidir::render::{Integrator, Join, RenderError, RenderSettings, Renderer};
use bidir::scene::Scene;
use common::{finish, gpu};

/// The integrator kernels include only the binary traversal: a compressed wide BVH would have
/// its nodes read as binary ones.
#[test]
fn wide_bvh_layout_is_refused_by_every_integrator() {
    let ctx = gpu();
    let scene = Scene::builtin_cornell_box();
    for integrator in [Integrator::Pt, Integrator::PtNee, Integrator::Bdpt(Join::Full), Integrator::Bdpt(Join::Lvc(0))] {
        let mut settings = RenderSettings::new(integrator);
        settings.bvh.layout = BvhLayout::Cwbvh;
        match Renderer::new(&ctx, &scene, &scene.cameras[0], settings) {
            Err(RenderError::Unsupported(msg)) => {
                assert!(msg.contains("cwbvh") && msg.contains("binary"), "{}: unhelpful message: {msg}", integrator.name())
            }
            Err(e) => panic!("{}: wrong error: {e}", integrator.name()),
            Ok(_) => panic!("{}: a wide BVH was accepted by kernels that traverse binary nodes", integrator.name()),
        }
    }
    finish(ctx);
}
