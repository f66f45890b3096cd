//! What runs by default on which device and scene: the BVH layout, path regeneration, one
//! trace call, the shadow-ray queue, each measured (docs/results.md) and picked per device
//! (GPU or CPU), integrator and scene features, with what `--bvh` / `--shadow-queue` ask.

use super::{pt, shadow_queue, Integrator, Join, Mis, RenderSettings, ShadowQueue};
use crate::bvh::BvhLayout;
use crate::gpu_data::SceneFeatures;
use crate::vk::Context;

/// The BVH layout `integrator` traces fastest on a device for a scene with `features`,
/// measured with `bidir bench render` (NVIDIA H200 and llvmpipe; docs/results.md, "Cornell
/// box, session 6" and "Which BVH the path tracers take in glossy scenes"): the compressed wide
/// BVH on CPU devices (fewer, wider node visits suit llvmpipe's SIMD lanes); on GPUs the wide
/// BVH for the path tracers where the scene has only diffuse surfaces (Cornell box pt-nee 693
/// against 606 Msamples/s over the binary BVH) and for pt-nee also where it has GGX lobes but
/// no mirror or glass (session 9: Sponza +6 %, DamagedHelmet +8-17 %, MetalRoughSpheres +7 %),
/// the binary one where it has mirrors or glass (their larger kernels reached 96 registers
/// over the wide BVH: caustic scene pt-nee 314-412 against 385-490; rough Cornell -7 %), for
/// pt in glossy scenes (Sponza -10 % over the wide BVH). BDPT and VCM (`queued`: their shadow
/// rays go to the shadow-ray queue, the default on GPUs) take the wide BVH in every scene
/// measured (session 11: Cornell box bdpt 214.5 against 244.6 ms, Sponza 392.7 against 413.2,
/// caustic scene 77.2 against 87.0, Cornell box vcm 249.8 against 307.8); without the queue the
/// binary one (their camera pass was 13-24 % slower over the wide BVH; Sponza bdpt 549 against
/// 644 ms).
/// The 4-wide BVH (`bvh4`) is never the default: it traces standalone rays fastest, and since
/// session 12 (its stack skips boxes past the nearest hit) BDPT over it is 7 % faster on Sponza
/// (339.9 against 365.6 ms), but slower on the Cornell box (256.4 against 206.0), the punctual
/// lamp and a million-triangle scene, level elsewhere; no scene size separates them
/// (docs/traversal.md, "The node step as the driver compiles it").
/// [`Renderer::switch_integrator`](crate::render::Renderer::switch_integrator) rebuilds the renderer where a switch changes this choice.
pub fn default_bvh_layout(on_cpu: bool, integrator: Integrator, features: &SceneFeatures, queued: bool) -> BvhLayout {
    if on_cpu {
        return BvhLayout::Cwbvh;
    }
    match integrator {
        Integrator::Pt if features.only_diffuse() => BvhLayout::Cwbvh,
        Integrator::PtNee if !features.has_specular() => BvhLayout::Cwbvh,
        Integrator::Bdpt(_) | Integrator::Vcm(_) if queued => BvhLayout::Cwbvh,
        _ => BvhLayout::Bvh2,
    }
}

/// Whether pt and pt-nee regenerate paths by default (the image is the same either way):
/// on, except on GPUs for scenes with smooth mirrors or glass, where the regenerating loop
/// was slower on the H200 (caustic scene pt-nee 385 against 490 Msamples/s, mirror-and-glass
/// scene 318 against 395; elsewhere it gained up to 32 %: Sponza pt-nee 67.5 against 51.1).
/// Measured, not modelled (docs/results.md).
pub fn default_path_regeneration(on_cpu: bool, features: &SceneFeatures) -> bool {
    let smooth_specular = features.mirror || (features.glass && !features.rough_glass);
    on_cpu || !smooth_specular
}

/// Whether pt-nee traces its shadow rays through the extension rays' trace call, in the step
/// after the one that drew them (the image is the same either way): on GPUs, except over
/// the compressed wide BVH in scenes with only diffuse surfaces, where the extra steps cost
/// more than the shared traversal saves. NVIDIA H200, `bench render`, Msamples/s, two runs
/// (docs/results.md, "One trace call for extension and shadow rays"): Cornell box over bvh2
/// 631-638 against 534-537, over cwbvh 661-668 against 698-703; Sponza (cwbvh) 76.2-76.4
/// against 72.4-72.5; caustic scene (bvh2) 584-590 against 541-543. Off on CPU devices
/// (llvmpipe, Cornell box over cwbvh: 25-30 % slower on; DamagedHelmet: within its spread).
pub fn default_one_trace(on_cpu: bool, layout: BvhLayout, features: &SceneFeatures) -> bool {
    let wide_diffuse = layout == BvhLayout::Cwbvh && features.only_diffuse();
    !(on_cpu || wide_diffuse)
}

/// BDPT's and VCM's camera pass and light pass's joins to the camera: the shadow-ray queue by
/// default on GPUs, 64 slots (one camera or light path per thread; what does not fit is traced
/// in place, and `ShadowQueue::fit` takes fewer where the memory budget asks); off on CPU
/// devices. NVIDIA H200, `bench render` (docs/results.md, "A queue for the shadow rays" and
/// "The light pass's joins queued"): Cornell box bdpt 261.5 against 321 ms per 1024 spp with
/// the camera pass queued (session 10), 244.0 with the light pass's joins too, 214.5 over the
/// wide BVH (session 11); over it 64 slots against 32: Sponza bdpt 386.6 against 393.2 ms per
/// 64 spp, Cornell box vcm 243.7 against 249.7, Cornell box and caustic scene bdpt level (16
/// slots lose 3-16 %, 8 slots 23-42 %).
pub fn default_camera_pass_queue(on_cpu: bool) -> Option<ShadowQueue> {
    (!on_cpu).then_some(ShadowQueue { slots: 64, chunk_samples: 1, pause: false })
}

/// pt-nee's shadow-ray queue by default (`ShadowQueue`): on GPUs over the compressed wide BVH
/// (scenes without mirrors or glass), 192 slots and 24 samples per launch, paths pausing for a
/// full queue where the scene has glossy surfaces (the megakernel that traces a shadow ray
/// itself where the slots are full held 96 registers on Sponza against 80; on the diffuse
/// Cornell box the pausing one was the slower, 785 against 824 Msamples/s); none over the
/// binary BVH (caustic scene 490 against 581) nor on CPU devices (llvmpipe: a 128x128 render
/// of 48 samples per pixel took 1.27x the time, its two more kernels' compile included).
/// NVIDIA H200, `bench render`, two runs (docs/results.md, "A queue for the shadow rays"):
/// Cornell box 844-845 against 701-710 Msamples/s, Sponza 81.7-81.8 against 76.5-76.7 (84.9
/// with the queue's rays shared over the subgroup), DamagedHelmet 709-719 against 680-693 (at
/// 128/16), MetalRoughSpheres 817-819 against 819-832.
pub fn default_shadow_queue(on_cpu: bool, layout: BvhLayout, features: &SceneFeatures) -> Option<ShadowQueue> {
    if on_cpu || layout != BvhLayout::Cwbvh {
        return None;
    }
    Some(ShadowQueue { slots: 192, chunk_samples: 24, pause: !features.only_diffuse() })
}

/// The shadow-ray queue of `integrator`'s megakernel for launches of `invocations`
/// invocations: `--shadow-queue` or the default (`default_shadow_queue` for pt-nee,
/// `default_camera_pass_queue` for BDPT and VCM), with fewer slots where they would not fit in
/// `shadow_queue::budget`; none for the wavefront forms, whose trace kernels trace every ray.
pub(super) fn resolve_shadow_queue(
    ctx: &Context,
    settings: &RenderSettings,
    integrator: Integrator,
    features: &SceneFeatures,
    layout: BvhLayout,
    invocations: u64,
) -> Option<ShadowQueue> {
    if wavefront(ctx, settings, integrator, features) {
        return None;
    }
    let (queue, fixed) = match integrator {
        Integrator::Pt => return None,
        Integrator::PtNee => {
            let queue = settings.shadow_queue.unwrap_or_else(|| default_shadow_queue(on_cpu(ctx), layout, features));
            (queue, pt::PAUSED_PATH_BYTES)
        }
        Integrator::Bdpt(_) | Integrator::Vcm(_) => (settings.shadow_queue.unwrap_or_else(|| default_camera_pass_queue(on_cpu(ctx))), 0),
    };
    queue.and_then(|q| q.fit(invocations, fixed, shadow_queue::budget(ctx)))
}

/// Whether an integrator runs in its wavefront form by default. pt and pt-nee (the wavefront
/// path tracer, `pt_wavefront.rs`): on GPUs where the scene has glossy or textured surfaces,
/// or smooth mirrors or glass (since session 42, when its passes' finishing launch made it
/// 1.23x the megakernel's speed on the caustic scene's smooth glass, pt-nee 21.2 against 26.1
/// ms per 1024 spp on an H100, pt 17.6 against 21.7; the plain Cornell box and the hidden
/// light's box keep the megakernel there, 72.6 against 53.2 and 57.4; docs/results.md, "A
/// finishing launch for the wavefront passes"). Before it (NVIDIA
/// H200, `bench render`, pt-nee, ms per run (docs/results.md, "A wavefront path tracer"):
/// textured Sponza under sun and sky 58.2 against 79.3 (640 x 360, 64 spp; pt 44.0 against
/// 51.9), 120.3 against 162.5 at 1920 x 1080; DamagedHelmet 25.1 against 36.0,
/// MetalRoughSpheres 30.8 against 37.9, CesiumMilkTruck 15.1 against 15.7 (384², 256 spp); the
/// megakernels stay for the diffuse Cornell box (58.4 against 78.6 ms per 1024 spp: there the
/// slots' memory traffic costs more than the trace kernels save) and the caustic scene's smooth
/// glass (102 against 108), which has the wavefront form now); CPU devices (llvmpipe: 3-4x
/// slower, its launches' fixed costs).
///
/// BDPT's passes (`bdpt_wavefront.rs`; bdpt and bdpt:lvc=N, N <= 3) take their wavefront form
/// on GPUs in every scene but a plain one (untextured diffuse surfaces without mirrors or
/// glass), and there too with one connection per camera vertex (`bdpt`, the default join).
/// NVIDIA H200, session 21, ms per run, GPU time (wall time): textured Sponza 72.4
/// against 123.2 (640 x 360, 64 spp), DamagedHelmet 171 against 401.5 (384², 256 spp), the
/// rough Cornell box 77.6 against 153.1 (256², 256 spp), the caustic scene's smooth glass 53.8
/// against 66.0 (wall 58.4-59.8 against 67.9-68.3, with submissions that reuse their fences)
/// (docs/results.md, "Launches of three dispatches"). Plain scenes, session 27 (256², 1024 spp,
/// two runs; docs/results.md, "BDPT's wavefront form on the plain Cornell box"): the Cornell
/// box's bdpt 164.0-164.1 against 175.1 ms (wall 169-174 against 181-184; in session 21 the
/// megakernels led, 174.9 against 185.4), the box whose light hides above a panel 182.0-182.5
/// against 187.7; with more connections the megakernels stay (lvc=3: 230.3 against 224.2 and
/// 243.0 against 227.0; lvc=2 on the hidden light 215.9 against 208.3). Small images
/// need their slots from more sample slices (`slices::MAX_WAVEFRONT_SLICES`): with them the caustic
/// scene at 64² takes 12.7 against 16.5 ms per 1024 spp, DamagedHelmet 19.2 against 47.5
/// (session 22, "Slots for small images").
pub fn default_wavefront(on_cpu: bool, integrator: Integrator, features: &SceneFeatures) -> bool {
    let smooth_specular = features.mirror || (features.glass && !features.rough_glass);
    let rich = features.glossy || features.textures;
    let wins = match integrator {
        Integrator::Bdpt(join) => rich || smooth_specular || join == Join::Lvc(1),
        _ => rich || smooth_specular,
    };
    wavefront_supported(integrator) && !on_cpu && wins
}

/// Whether `integrator` has a wavefront form: pt and pt-nee (pt_wavefront.rs), and BDPT's
/// passes with the light vertex cache's fixed joins (bdpt_wavefront.rs).
pub fn wavefront_supported(integrator: Integrator) -> bool {
    match integrator {
        Integrator::Pt | Integrator::PtNee => true,
        Integrator::Bdpt(join) => super::bdpt_wavefront::shadow_rays_per_slot(join).is_some(),
        Integrator::Vcm(_) => false,
    }
}

/// Whether `integrator` runs in its wavefront form on `ctx` with `settings` (`--wavefront`,
/// or the default), and by default not where traversal is counted (`bench render --count`:
/// the megakernels count it).
pub(super) fn wavefront(ctx: &Context, settings: &RenderSettings, integrator: Integrator, features: &SceneFeatures) -> bool {
    let default = || !settings.count_traversal && default_wavefront(on_cpu(ctx), integrator, features);
    wavefront_supported(integrator) && settings.wavefront.unwrap_or_else(default)
}

/// The BVH layout of the wavefront path tracer's trace kernels: on GPUs the 4-wide one, whose
/// lockstep loops and dynamic fetch trace standalone rays fastest (`bench traversal` on the
/// H200, docs/traversal.md); on CPU devices the compressed wide one, as for every integrator.
pub fn wavefront_bvh_layout(on_cpu: bool) -> BvhLayout {
    if on_cpu {
        BvhLayout::Cwbvh
    } else {
        BvhLayout::Bvh4
    }
}

/// BDPT's and VCM's MIS heuristic where `--mis` does not say: the balance heuristic for BDPT
/// in scenes with only diffuse surfaces, the power heuristic (exponent 2) otherwise. Variance
/// per sample does not depend on the device, so lavapipe measured it, from the difference of
/// two seeds' renders (docs/results.md, "BDPT's MIS heuristic"): on the Cornell box the
/// balance heuristic has 5.6 % less variance off the light's edge at 256², 64 spp, 7.6-8.1 % at
/// 64², 1,024 spp (seed pairs 1-2 and 3-4), at the same cost; on the box whose light hides
/// above a panel it is level or slightly ahead (-6 % and 0 % in MSE, 64², 1,024 spp); on the
/// rough Cornell box (GGX lobes) it is 2-4 % behind (where a BSDF lobe is much narrower than
/// the light's spread, the power heuristic's sharper weights pay, Veach 1997, 9.2.4); the
/// caustic scene level. VCM keeps the power heuristic (not measured with the other).
pub fn default_mis(integrator: Integrator, features: &SceneFeatures) -> Mis {
    match integrator {
        Integrator::Bdpt(_) if features.only_diffuse() => Mis::Balance,
        _ => Mis::Power,
    }
}

/// Whether the light vertex cache's listing (lvc_compact.comp) runs an invocation per slot of
/// the store rather than one per light path: on GPUs where the entries carry a preview of the
/// vertex (resampled connections, `connection_candidates` > 1), which the listing reads whole.
/// There a subgroup's lanes read neighbouring slots instead of one path's slots each. NVIDIA
/// H100, `bench render --spp 1024` (docs/results.md, "Where the camera kernel's time goes; the
/// light vertex cache listed per slot"):
/// the Cornell box 111.61-111.68 against 112.48-112.51 ms (the listing 2.86 against 3.69), the
/// box whose light hides above a panel 123.16-123.26 against 125.23-125.25, Sponza with 8
/// candidates 166.08-166.12 against 166.34-166.47; with uniform entries (DamagedHelmet, one
/// candidate) the listing took 0.83 against 0.44 ms, and on lavapipe 50-52 against 31 ms
/// (Cornell box 128², 64 spp): there an invocation per path stays.
pub fn default_lvc_listing_per_slot(on_cpu: bool, connection_candidates: u32) -> bool {
    !on_cpu && connection_candidates > 1
}

/// Light paths per pixel for BDPT's default join (the light vertex cache, one connection) where
/// `--light-paths` does not say: 0.4 in scenes with only diffuse surfaces, where its
/// connections are resampled from [`default_connection_candidates`]' eight candidates; one
/// otherwise, and for every other integrator and join. With the connections resampled, fewer
/// light paths lose less than their time buys (docs/results.md, "Candidates shared within the
/// subgroup": on the H200 the Cornell box's RMSE at 1 s went from 0.000358-0.000364 with one
/// light path and the uniform draw to 0.000308-0.000310 with half a light path and 8
/// candidates). 0.4 rather than session 38's 0.5 since session 50 (docs/results.md, "0.4 light
/// paths per pixel"): an NVIDIA H100's BDPT sample took 101.4 against 110.0 ms per 1024 spp
/// (pt-nee 46.9). At equal time (lavapipe's variance per sample, three seed pairs, times the
/// H100's ms) the Cornell box's MSE fell 5-7 %. On the box whose light hides above a panel it
/// fell 4 % away from the bright region the light shines on (2 % of the pixels, where light
/// paths carry most) and rose 11 % over the whole image, which that region dominates; its
/// relative MSE fell 1 %.
pub fn default_light_path_ratio(integrator: Integrator, features: &SceneFeatures) -> f32 {
    if resampled_diffuse_bdpt(integrator, features) {
        0.4
    } else {
        1.0
    }
}

/// Where BDPT takes its resampled connections and fewer light paths than pixels by default:
/// its default join in scenes with only diffuse surfaces. One predicate for both defaults,
/// which were measured together and only pay together.
fn resampled_diffuse_bdpt(integrator: Integrator, features: &SceneFeatures) -> bool {
    integrator == Integrator::Bdpt(Join::DEFAULT) && features.only_diffuse()
}

/// Candidates of each connection to the light vertex cache (`--connection-candidates`) where
/// the settings do not say: eight for BDPT's default join in scenes with only diffuse surfaces,
/// one (the uniform draw) otherwise. The candidates' reads are shared within the subgroup where
/// its lanes can serve all its blocks (glsl/common/bdpt_camera_path.glsl), so each costs mostly
/// arithmetic and shuffles: NVIDIA H200, the Cornell box 256², a BDPT sample 160.6 ms per 1024
/// spp with 1, 171.3 with 4, 173.2 with 8, 176.2 with 16 (session 38's lane-shared form; session
/// 41's groups of pixels in one loop of N trips took an H100 2 % less than that form at 8). Where it was measured at equal time (docs/results.md,
/// "Candidates shared within the subgroup"): the Cornell box -8 to -14 % MSE, the box whose
/// light hides above a panel -6 % (-22 % off the light's edge); in scenes with glossy or
/// glass surfaces, where the target's blindness to visibility and to the lobes costs more,
/// the rough Cornell box +11 %, the caustic scene level over six seeds, Sponza under its sun
/// and sky level off the sun's edge: those keep the uniform draw. VCM keeps it too.
pub fn default_connection_candidates(integrator: Integrator, features: &SceneFeatures) -> u32 {
    if resampled_diffuse_bdpt(integrator, features) {
        8
    } else {
        1
    }
}

/// The most triangles per leaf and the obvhs quality preset a BVH of `layout` is built with
/// for the integrators where `--bvh-leaf-size` / `--bvh-quality` do not say: the 4-wide BVH
/// of the wavefront forms' trace kernels at 3 and 4, as `bench traversal` measured best for
/// it (docs/traversal.md, session 17); the binary and compressed wide BVHs at 4 and 4 for
/// scenes of up to [`QUALITY_4_MAX_TRIANGLES`] triangles, at 4 and 2 beyond. NVIDIA H200,
/// `bench render`, two runs (docs/traversal.md, "Half-precision boxes, alpha masks, the
/// integrators' build"): textured Sponza 640x360 under sun and sky, 64 spp, pt-nee 53.6 ->
/// 49.8 ms, pt 41.9 -> 39.4, bdpt 69.4 -> 66.4 against leaf size 4, quality 2 (with the alpha
/// marks of the same session). obvhs builds in parallel (rayon): Sponza's 4-wide tree at
/// quality 4 in 0.31 s on the H200's 16-core host (0.14 s at quality 2; 1.5 s at quality 4 on
/// one core), the same tree on any number of threads.
///
/// Quality 4 for the binary and compressed wide BVHs (docs/results.md, "Build quality 4 for
/// every BVH"): the built-in Cornell box 256², ms per 1024 spp, NVIDIA H200, three rounds:
/// pt-nee 52.95-53.36 against 57.17-57.35, pt 30.14-30.54 against 32.64-32.79, and pt-nee on
/// the caustic scene's binary BVH 10.21-10.61 against 10.81-11.77 (H100: quality 3 level with
/// 4 over the wide BVH, behind on the binary one; leaf size 2 no better); BDPT's megakernels
/// over the wide BVH 168.3 against 176.6 (H100); on lavapipe 7-9 % for pt-nee, bdpt and pt
/// (fewer nodes per ray: primary 1.4 -> 1.2, diffuse 1.6 -> 1.4), Sponza (262,087 triangles)
/// 3 % faster, for a build of 0.98 s instead of 0.23 s on two cores. The build time grows with
/// the triangles, so larger scenes keep quality 2 and their first pixel comes no later than
/// it did. The image is the same.
pub fn default_bvh_build(layout: BvhLayout, triangles: usize) -> (u32, u32) {
    match layout {
        BvhLayout::Bvh4 => (3, 4),
        BvhLayout::Cwbvh | BvhLayout::Bvh2 if triangles <= QUALITY_4_MAX_TRIANGLES => (4, 4),
        _ => (4, 2),
    }
}

/// The most triangles [`default_bvh_build`] builds the binary and compressed wide BVHs for at
/// quality 4: about four times Sponza's, a build of some 4 s on this project's two-core CI
/// machine (about 1 s on the H200's 16-core host).
pub const QUALITY_4_MAX_TRIANGLES: usize = 1 << 20;

/// The layout `Renderer::new` builds for `integrator` on `ctx` with `settings` (`--bvh`, or
/// the default for the device, integrator and scene).
pub(super) fn auto_bvh_layout(ctx: &Context, settings: &RenderSettings, integrator: Integrator, features: &SceneFeatures) -> BvhLayout {
    // BDPT's and VCM's queue is on unless `--shadow-queue off` (default_camera_pass_queue).
    let queued = settings.shadow_queue != Some(None);
    let default = || match wavefront(ctx, settings, integrator, features) {
        true => wavefront_bvh_layout(on_cpu(ctx)),
        false => default_bvh_layout(on_cpu(ctx), integrator, features, queued),
    };
    settings.bvh_layout.unwrap_or_else(default)
}

/// Whether `ctx` runs on the CPU (llvmpipe and the like), for the defaults above.
pub(super) fn on_cpu(ctx: &Context) -> bool {
    ctx.info().is_cpu()
}

#[cfg(test)]
mod default_tests {
    use super::*;
    use crate::render::vcm;

    /// The scenes of the measured table (docs/results.md, "Cornell box, session 6") by what
    /// they have, and what `auto` picked there for pt-nee on the H200.
    #[test]
    fn path_tracer_defaults_follow_the_measured_table() {
        let diffuse = SceneFeatures::default();
        let glass = SceneFeatures { glass: true, ..diffuse };
        let mirror_glass = SceneFeatures { mirror: true, glass: true, ..diffuse };
        let rough = SceneFeatures { glossy: true, glass: true, rough_glass: true, ..diffuse };
        let textured_ggx = SceneFeatures { glossy: true, textures: true, uvs: true, normals: true, ..diffuse };
        let (cw, b2) = (BvhLayout::Cwbvh, BvhLayout::Bvh2);
        // (features, pt-nee's layout, pt's layout, path regeneration)
        let gpu = [
            (diffuse, cw, cw, true),
            (glass, b2, b2, false),
            (mirror_glass, b2, b2, false),
            (rough, b2, b2, true),
            (textured_ggx, cw, b2, true),
        ];
        for (f, pt_nee, pt, regen) in gpu {
            for queued in [true, false] {
                assert_eq!(default_bvh_layout(false, Integrator::PtNee, &f, queued), pt_nee, "{f:?}");
                assert_eq!(default_bvh_layout(false, Integrator::Pt, &f, queued), pt, "{f:?}");
            }
            assert_eq!(default_path_regeneration(false, &f), regen, "{f:?}");
            // BDPT and VCM take the wide BVH on GPUs with their shadow rays queued (the
            // default), the binary one without; CPU devices take the wide one and regenerate
            // everywhere.
            assert_eq!(default_bvh_layout(false, Integrator::Bdpt(Join::Lvc(0)), &f, true), cw);
            assert_eq!(default_bvh_layout(false, Integrator::Vcm(vcm::VcmMode::FULL), &f, true), cw);
            assert_eq!(default_bvh_layout(false, Integrator::Bdpt(Join::Lvc(0)), &f, false), b2);
            assert_eq!(default_bvh_layout(false, Integrator::Vcm(vcm::VcmMode::FULL), &f, false), b2);
            assert_eq!(default_bvh_layout(true, Integrator::Bdpt(Join::Full), &f, false), cw);
            assert!(default_path_regeneration(true, &f));
            // One trace call for pt-nee's two rays: on GPUs but over the wide BVH in diffuse
            // scenes; never on CPU devices.
            assert_eq!(default_one_trace(false, BvhLayout::Cwbvh, &f), f != diffuse, "{f:?}");
            assert!(default_one_trace(false, BvhLayout::Bvh2, &f));
            assert!(!default_one_trace(true, BvhLayout::Cwbvh, &f));
            // pt-nee's shadow-ray queue: on GPUs over the wide BVH (pausing paths but in
            // diffuse scenes), never over the binary one nor on CPU devices.
            let queue = default_shadow_queue(false, pt_nee, &f);
            assert_eq!(queue.is_some(), pt_nee == cw, "{f:?}");
            assert_eq!(queue.map(|q| q.pause), (pt_nee == cw).then_some(f != diffuse), "{f:?}");
            assert_eq!(default_shadow_queue(true, BvhLayout::Cwbvh, &f), None);
            // The wavefront forms: on GPUs, the path tracers' for every scene but the diffuse
            // one, BDPT's (fixed cache joins only) likewise, and there too with one
            // connection; never on CPU devices.
            let wave = f != diffuse;
            for i in [Integrator::Pt, Integrator::PtNee] {
                assert_eq!(default_wavefront(false, i, &f), wave, "{f:?}");
                assert!(!default_wavefront(true, i, &f));
            }
            assert!(default_wavefront(false, Integrator::Bdpt(Join::Lvc(1)), &f), "{f:?}");
            assert!(!default_wavefront(true, Integrator::Bdpt(Join::Lvc(1)), &f));
            for i in [Integrator::Bdpt(Join::Lvc(2)), Integrator::Bdpt(Join::Lvc(3))] {
                assert_eq!(default_wavefront(false, i, &f), f != diffuse, "{f:?}");
                assert!(!default_wavefront(true, i, &f));
            }
            for i in [Integrator::Bdpt(Join::Lvc(0)), Integrator::Bdpt(Join::Full), Integrator::Vcm(vcm::VcmMode::FULL)] {
                assert!(!default_wavefront(false, i, &f));
            }
            // BDPT's and VCM's camera pass: on GPUs, never on CPU devices.
            assert_eq!(default_camera_pass_queue(false).map(|q| q.slots), Some(64));
            assert_eq!(default_camera_pass_queue(true), None);
        }
    }

    /// The balance heuristic for BDPT where every surface is diffuse; the power heuristic for
    /// BDPT in glossy or specular scenes and for VCM.
    #[test]
    fn mis_heuristic_follows_the_scene() {
        let diffuse = SceneFeatures::default();
        let glossy = SceneFeatures { glossy: true, ..diffuse };
        let glass = SceneFeatures { glass: true, ..diffuse };
        assert_eq!(default_mis(Integrator::Bdpt(Join::DEFAULT), &diffuse), Mis::Balance);
        assert_eq!(default_mis(Integrator::Bdpt(Join::Full), &diffuse), Mis::Balance);
        assert_eq!(default_mis(Integrator::Bdpt(Join::DEFAULT), &glossy), Mis::Power);
        assert_eq!(default_mis(Integrator::Bdpt(Join::DEFAULT), &glass), Mis::Power);
        assert_eq!(default_mis(Integrator::Vcm(vcm::VcmMode::FULL), &diffuse), Mis::Power);
    }

    /// Eight shared candidates and 0.4 light paths per pixel for BDPT's default join where
    /// every surface is diffuse; the uniform draw and one light path per pixel in glossy or
    /// specular scenes, for the other joins (the megakernel joins need one light path per
    /// pixel) and for VCM.
    #[test]
    fn connections_and_light_paths_follow_the_scene() {
        let diffuse = SceneFeatures::default();
        let glossy = SceneFeatures { glossy: true, ..diffuse };
        let glass = SceneFeatures { glass: true, ..diffuse };
        let bdpt = Integrator::Bdpt(Join::DEFAULT);
        assert_eq!((default_connection_candidates(bdpt, &diffuse), default_light_path_ratio(bdpt, &diffuse)), (8, 0.4));
        for features in [&glossy, &glass] {
            assert_eq!((default_connection_candidates(bdpt, features), default_light_path_ratio(bdpt, features)), (1, 1.0));
        }
        for other in [Integrator::Bdpt(Join::Full), Integrator::Bdpt(Join::Lvc(2)), Integrator::Vcm(vcm::VcmMode::FULL)] {
            assert_eq!((default_connection_candidates(other, &diffuse), default_light_path_ratio(other, &diffuse)), (1, 1.0));
        }
        let mut settings = RenderSettings::new(bdpt);
        assert_eq!((settings.connection_candidates_for(&diffuse), settings.light_path_ratio_for(&diffuse)), (8, 0.4));
        (settings.connection_candidates, settings.light_path_ratio) = (Some(2), Some(3.0));
        assert_eq!((settings.connection_candidates_for(&diffuse), settings.light_path_ratio_for(&diffuse)), (2, 3.0));
        // The joins without the cache ignore candidates set by hand.
        settings.integrator = Integrator::Bdpt(Join::Full);
        assert_eq!(settings.connection_candidates_for(&diffuse), 1);
    }

    /// The cache listed per slot only on GPUs and only where its entries carry a preview.
    #[test]
    fn the_cache_is_listed_per_slot_on_gpus_with_resampled_entries() {
        assert!(default_lvc_listing_per_slot(false, 8));
        assert!(default_lvc_listing_per_slot(false, 2));
        assert!(!default_lvc_listing_per_slot(false, 1));
        assert!(!default_lvc_listing_per_slot(true, 8));
    }

    /// Quality 4 up to the bound for the binary and compressed wide BVHs, 2 past it; the 4-wide
    /// one at 4 whatever the size; leaf sizes 4, 4 and 3.
    #[test]
    fn bvh_build_quality_follows_the_scene_size() {
        let n = QUALITY_4_MAX_TRIANGLES;
        for layout in [BvhLayout::Bvh2, BvhLayout::Cwbvh] {
            assert_eq!(default_bvh_build(layout, 12), (4, 4), "{layout:?}");
            assert_eq!(default_bvh_build(layout, n), (4, 4), "{layout:?}");
            assert_eq!(default_bvh_build(layout, n + 1), (4, 2), "{layout:?}");
        }
        assert_eq!(default_bvh_build(BvhLayout::Bvh4, n + 1), (3, 4));
        assert_eq!(default_bvh_build(BvhLayout::Bvh2q, 12), (4, 2));
    }

    /// The queue takes the slots asked for where they fit the budget, fewer where not, none
    /// where fewer than a handful would; the budget covers the queue, counts and paused paths.
    #[test]
    fn shadow_queue_fits_its_budget() {
        let q = ShadowQueue { slots: 192, chunk_samples: 24, pause: true };
        let fixed = pt::PAUSED_PATH_BYTES;
        let per_invocation = |slots: u64| slots * 48 + 4 + fixed;
        assert_eq!(q.fit(1000, fixed, per_invocation(192) * 1000), Some(q));
        let fewer = q.fit(1000, fixed, per_invocation(100) * 1000 + 47).expect("100 slots fit");
        assert_eq!((fewer.slots, fewer.chunk_samples, fewer.pause), (100, 24, true));
        assert_eq!(q.fit(1000, fixed, per_invocation(3) * 1000), None);
        assert_eq!(q.fit(1000, fixed, per_invocation(4) * 1000).map(|q| q.slots), Some(4));
        // BDPT's camera pass needs nothing besides its slots.
        assert_eq!(q.fit(1000, 0, (192 * 48 + 4) * 1000), Some(q));
    }
}
