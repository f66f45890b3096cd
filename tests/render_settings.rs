//! Settings that cannot reach the wrong kernel: combinations the integrators cannot honour are
//! clear errors from `Renderer::new`, not quietly wrong images.

mod common;

use bidir::bvh::BvhLayout;
use bidir::render::{Integrator, Join, RenderError, RenderSettings, Renderer};
use bidir::scene::Scene;
use common::{finish, gpu};

/// The integrator kernels are built for the binary and the compressed wide BVH: a quantised
/// binary BVH would have its nodes read as one of those, so it is refused with a message that
/// says what is accepted; both accepted layouts are the ones the renderer then uses.
#[test]
fn quantised_bvh_layout_is_refused_by_every_integrator() {
    let ctx = gpu();
    let scene = Scene::builtin_cornell_box();
    for integrator in [Integrator::Pt, Integrator::PtNee, Integrator::Bdpt(Join::Full), Integrator::Bdpt(Join::Lvc(0))] {
        let mut settings = RenderSettings::new(integrator);
        settings.bvh_layout = Some(BvhLayout::Bvh2q);
        match Renderer::new(&ctx, &scene, &scene.cameras[0], settings) {
            Err(RenderError::Unsupported(msg)) => {
                assert!(msg.contains("bvh2q") && msg.contains("bvh2 or cwbvh"), "{}: unhelpful message: {msg}", integrator.name())
            }
            Err(e) => panic!("{}: wrong error: {e}", integrator.name()),
            Ok(_) => panic!("{}: a bvh2q BVH was accepted by kernels built for bvh2 and cwbvh", integrator.name()),
        }
        for layout in [BvhLayout::Bvh2, BvhLayout::Cwbvh] {
            let mut settings = RenderSettings::new(integrator);
            settings.bvh_layout = Some(layout);
            let r = Renderer::new(&ctx, &scene, &scene.cameras[0], settings).unwrap();
            assert_eq!(r.settings().bvh.layout, layout, "{}", integrator.name());
        }
    }
    finish(ctx);
}
