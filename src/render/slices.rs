//! Sample slices: how many samples of each pixel one pass renders at once (one invocation or
//! slot each, `RenderSettings::sample_slices`), sized per device and integrator so that the
//! kernels get enough work a launch within the memory their slots and BDPT's light-vertex
//! store may take.

use super::gpu_scene::GpuScene;
use super::{bdpt, bdpt_wavefront, defaults::on_cpu, defaults::wavefront, pt, pt_wavefront, shadow_queue, Integrator, RenderSettings};
use crate::imaging::Crop;
use crate::vk::Context;

/// Invocations of a megakernel launch that keep a large GPU busy: about four times the
/// 270,336 threads an H100 keeps resident (132 SMs x 2,048), so that a launch's tail of slow
/// paths is short beside it. Session 1 chose 2^18; in session 48 an H100 (`bench render`, GPU
/// ms, two rounds; docs/results.md, "Megakernel launches of a million invocations") rendered
/// the Cornell box 256² with pt-nee in 53.08 ms per 1024 spp at 4 slices (2^18), 48.7 at 8,
/// 47.1 at 12, 46.9 at 16 (2^20), 49.6 at 24, 50.7 at 32 (the shadow-ray queue shrinking within
/// its budget); at 2^20 pt gained 9 %, bdpt:full 21 %, vcm 11 %, the hidden light's pt-nee 12 %.
const TARGET_INVOCATIONS: u64 = 1 << 20;
/// Most GPU memory the automatic sample slices may give BDPT's light-vertex store.
const SLICED_STORE_BYTES: u64 = 1 << 30;
/// Most automatic sample slices of a megakernel (a 64 x 64 image and smaller: 2^20 invocations).
const MAX_SLICES: u64 = 256;
/// Most automatic sample slices of a wavefront form: enough for 4 million slots in a 64 x 64
/// image (TARGET_SLOTS is 8 million). Capped at 64 (the megakernels' cap then) they left small
/// images a quarter of the slots or less, and the launches' fixed costs over too few rays:
/// NVIDIA H200, bdpt, ms per 512 spp, at 4 million slots then (session 22, docs/results.md,
/// "Slots for small images"): caustic scene 128² 48.8 at 64 slices, 26.6 at 256 (megakernels
/// 33.3); DamagedHelmet 128² 90.3 against 40.6 (megakernels 94.4).
const MAX_WAVEFRONT_SLICES: u64 = 1024;

/// Sample slices for a film of `pixels` pixels (see `RenderSettings::sample_slices`) of
/// `scene`: a megakernel's by `megakernel_slices`; the wavefront forms take more, as their
/// trace kernels need many rays per launch (`pt_wavefront::TARGET_SLOTS`,
/// `bdpt_wavefront::TARGET_SLOTS`), within the memory their slots (and BDPT's light-vertex
/// store) may take.
pub(super) fn sample_slices(ctx: &Context, settings: &RenderSettings, scene: &GpuScene, pixels: u32) -> u32 {
    if settings.sample_slices > 0 {
        return settings.sample_slices;
    }
    if on_cpu(ctx) {
        return 1;
    }
    let wave = wavefront(ctx, settings, settings.integrator, &scene.features);
    let mut s = if wave {
        let (slot_bytes, target) = match settings.integrator {
            // BDPT's passes each have their slots: a pixel's camera sample's, and `ratio` light
            // paths'.
            Integrator::Bdpt(join) => {
                let camera = bdpt_wavefront::camera_slot_bytes(bdpt_wavefront::shadow_rays_per_slot(join).unwrap_or(1));
                let ratio = settings.light_path_ratio_for(&scene.estimator_features) as f64;
                ((camera as f64 + bdpt_wavefront::LIGHT_SLOT_BYTES as f64 * ratio).ceil() as u64, bdpt_wavefront::TARGET_SLOTS)
            }
            _ => (pt_wavefront::SLOT_BYTES, pt_wavefront::TARGET_SLOTS),
        };
        wavefront_slices(pixels, slot_bytes, shadow_queue::budget(ctx), target)
    } else {
        megakernel_slices(pixels, shadow_queue::budget(ctx))
    };
    if settings.integrator.stores_light_vertices() {
        // A slice's store as `Bdpt::new` allocates it, so that the slices' store fits the limit.
        let merges = matches!(settings.integrator, Integrator::Vcm(m) if m.merge);
        let ratio = settings.light_path_ratio_for(&scene.estimator_features);
        let per_sample = bdpt::store_bytes_per_sample(pixels, ratio, settings.light_path_len, &scene.features, merges);
        // BDPT's wavefront passes want millions of slots, so their iterations may take more
        // light paths: the store may grow to the shadow queue's budget (a sixteenth of the
        // device's memory, within one buffer's range). NVIDIA H200, textured Sponza 640 x 360
        // bdpt, 64 spp, the camera pass alone as a wavefront (session 19): 169.7 ms at 2
        // slices, 126.8 at 4, 112.3 at 6 (a 1 GiB store), 97.9 at 12, 91.5 at 19; both passes
        // (session 20): 101.4 at 8, 91.9 at 12, 82.7 at 19 (the default there; docs/results.md,
        // "BDPT's light pass as a wavefront").
        let budget = if wave { SLICED_STORE_BYTES.max(shadow_queue::budget(ctx)) } else { SLICED_STORE_BYTES };
        let limit = budget.min(ctx.info().max_storage_buffer_range as u64);
        s = s.min(store_slices(per_sample, limit));
    }
    s as u32
}

/// Sample slices whose light-vertex store (`per_sample` bytes a slice) fits in `limit` bytes;
/// at least 1.
fn store_slices(per_sample: u64, limit: u64) -> u64 {
    (limit / per_sample.max(1)).max(1)
}

/// A megakernel's sample slices for `pixels` pixels: about TARGET_INVOCATIONS invocations a
/// launch, fewer (down to session 1's 2^18) where the shadow-ray queue's `budget` would then
/// leave an invocation fewer than 64 slots (a small GPU: the queue's budget is a sixteenth of
/// its memory; pt-nee's paused path counted, the most an invocation adds). The H100's 2^20
/// invocations kept 85 slots and lost nothing to the queue's size (64 slots: 47.03 ms, 192:
/// 49.99), but a queue too small to hold a launch's shadow rays sends them to the in-kernel
/// traversal.
fn megakernel_slices(pixels: u32, budget: u64) -> u64 {
    let per_invocation = shadow_queue::invocation_bytes(64, pt::PAUSED_PATH_BYTES);
    let invocations = (budget / per_invocation).clamp(1 << 18, TARGET_INVOCATIONS);
    invocations.div_ceil(pixels.max(1) as u64).clamp(1, MAX_SLICES)
}

/// A wavefront form's sample slices for `pixels` pixels: about `target` slots of
/// `slot_bytes`, as many as fit in `budget` bytes, at most MAX_WAVEFRONT_SLICES.
fn wavefront_slices(pixels: u32, slot_bytes: u64, budget: u64, target: u64) -> u64 {
    let slots = target.min(budget / slot_bytes.max(1));
    slots.div_ceil(pixels.max(1) as u64).clamp(1, MAX_WAVEFRONT_SLICES)
}

/// The pixels that size the sample slices: BDPT's light paths are the full image's
/// whatever the window (so a crop's iterations are the full render's), a path tracer's
/// invocations are the window's.
pub(super) fn slice_pixels(settings: &RenderSettings, full_pixels: u32, window: Crop) -> u32 {
    if settings.integrator.stores_light_vertices() {
        full_pixels
    } else {
        window.pixels() as u32
    }
}

#[cfg(test)]
mod slice_tests {
    use super::*;
    use crate::gpu_data::SceneFeatures;

    /// Megakernels get 2^20 invocations a launch where the shadow-ray queue's budget keeps 64
    /// slots each (the H100's and H200's 4 GiB), down to 2^18 on small GPUs.
    #[test]
    fn megakernel_slices_follow_the_queue_budget() {
        let large = 4095u64 << 20;
        assert_eq!(megakernel_slices(256 * 256, large), 16);
        assert_eq!(megakernel_slices(128 * 128, large), 64);
        assert_eq!(megakernel_slices(64 * 64, large), MAX_SLICES);
        assert_eq!(megakernel_slices(32 * 32, large), MAX_SLICES, "capped");
        assert_eq!(megakernel_slices(1920 * 1080, large), 1);
        // A 16 GiB GPU's 1 GiB budget: 64 slots for about 338,000 invocations.
        assert_eq!(megakernel_slices(256 * 256, 1 << 30), 6);
        // A 4 GiB GPU's 256 MiB: session 1's 2^18.
        assert_eq!(megakernel_slices(256 * 256, 1 << 28), 4);
    }

    /// The light-vertex store caps the slices by the vertices it holds: the Cornell box 256² at
    /// 0.4 light paths per pixel within a 4 GiB buffer takes 320 slices of 64-byte vertices
    /// (diffuse scenes), 213 of whole 96-byte ones (glossy scenes, VCM's merging; diffuse scenes
    /// too before session 51); the slices' store fits the limit with the light paths counted
    /// as `Bdpt::new` counts them (rounded: 101² x 0.5 is 5,101; truncated, 5,100 overflowed).
    #[test]
    fn the_store_caps_the_slices_by_its_vertex_size() {
        let limit = u32::MAX as u64;
        let diffuse = SceneFeatures::default();
        let glossy = SceneFeatures { glossy: true, ..diffuse };
        let cornell = |features: &SceneFeatures, merges| bdpt::store_bytes_per_sample(256 * 256, 0.4, 8, features, merges);
        assert_eq!(cornell(&diffuse, false), 26_214 * 8 * 64);
        assert_eq!(store_slices(cornell(&diffuse, false), limit), 320);
        assert_eq!(store_slices(cornell(&glossy, false), limit), 213);
        assert_eq!(store_slices(cornell(&diffuse, true), limit), 213);
        assert_eq!(store_slices(cornell(&diffuse, false), 1), 1, "at least one");
        let per_sample = bdpt::store_bytes_per_sample(101 * 101, 0.5, 8, &diffuse, false);
        assert_eq!(per_sample, 5101 * 8 * 64);
        let limit = 5100 * 8 * 64 * 3 + 1000;
        let fit = store_slices(per_sample, limit);
        assert!(fit * per_sample <= limit, "{fit} slices of {per_sample} bytes overflow {limit} bytes");
        assert!(store_slices(5100 * 8 * 64, limit) * per_sample > limit, "truncated, the count overflows");
    }

    /// Small images get the slots a large one gets (down to 91 x 91; 4 million at 64 x 64),
    /// within the memory budget.
    #[test]
    fn wavefront_slices_fill_the_target_slots_in_small_images() {
        let (bytes, ample, pt) = (200, 1 << 40, pt_wavefront::TARGET_SLOTS);
        assert_eq!(pt, 1 << 23);
        assert_eq!(wavefront_slices(128 * 128, bytes, ample, pt), 512);
        assert_eq!(wavefront_slices(192 * 192, bytes, ample, pt), 228);
        assert_eq!(wavefront_slices(640 * 360, bytes, ample, pt), 37);
        assert_eq!(wavefront_slices(64 * 64, bytes, ample, pt), MAX_WAVEFRONT_SLICES, "capped");
        assert_eq!(wavefront_slices(1920 * 1080, bytes, ample, pt), 5);
        // A budget of a million slots: an eighth of the target.
        assert_eq!(wavefront_slices(128 * 128, bytes, bytes << 20, pt), 64);
        assert_eq!(wavefront_slices(1 << 24, bytes, 0, pt), 1);
        // BDPT's passes aim at twice the slots.
        assert_eq!(bdpt_wavefront::TARGET_SLOTS, 2 * pt_wavefront::TARGET_SLOTS);
        assert_eq!(wavefront_slices(256 * 256, bytes, ample, bdpt_wavefront::TARGET_SLOTS), 256);
    }
}
