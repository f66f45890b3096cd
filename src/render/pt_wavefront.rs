//! The wavefront path tracer (`--wavefront`, `glsl/kernels/pt_wavefront.comp`): pt.comp's
//! paths with their traversal in the trace kernels of `crate::trace` (Laine, Karras & Aila
//! 2013). A pass is a loop of launches: the path kernel (scatter at the hits, start samples,
//! leave the next segment and shadow ray per slot), the closest-hit trace of the segments, the
//! any-hit trace of the shadow rays; recorded in batches, each ending in a read of how many
//! rays each launch queued, until a launch queues none, or (`--wavefront-finish`, as BDPT's
//! passes) until a finishing launch (`glsl/kernels/pt_finish.comp`) has run the rest of every
//! slot's samples, tracing their rays itself, once the slots' paths were running out.

use std::cell::Cell;

use super::integrator::{IntegratorKernels, PassInputs};
use super::wavefront_queues::{even_batch, queue_bytes, slot_buffer, Queues, STATE_BYTES};
use super::{gpu_scene::GpuScene, settings::WavefrontFinish, RenderError};
use crate::gpu::{abi, abi::PtPush, abi::PtWavefrontPush, kernels};
use crate::vk::{Bind, Buffer, Context, Kernel, Spec};

/// Bytes per slot: the path, two rays, two hits, and the pending light sample's contribution
/// (twice: launches of alternate parity).
pub const SLOT_BYTES: u64 = STATE_BYTES + queue_bytes(1) + 2 * 16;

/// Slots the wavefront integrators' passes aim for on GPUs (sample slices enough for about
/// this many): fewer leave their trace kernels' launches too short to fill the GPU. NVIDIA
/// H200, `bench render`, Sponza 640 x 360 pt-nee, 64 spp: 201 ms at 2 slices (0.46 million
/// slots), 147 at 8 and 16 (1.8 and 3.7 million), 153 at 32; Cornell box 256 x 256, 1024 spp:
/// 91 ms at 16 slices (1 million), 78 at 64 (4.2 million) (docs/results.md, "A wavefront path
/// tracer"). 8 million against 4 (session 22, "Slots for small images"): DamagedHelmet 384²
/// pt-nee 38.3 -> 35.1 ms per 456 spp, bdpt 297.9 -> 275.9; MetalRoughSpheres pt-nee 47.0 ->
/// 43.3, bdpt 128.2 -> 122.8; caustic scene 256² bdpt 206 -> 193 per 1024 spp; textured Sponza
/// 640 x 360 bdpt 500.3 -> 485.4 (its light-vertex store caps it at 24 slices), pt-nee and pt
/// level (-0.7 % / 0 %).
pub const TARGET_SLOTS: u64 = 1 << 23;

/// The wavefront path tracer's kernels and per-slot storage for passes of up to `slots` slots.
pub struct WavefrontPathTracer {
    kernel: Kernel,
    queues: Queues,
    state: Buffer,
    contrib: Buffer,
    slots: u64,
    /// Launches a pass took per sample of a slot, learnt from the last pass: sizes the first
    /// batch of the next.
    launches_per_sample: Cell<f64>,
    /// The finishing launch's kernel (None where `finish` is Off).
    finisher: Option<Kernel>,
    finish: WavefrontFinish,
    /// Launches before the finishing one per sample of a slot, learnt from the last pass.
    finish_per_sample: Cell<f64>,
}

impl WavefrontPathTracer {
    pub fn new(
        ctx: &Context,
        scene: &GpuScene,
        nee: bool,
        settings: &super::RenderSettings,
        slots: u64,
    ) -> std::result::Result<Self, RenderError> {
        if settings.count_traversal {
            return Err(RenderError::Unsupported(
                "counting traversal (`bench render --count`) is for the megakernels: add --wavefront off".into(),
            ));
        }
        let mut specs = scene.features.specs();
        specs.push(Spec { id: abi::SPEC_TRI_TEST, value: scene.bvh.tri_test.spec_value() });
        specs.push(Spec { id: abi::SPEC_NEE, value: nee as u32 });
        specs.push(settings.sampler.spec());
        let what = ("the wavefront path tracer", "pt_wavefront");
        let queues = Queues::new(ctx, scene, what, slots, 1, SLOT_BYTES, false)?;
        specs.extend(queues.ray_specs());
        let kernel = ctx.create_kernel(&kernels::PT_WAVEFRONT, &specs)?;
        let finish = settings.wavefront_finish;
        let finisher = match finish {
            WavefrontFinish::Off => None,
            _ => Some(ctx.create_kernel(scene.bvh.kernel(&kernels::PT_FINISH_FORMS), &specs)?),
        };
        let buffer = |name: &str, bytes: u64| slot_buffer(ctx, what.0, &format!("{}.{name}", what.1), slots, bytes, SLOT_BYTES);
        Ok(WavefrontPathTracer {
            kernel,
            queues,
            state: buffer("state", STATE_BYTES)?,
            // Two halves, written by launches of alternate parity (pt_wavefront.glsl).
            contrib: buffer("contrib", 2 * 16)?,
            slots,
            launches_per_sample: Cell::new(8.0),
            finisher,
            finish,
            finish_per_sample: Cell::new(8.0),
        })
    }
}

/// Launches of the next batch: the first of a pass sized by what the last pass took per
/// sample of a slot (a few more, so most passes take one batch), later ones a quarter of the
/// launches so far (the tail of the longest paths); even (`even_batch`).
fn batch_launches(first: bool, samples_per_slot: u32, launches_per_sample: f64, done: u32) -> u32 {
    even_batch(match first {
        true => (samples_per_slot as f64 * launches_per_sample * 1.1).ceil() as u32 + 2,
        false => done / 4,
    })
}

/// The finishing threshold `full` of a pass over all `capacity` slots, for a pass over `slots`
/// of them (at least 1).
fn scaled_threshold(full: u32, slots: u64, capacity: u64) -> u32 {
    ((full as u64 * slots.min(capacity)) / capacity.max(1)).max(1) as u32
}

/// Launches before a pass's finishing one (`finish`, not Off): `After(n)`'s n, else the last
/// pass's launches per sample of a slot times this pass's samples; even, at least 2 (recorded
/// in batches of at most `WF_MAX_BATCH`).
fn finish_launches(finish: WavefrontFinish, samples_per_slot: u32, finish_per_sample: f64) -> u32 {
    let n = match finish {
        WavefrontFinish::After(n) => n,
        _ => (samples_per_slot as f64 * finish_per_sample).ceil().min(f64::from(u32::MAX / 2)) as u32,
    };
    (n.max(2) + 1) & !1
}

impl IntegratorKernels for WavefrontPathTracer {
    fn kernels(&self) -> Vec<&Kernel> {
        let mut k = vec![&self.kernel];
        k.extend(self.finisher.iter());
        k.extend(self.queues.kernels());
        k
    }

    fn storage_bytes(&self) -> u64 {
        self.slots * SLOT_BYTES
    }

    fn sized_by_pixels(&self) -> bool {
        true
    }

    fn wavefront(&self) -> bool {
        true
    }

    fn pass(&self, ctx: &Context, inputs: &PassInputs, first: u32, spp: u32) -> std::result::Result<(), RenderError> {
        let (scene, film) = (inputs.scene, inputs.film);
        let pt = super::pt::pt_push(inputs, first, spp);
        let slices = pt.slices.max(1);
        let push = PtWavefrontPush { pt: PtPush { slices, ..pt }, ..Default::default() };
        let slots = crate::gpu_data::tiled_invocations(film.width, film.height) * slices;
        assert!(slots as u64 <= self.slots, "a pass of {slots} slots on storage for {}", self.slots);
        let geometry = scene.binds();
        let mut binds = geometry.clone();
        binds.extend([
            Bind::buffer(abi::BIND_ACCUM, &film.accum),
            Bind::buffer(abi::BIND_RENDER_STATS, &film.stats),
            Bind::buffer(abi::BIND_SLICES, film.slices_buffer()),
            Bind::buffer(abi::BIND_PT_SUSPENDED, &self.state),
            Bind::buffer(abi::BIND_WF_CONTRIB, &self.contrib),
        ]);
        binds.extend(self.queues.binds());
        let samples_per_slot = spp.div_ceil(slices);
        // With a finishing launch: after `finish_at` launches (in batches of at most
        // WF_MAX_BATCH), and the first launch that left fewer segments than `live`, for the
        // next pass's count. `live` is the threshold of a pass over all the slots, scaled to this
        // pass's: a smaller pass (a time-budgeted render's first ones, a remainder) starts with
        // fewer paths and would cross the whole threshold launches early, and the next full
        // pass, finishing that early, would run most of its paths in the finishing kernel.
        let finish_at = self.finisher.as_ref().map(|_| finish_launches(self.finish, samples_per_slot, self.finish_per_sample.get()));
        let live = scaled_threshold(self.queues.finish_below(), slots as u64, self.slots);
        let mut first_below = None;
        let mut done = 0u32;
        loop {
            let (launches, finishing) = match finish_at {
                Some(f) => {
                    let n = (f - done).min(abi::WF_MAX_BATCH);
                    (n, done + n == f)
                }
                None => (batch_launches(done == 0, samples_per_slot, self.launches_per_sample.get(), done), false),
            };
            ctx.submit("wavefront path tracing", |rec| {
                if done == 0 {
                    // Every slot starts its pass fresh with nothing pending (the state's queue word:
                    // no contribution is read unless it says one is pending); slices sum from 0.
                    rec.fill_buffer(&self.state, 0);
                    if slices > 1 {
                        rec.fill_buffer(film.slices_buffer(), 0);
                    }
                }
                // Every launch runs every slot (the queues without lists of live slots).
                self.queues.record_batch(rec, &geometry, slots, (launches, 0), false, |rec, launch| {
                    let push = PtWavefrontPush { launch, ..push };
                    self.queues.dispatch_path(rec, &self.kernel, &binds, bytemuck::bytes_of(&push), slots, launch)
                })?;
                if let Some(finisher) = self.finisher.as_ref().filter(|_| finishing) {
                    let push = PtWavefrontPush { launch: launches, ..push };
                    self.queues.dispatch_path(rec, finisher, &binds, bytemuck::bytes_of(&push), slots, launches)?;
                }
                Ok(())
            })?;
            let queued = self.queues.queued(launches, 0)?;
            if first_below.is_none() {
                first_below = queued.iter().position(|c| c[0] < live).map(|l| done + l as u32);
            }
            // The first launch that queued no ray ends the pass (the rest found nothing to do).
            match Queues::first_idle_launch(&queued) {
                Some(last) => {
                    done += last + 1;
                    break;
                }
                None if finishing => {
                    done += launches + 1;
                    break;
                }
                None => done += launches,
            }
        }
        self.launches_per_sample.set(done as f64 / samples_per_slot as f64);
        if let (Some(f), WavefrontFinish::Auto) = (finish_at, self.finish) {
            // The launch after the first that left few paths; where none did, four more.
            let next = first_below.map_or(f + 4, |l| l + 1);
            self.finish_per_sample.set(f64::from(next) / samples_per_slot as f64);
            if std::env::var_os("BIDIR_WF_LOG").is_some() {
                eprintln!(
                    "wavefront path tracing pass over {slots} slots, {samples_per_slot} samples each: finished after {f} launches, below {live} live segments after {}; next: {:.2} launches a sample",
                    first_below.map_or("none".to_string(), |l| (l + 1).to_string()),
                    self.finish_per_sample.get()
                );
            }
        }
        if slices > 1 {
            ctx.submit("wavefront film", |rec| film.record_add_slices(rec, slices))?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_finishing_threshold_scales_with_the_pass_slots() {
        assert_eq!(scaled_threshold(16_896, 8 << 20, 8 << 20), 16_896);
        assert_eq!(scaled_threshold(16_896, 1 << 20, 8 << 20), 2_112);
        assert_eq!(scaled_threshold(16_896, 10, 8 << 20), 1, "never 0: a launch must be able to fall below it");
        assert_eq!(scaled_threshold(100, 1 << 30, 1 << 20), 100, "not above the whole");
    }

    #[test]
    fn finishing_launches_scale_with_the_samples_and_stay_even() {
        assert_eq!(finish_launches(WavefrontFinish::Auto, 8, 6.0), 48);
        assert_eq!(finish_launches(WavefrontFinish::Auto, 3, 2.5), 8);
        assert_eq!(finish_launches(WavefrontFinish::Auto, 1, 0.1), 2);
        assert_eq!(finish_launches(WavefrontFinish::After(6), 100, 9.0), 6);
    }

    #[test]
    fn batches_cover_the_pass_and_stay_bounded() {
        // The first batch of a pass: the last pass's launches per sample, 10 % and 2 more, even.
        assert_eq!(batch_launches(true, 8, 6.0, 0), 56);
        assert_eq!(batch_launches(true, 1, 1.0, 0), 4);
        assert_eq!(batch_launches(true, 1000, 8.0, 0), abi::WF_MAX_BATCH);
        // Later ones: a quarter of the launches so far, at least 4, even.
        assert_eq!(batch_launches(false, 8, 6.0, 56), 14);
        assert_eq!(batch_launches(false, 8, 6.0, 5), 4);
    }
}
