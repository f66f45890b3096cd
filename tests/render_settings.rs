//! Settings that cannot reach the wrong kernel: combinations the integrators cannot honour are
//! clear errors from `Renderer::new`, not quietly wrong images.

mod common;

use bidir::bvh::BvhLayout;
use bidir::gpu::abi;
use bidir::render::{Integrator, Join, RenderError, RenderSettings, Renderer, WavefrontFinish, DEFAULT_WAVEFRONT_OVERLAP};
use bidir::scene::Scene;
use common::{finish, gpu};

/// The built-in Cornell box at `width` x `height`, and its camera.
fn small_cornell(width: u32, height: u32) -> (Scene, bidir::scene::Camera) {
    let mut scene = Scene::builtin_cornell_box();
    let mut camera = scene.cameras[0].clone();
    camera.width = width;
    camera.height = height;
    scene.cameras[0] = camera.clone();
    (scene, camera)
}

/// `spp` samples per pixel of `scene` with `settings`, in the same passes whatever the
/// settings (a 1-spp calibration pass, then the rest at once: passes sized by measured time
/// could split them differently, and the film's sums would then round differently in the last
/// bits); the image's values.
fn render_values(
    ctx: &bidir::vk::Context,
    scene: &Scene,
    camera: &bidir::scene::Camera,
    mut settings: RenderSettings,
    spp: u32,
) -> Vec<f32> {
    settings.pass_target = std::time::Duration::from_secs(3600);
    let mut r = Renderer::new(ctx, scene, camera, settings).unwrap();
    r.render_spp(spp, |_| {}).unwrap();
    r.image().unwrap().data
}

/// How many of `a`'s values differ from `b`'s by more than `relative` of their size.
fn values_differing(a: &[f32], b: &[f32], relative: f32) -> usize {
    a.iter().zip(b).filter(|(x, y)| (*x - *y).abs() > relative * x.abs()).count()
}

// SHARED_CANDIDATES: BDPT's resampled connections take their candidates from a group (a 16 x 8
// block of pixels, one sample, one vertex count), whose reads the lanes of a subgroup share
// (glsl/common/bdpt_camera_path.glsl): an image is the same whichever lanes connect together,
// so the tests below that compare two ways of rendering one image value for value keep the
// scene's default candidates (8 for BDPT's default join on the diffuse box) or ask for several.

/// The BVH's build where `--bvh-quality` does not say (`render::default_bvh_build`): the
/// binary and compressed wide BVHs at quality 4 for scenes up to the bound on any device; the
/// renderer's settings say which, and a quality asked for is kept.
#[test]
fn bvh_build_quality_follows_the_scene_size() {
    let ctx = gpu();
    let scene = Scene::builtin_cornell_box();
    assert!(scene.triangles.len() <= bidir::render::QUALITY_4_MAX_TRIANGLES);
    for layout in [BvhLayout::Bvh2, BvhLayout::Cwbvh] {
        let mut settings = RenderSettings::new(Integrator::PtNee);
        settings.bvh_layout = Some(layout);
        let r = Renderer::new(&ctx, &scene, &scene.cameras[0], settings.clone()).unwrap();
        assert_eq!(r.settings().bvh.quality, 4, "{layout:?} on {}", ctx.info().name);
        drop(r);
        settings.bvh_quality = Some(1);
        let r = Renderer::new(&ctx, &scene, &scene.cameras[0], settings.clone()).unwrap();
        assert_eq!(r.settings().bvh.quality, 1, "{layout:?}: --bvh-quality was not kept");
        drop(r);
        // `bench render` reports the build it timed, in its JSON too.
        let mut camera = scene.cameras[0].clone();
        (camera.width, camera.height) = (8, 8);
        let o = bidir::bench::render::Options { spp: 1, warmup: 0, runs: 1, count: false };
        let report = bidir::bench::render::run(&ctx, &scene, &camera, settings, &o).unwrap();
        assert_eq!((report.bvh.layout, report.bvh.quality, report.bvh.max_leaf_tris), (layout, 1, 4));
        let json = report.to_json().to_pretty();
        let name = layout.name();
        assert!(json.contains(&format!("\"layout\": \"{name}\"")) && json.contains("\"quality\": 1"), "{json}");
    }
    finish(ctx);
}

/// The integrator kernels are built for the binary, the compressed wide and the 4-wide BVH: a
/// quantised binary BVH would have its nodes read as one of those, so it is refused with a
/// message that says what is accepted; the accepted layouts are the ones the renderer then uses.
#[test]
fn quantised_bvh_layout_is_refused_by_every_integrator() {
    let ctx = gpu();
    let scene = Scene::builtin_cornell_box();
    for integrator in [Integrator::Pt, Integrator::PtNee, Integrator::Bdpt(Join::Full), Integrator::Bdpt(Join::Lvc(0))] {
        let mut settings = RenderSettings::new(integrator);
        settings.bvh_layout = Some(BvhLayout::Bvh2q);
        match Renderer::new(&ctx, &scene, &scene.cameras[0], settings) {
            Err(RenderError::Unsupported(msg)) => {
                assert!(msg.contains("bvh2q") && msg.contains("bvh2, cwbvh or bvh4"), "{}: unhelpful message: {msg}", integrator.name())
            }
            Err(e) => panic!("{}: wrong error: {e}", integrator.name()),
            Ok(_) => panic!("{}: a bvh2q BVH was accepted by kernels built for bvh2 and cwbvh", integrator.name()),
        }
        for layout in [BvhLayout::Bvh2, BvhLayout::Cwbvh, BvhLayout::Bvh4] {
            let mut settings = RenderSettings::new(integrator);
            settings.bvh_layout = Some(layout);
            let r = Renderer::new(&ctx, &scene, &scene.cameras[0], settings).unwrap();
            assert_eq!(r.settings().bvh.layout, layout, "{}", integrator.name());
        }
    }
    finish(ctx);
}

/// Path regeneration (`--path-regeneration`) changes only how an invocation's samples are
/// scheduled, not which random numbers a sample uses: pt and pt-nee give bit-identical images
/// either way, with several samples per invocation (one slice) and with slices.
#[test]
fn path_regeneration_gives_the_same_image() {
    let ctx = gpu();
    let (scene, camera) = small_cornell(24, 16);
    for integrator in [Integrator::Pt, Integrator::PtNee] {
        for slices in [1, 3] {
            let image = |regenerate: bool| {
                let mut settings = RenderSettings::new(integrator);
                settings.path_regeneration = Some(regenerate);
                settings.sample_slices = slices;
                render_values(&ctx, &scene, &camera, settings, 7)
            };
            let (on, off) = (image(true), image(false));
            assert!(on.iter().any(|&v| v > 0.0), "{}: black image", integrator.name());
            let differ = on.iter().zip(&off).filter(|(a, b)| a.to_bits() != b.to_bits()).count();
            assert_eq!(differ, 0, "{} with {slices} slices: {differ} of {} values differ", integrator.name(), on.len());
        }
    }
    finish(ctx);
}

/// The integrators over the 4-wide BVH (`--bvh bvh4`) find the hits they find over the binary
/// one (same leaves, another traversal order): pt-nee and BDPT give the same image but for
/// rays that hit two triangles at exactly the same distance (a shared edge), where either
/// may win; on the Cornell box at this size none does (pt-nee bit for bit; BDPT to the
/// rounding of its splats' order).
#[test]
fn four_wide_bvh_gives_the_binary_bvhs_image() {
    let ctx = gpu();
    let (scene, camera) = small_cornell(32, 24);
    for integrator in [Integrator::PtNee, Integrator::Bdpt(Join::DEFAULT)] {
        let image = |layout: BvhLayout| {
            let mut settings = RenderSettings::new(integrator);
            settings.bvh_layout = Some(layout);
            // The diffuse box's default: 8 shared candidates (SHARED_CANDIDATES).
            render_values(&ctx, &scene, &camera, settings, 4)
        };
        let (binary, wide) = (image(BvhLayout::Bvh2), image(BvhLayout::Bvh4));
        assert!(binary.iter().any(|&v| v > 0.0), "{}: black image", integrator.name());
        // BDPT's light-tracing splats are atomic float adds, whose order varies from run to
        // run: its values may differ in the last bits (as two renders over one layout do).
        let relative = if integrator == Integrator::PtNee { 0.0 } else { 1e-5 };
        let differ = values_differing(&binary, &wide, relative);
        assert_eq!(differ, 0, "{}: {differ} of {} values differ", integrator.name(), binary.len());
    }
    finish(ctx);
}

/// `RenderSettings::count_traversal` (`bench render --count`): the integrator kernels count
/// what they trace. Every sample traces at least its camera ray and, with paths of at most 3
/// bounces, at most 3 extension and 3 shadow rays (pt-nee), plus up to 3 connections and a
/// light path of its own (BDPT); every ray visits at least the root; off, nothing is counted.
#[test]
fn traversal_counts_are_plausible_and_off_by_default() {
    let ctx = gpu();
    let scene = Scene::builtin_cornell_box();
    let mut camera = scene.cameras[0].clone();
    camera.width = 16;
    camera.height = 16;
    for (integrator, most_per_sample) in [(Integrator::PtNee, 7.0), (Integrator::Bdpt(Join::DEFAULT), 19.0)] {
        for count in [false, true] {
            let mut settings = RenderSettings::new(integrator);
            settings.max_depth = 3;
            settings.count_traversal = count;
            let mut r = Renderer::new(&ctx, &scene, &camera, settings).unwrap();
            r.render_spp(8, |_| {}).unwrap();
            let [rays, nodes, tris] = r.traversal_counts().unwrap();
            let samples = (16 * 16 * 8) as f64;
            if !count {
                assert_eq!([rays, nodes, tris], [0, 0, 0], "{}: counted without count_traversal", integrator.name());
                continue;
            }
            let per_sample = rays as f64 / samples;
            eprintln!(
                "{}: {per_sample:.2} rays/sample, {:.2} nodes/ray, {:.2} triangles/ray",
                integrator.name(),
                nodes as f64 / rays as f64,
                tris as f64 / rays as f64
            );
            assert!((1.0..=most_per_sample).contains(&per_sample), "{}: {per_sample} rays per sample", integrator.name());
            assert!(nodes >= rays && tris > 0, "{}: {nodes} nodes, {tris} triangles for {rays} rays", integrator.name());
        }
    }
    finish(ctx);
}

/// pt-nee's shadow-ray queue (`RenderSettings::shadow_queue`) traces the same shadow rays
/// with the same random numbers as tracing them where they are drawn, so the image is the
/// same but for the order in which the film's float sums take the contributions: values agree
/// to 1e-5 of their size (measured: at most 3e-7; one lost or doubled light sample moves a
/// pixel of these 7 samples by a percent or more). Shapes whose paths pause for a full queue
/// almost every bounce (4 slots), whose finishing launch traces most rays itself (4 slots, all
/// samples in one launch), and one sample per launch over three slices. The tall box is
/// half-transparent (alpha BLEND), so queued shadow rays must carry their path's
/// stochastic-opacity seed.
#[test]
fn shadow_queue_gives_the_same_image() {
    use bidir::render::ShadowQueue;
    let ctx = gpu();
    let (mut scene, camera) = small_cornell(24, 16);
    let tall = scene.materials.iter().position(|m| m.name == "tallBox").expect("the Cornell box's tall box");
    scene.materials[tall].blend = Some(0.5);
    let image = |queue: Option<ShadowQueue>, slices: u32| {
        let mut settings = RenderSettings::new(Integrator::PtNee);
        settings.shadow_queue = Some(queue);
        settings.sample_slices = slices;
        render_values(&ctx, &scene, &camera, settings, 7)
    };
    let shapes = [(4, 2, true, 1), (4, 100, true, 1), (16, 1, false, 3)];
    for slices in [1, 3] {
        let off = image(None, slices);
        assert!(off.iter().any(|&v| v > 0.0), "black image");
        for &(slots, chunk_samples, pause, _) in shapes.iter().filter(|s| s.3 == slices) {
            let queued = image(Some(ShadowQueue { slots, chunk_samples, pause }), slices);
            let differ = values_differing(&queued, &off, 1e-5);
            assert_eq!(
                differ,
                0,
                "{slots} slots, {chunk_samples} samples a launch, pause {pause}, {slices} slices: {differ} of {} values differ",
                off.len()
            );
        }
    }
    finish(ctx);
}

/// BDPT queues its camera pass's shadow rays and its light pass's joins to the camera (the
/// second kind splatted by their own kernel, at the pixel each projects to). In a crop the
/// light pass traces the full image's light paths, here twice as many per pixel
/// (`--light-paths 2`) over three slices: more light-pass invocations than camera-pass ones,
/// all with slots of their own. The image agrees with tracing every ray in place to 1e-5 of
/// each value (the splats' atomic adds land in any order either way).
#[test]
fn bdpt_shadow_queue_gives_the_same_image_in_a_crop() {
    use bidir::imaging::Crop;
    use bidir::render::ShadowQueue;
    let ctx = gpu();
    let (scene, camera) = small_cornell(24, 16);
    let image = |queue: Option<ShadowQueue>| {
        let mut settings = RenderSettings::new(Integrator::Bdpt(Join::DEFAULT));
        settings.shadow_queue = Some(queue);
        settings.crop = Some(Crop { x0: 5, y0: 3, x1: 17, y1: 11 });
        settings.light_path_ratio = Some(2.0);
        settings.sample_slices = 3;
        // The diffuse box's default: 8 shared candidates, the crop cutting their pixel blocks
        // (SHARED_CANDIDATES).
        render_values(&ctx, &scene, &camera, settings, 6)
    };
    let off = image(None);
    assert!(off.iter().filter(|&&v| v > 0.0).count() * 2 > off.len(), "a mostly black image");
    let queued = image(Some(ShadowQueue { slots: 4, chunk_samples: 1, pause: false }));
    let differ = values_differing(&queued, &off, 1e-5);
    assert_eq!(differ, 0, "{differ} of {} values differ", off.len());
    finish(ctx);
}

/// `--one-trace` changes where pt-nee traces a light sample's shadow ray (the next step,
/// through the extension rays' call, or where it is drawn), not what it adds or in which
/// order: the images agree, with path regeneration and with a loop of samples over slices, to
/// the last bits the shader compiler may round differently in the two specialisations.
#[test]
fn one_trace_gives_the_same_image() {
    let ctx = gpu();
    let (scene, camera) = small_cornell(24, 16);
    // Regeneration with one slice (7 samples per invocation), and the loop of samples with 3.
    for (regenerate, slices) in [(true, 1), (false, 3)] {
        let image = |one_trace: bool| {
            let mut settings = RenderSettings::new(Integrator::PtNee);
            settings.one_trace = Some(one_trace);
            settings.path_regeneration = Some(regenerate);
            settings.sample_slices = slices;
            render_values(&ctx, &scene, &camera, settings, 7)
        };
        let (on, off) = (image(true), image(false));
        assert!(on.iter().any(|&v| v > 0.0), "black image");
        let differ = values_differing(&on, &off, 1e-5);
        assert_eq!(differ, 0, "regeneration {regenerate}, {slices} slices: {differ} of {} values differ", on.len());
    }
    finish(ctx);
}

/// The wavefront path tracer (`--wavefront`) runs the megakernel's path code with the same
/// random numbers, its segments and shadow rays traced by the trace kernels between its
/// launches (packed into queues, each ray carrying its path's stochastic-opacity seed: the tall
/// box is half-transparent here): pt and pt-nee give the megakernel's image over every layout
/// the integrators traverse, with one slice and three, up to the order of the film's float sums
/// (a clear light sample is added to the radiance of the path that goes on in its slot): to
/// 1e-5 of each value.
#[test]
fn wavefront_gives_the_megakernels_image() {
    let ctx = gpu();
    let (mut scene, camera) = small_cornell(24, 16);
    let tall = scene.materials.iter().position(|m| m.name == "tallBox").expect("the Cornell box's tall box");
    scene.materials[tall].blend = Some(0.5);
    // (pt finds the small light itself: more samples for a lit image.)
    // The wavefront form's passes end as by default, and (one per layout) by launches until
    // none queues a ray, or by a finishing launch after 2 launches (nearly every sample of the
    // pass run in it) or 6.
    let finishes = [WavefrontFinish::Off, WavefrontFinish::After(2), WavefrontFinish::After(6)];
    // And with the short box of absorbing glass (a medium, which the slots' paths carry
    // across launches), over one layout.
    let mut medium = scene.clone();
    let short = medium.materials.iter().position(|m| m.name == "shortBox").expect("the Cornell box's short box");
    (medium.materials[short].refractivity, medium.materials[short].ior) = (1.0, 1.5);
    medium.materials[short].absorption = glam::Vec3::new(0.002, 0.006, 0.012);
    // And with no surface that alpha or blending can skip (the slots' paths then take one
    // 16-byte word less: wf_ray.glsl, WF_STATE_STRIDE).
    let mut opaque = scene.clone();
    opaque.materials[tall].blend = None;
    let cases = [
        (&scene, BvhLayout::Cwbvh, 1),
        (&scene, BvhLayout::Bvh2, 3),
        (&scene, BvhLayout::Bvh4, 3),
        (&medium, BvhLayout::Bvh4, 3),
        (&opaque, BvhLayout::Bvh4, 3),
    ];
    for (integrator, spp) in [(Integrator::Pt, 64), (Integrator::PtNee, 7)] {
        for (i, (scene, layout, slices)) in cases.into_iter().enumerate() {
            let image = |wavefront: bool, finish: WavefrontFinish| {
                let mut settings = RenderSettings::new(integrator);
                settings.wavefront = Some(wavefront);
                settings.wavefront_finish = finish;
                settings.bvh_layout = Some(layout);
                settings.sample_slices = slices;
                render_values(&ctx, scene, &camera, settings, spp)
            };
            let mega = image(false, WavefrontFinish::Auto);
            let name = integrator.name();
            let lit = mega.iter().filter(|&&v| v > 0.0).count();
            assert!(lit * 3 > mega.len(), "{name}: {lit} of {} values above 0", mega.len());
            for finish in [WavefrontFinish::Auto, finishes[i % finishes.len()]] {
                let wave = image(true, finish);
                let differ = values_differing(&wave, &mega, 1e-5);
                let glass = scene.materials[short].refractivity > 0.0;
                let blend = scene.materials[tall].blend.is_some();
                assert_eq!(
                    differ,
                    0,
                    "{name} over {}, {slices} slices, absorbing glass {glass}, blending {blend}, finish {}: {differ} of {} values differ",
                    layout.name(),
                    finish.name(),
                    mega.len()
                );
            }
        }
    }
    finish(ctx);
}

/// BDPT's passes as wavefronts (`--wavefront on`, bdpt_light_wavefront.comp,
/// bdpt_camera_wavefront.comp): their segments, the light paths' joins to the eye and the
/// camera paths' light samples and connections traced by the trace kernels between their
/// launches give the megakernels' image, with one and with three connections per vertex, one
/// slice and three, twice and half as many light paths as pixels, over every layout, the tall
/// box half-transparent (each ray carrying its path's stochastic-opacity seed), and with a
/// glass short box and a mirror tall box, up to the order
/// of the film's float sums: to 1e-5 of each value. A first version that kept each shadow ray's
/// contribution in one buffer for the launch that reads it and the launch that writes the next
/// failed here (one slot overwrote what another had yet to read: the image came out darker, and
/// differed from run to run).
#[test]
fn wavefront_bdpt_gives_the_megakernels_image() {
    let ctx = gpu();
    let (mut scene, camera) = small_cornell(24, 16);
    let tall = scene.materials.iter().position(|m| m.name == "tallBox").expect("the Cornell box's tall box");
    let short = scene.materials.iter().position(|m| m.name == "shortBox").expect("the Cornell box's short box");
    // The same box with a smooth glass short box and a mirror tall box (BDPT's wavefront passes
    // are its default on GPUs in such scenes: paths through specular vertices), the glass
    // absorbing (a medium, which the passes' path states carry across launches).
    let mut specular = scene.clone();
    (specular.materials[short].refractivity, specular.materials[short].ior) = (1.0, 1.5);
    specular.materials[short].absorption = glam::Vec3::new(0.002, 0.006, 0.012);
    specular.materials[tall].reflectivity = 1.0;
    scene.materials[tall].blend = Some(0.5);
    // Two and three candidates: lavapipe's 8-lane subgroups share them among the blocks that
    // compaction puts in one subgroup of the wavefront form (up to 4 and 2 groups), where the
    // megakernels' subgroups hold one block; eight are shared there only by one block's 8 lanes.
    // Each case's wavefront form ends its passes as by default (a finishing launch once few paths
    // are live), and one other way: launches until none queues a ray, or the finishing launch
    // after 2 or 4 launches (most paths still live: it runs nearly all of the pass).
    let others = [WavefrontFinish::Off, WavefrontFinish::After(2), WavefrontFinish::After(4)];
    for (i, (scene, join, layout, slices, ratio, candidates)) in [
        (&scene, Join::Lvc(1), BvhLayout::Cwbvh, 1, 1.0, 8),
        (&scene, Join::Lvc(1), BvhLayout::Bvh2, 3, 1.0, 8),
        (&scene, Join::Lvc(3), BvhLayout::Bvh4, 3, 1.0, 8),
        (&scene, Join::Lvc(1), BvhLayout::Bvh4, 3, 2.0, 8),
        (&scene, Join::Lvc(2), BvhLayout::Bvh2, 1, 0.5, 8),
        (&scene, Join::Lvc(1), BvhLayout::Bvh4, 3, 1.0, 2),
        (&scene, Join::Lvc(2), BvhLayout::Cwbvh, 3, 0.5, 3),
        (&specular, Join::Lvc(1), BvhLayout::Cwbvh, 3, 1.0, 8),
        (&specular, Join::Lvc(3), BvhLayout::Bvh4, 1, 1.0, 8),
    ]
    .into_iter()
    .enumerate()
    {
        let image = |wavefront: bool, finish: WavefrontFinish, overlap: Option<u32>| {
            let mut settings = RenderSettings::new(Integrator::Bdpt(join));
            settings.wavefront = Some(wavefront);
            settings.wavefront_finish = finish;
            settings.wavefront_overlap = overlap;
            settings.bvh_layout = Some(layout);
            settings.sample_slices = slices;
            settings.light_path_ratio = Some(ratio);
            // Shared candidates per connection, on every join (SHARED_CANDIDATES).
            settings.connection_candidates = Some(candidates);
            render_values(&ctx, scene, &camera, settings, 6)
        };
        let mega = image(false, WavefrontFinish::Auto, None);
        let lit = mega.iter().filter(|&&v| v > 0.0).count();
        assert!(lit * 3 > mega.len(), "{lit} of {} values above 0", mega.len());
        // By default each camera pass's last launches run beside the next light pass (two
        // stores); also each pass alone, or side by side from the camera pass's second launch on
        // (every launch of it beside the light pass), or only the last.
        let (default, overlaps) = (Some(DEFAULT_WAVEFRONT_OVERLAP), [None, Some(abi::WF_MAX_BATCH - 1), Some(1)]);
        let finishes = [(WavefrontFinish::Auto, default), (others[i % others.len()], default), (WavefrontFinish::Auto, overlaps[i % 3])];
        for (finish, overlap) in finishes {
            let wave = image(true, finish, overlap);
            let differ = values_differing(&wave, &mega, 1e-5);
            let glass = scene.materials[short].refractivity > 0.0;
            assert_eq!(
                differ,
                0,
                "bdpt:{} over {}, {slices} slices, {ratio} light paths per pixel, {candidates} candidates, glass and mirror {glass}, finish {}, overlap {overlap:?}: {differ} of {} values differ",
                join.name(),
                layout.name(),
                finish.name(),
                mega.len()
            );
        }
    }
    // The light vertex cache listed with an invocation per slot of the store (the GPUs' form
    // with resampled connections) and per light path (lavapipe's): the same listing, so the same
    // image (up to the order of the light pass's float splats, as above), with resampled and
    // uniform entries, over sample slices, with fewer light paths than pixels and more.
    for (candidates, slices, ratio) in [(8, 3, 0.5), (1, 1, 1.0), (3, 3, 2.0)] {
        let image = |per_slot: bool| {
            let mut settings = RenderSettings::new(Integrator::Bdpt(Join::Lvc(1)));
            settings.wavefront = Some(true);
            settings.sample_slices = slices;
            settings.light_path_ratio = Some(ratio);
            settings.connection_candidates = Some(candidates);
            settings.lvc_listing_per_slot = Some(per_slot);
            render_values(&ctx, &scene, &camera, settings, 6)
        };
        let (per_path, per_slot) = (image(false), image(true));
        let differ = values_differing(&per_slot, &per_path, 1e-5);
        assert_eq!(
            differ,
            0,
            "{candidates} candidates, {slices} slices, {ratio} light paths per pixel: the listing per slot changes {differ} of {} values",
            per_path.len()
        );
    }
    // An image whose size is no multiple of the 8 x 8 tiles (TILE_SIZE): the camera pass's first
    // launch queues a ray without a segment for each slot past the window's pixels, so that
    // every slot has its place in the queue (bdpt_camera_wavefront.glsl).
    let (mut odd, odd_camera) = small_cornell(20, 13);
    odd.materials[tall].blend = Some(0.5);
    let image = |wavefront: bool, finish: WavefrontFinish| {
        let mut settings = RenderSettings::new(Integrator::Bdpt(Join::Lvc(1)));
        settings.wavefront = Some(wavefront);
        settings.wavefront_finish = finish;
        settings.bvh_layout = Some(BvhLayout::Bvh4);
        settings.sample_slices = 3;
        render_values(&ctx, &odd, &odd_camera, settings, 6)
    };
    let mega = image(false, WavefrontFinish::Auto);
    for finish in [WavefrontFinish::Auto, WavefrontFinish::After(2)] {
        let differ = values_differing(&image(true, finish), &mega, 1e-5);
        assert_eq!(differ, 0, "bdpt at 20 x 13, finish {}: {differ} of {} values differ", finish.name(), mega.len());
    }
    // Joins without a fixed number of connections per vertex have no wavefront form.
    for integrator in [Integrator::Bdpt(Join::Full), Integrator::Bdpt(Join::Lvc(0)), Integrator::Vcm(bidir::render::vcm::VcmMode::FULL)] {
        let mut settings = RenderSettings::new(integrator);
        settings.wavefront = Some(true);
        let err = Renderer::new(&ctx, &scene, &camera, settings).err().map(|e| e.to_string()).unwrap_or_default();
        assert!(err.contains("no wavefront form"), "{}: {err:?}", integrator.name());
    }
    finish(ctx);
}
