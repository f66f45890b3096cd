//! BDPT's camera pass as a wavefront (`--wavefront` with bdpt; `glsl/kernels/
//! bdpt_camera_wavefront.comp`): the megakernel's camera subpaths with their segments and
//! shadow rays (light samples and connections) traced by the trace kernels of `crate::trace`,
//! as the wavefront path tracer does (pt_wavefront.rs). The light pass, the light vertex cache
//! and the light pass's joins to the camera stay as they are. A camera pass is a loop of
//! launches (camera kernel, closest-hit trace of the segments, any-hit trace of the shadow
//! rays), recorded in batches, each ending in a read of how many rays each launch queued,
//! until a launch queues none.

use std::cell::Cell;

use super::bdpt::Join;
use super::wavefront_queues::{queue_bytes, slot_buffer, Queues};
use super::{gpu_scene::GpuScene, RenderError};
use crate::gpu::{abi, abi::BdptPush, abi::BdptWavefrontPush, kernels};
use crate::vk::{Bind, Buffer, Context, Kernel, Recorder, Result, Spec};

/// Shadow rays a slot queues per launch at most for `join`: the light sample and the
/// connections; None where the wavefront camera pass cannot run the join (it draws a fixed
/// number of cache vertices, at most `BDPT_WF_SHADOW_RAYS - 1`).
pub fn shadow_rays_per_slot(join: Join) -> Option<u32> {
    match join {
        Join::Lvc(k) if (1..abi::BDPT_WF_SHADOW_RAYS).contains(&k) => Some(1 + k),
        _ => None,
    }
}

/// Bytes per slot with `shadow` shadow rays: the path (`BdptCameraState`), its rays and hits,
/// the shadow rays' contributions (twice: launches of alternate parity), and where its rays
/// went in the queues.
pub fn slot_bytes(shadow: u32) -> u64 {
    std::mem::size_of::<abi::BdptCameraState>() as u64 + queue_bytes(shadow) + shadow as u64 * 2 * 16 + 16
}

/// The wavefront camera pass's kernel and per-slot storage for iterations of up to `slots`
/// slots (pixels of the window times camera samples).
pub struct WavefrontCameraPass {
    kernel: Kernel,
    queues: Queues,
    state: Buffer,
    contrib: Buffer,
    index: Buffer,
    slots: u64,
    shadow_per_slot: u32,
    /// Launches the last camera pass took: sizes the first batch of the next.
    launches: Cell<u32>,
}

impl WavefrontCameraPass {
    /// `specs`: the BDPT kernels' specialisation constants (without VCM's).
    pub fn new(
        ctx: &Context,
        scene: &GpuScene,
        specs: &[Spec],
        settings: &super::RenderSettings,
        join: Join,
        slots: u64,
    ) -> std::result::Result<Self, RenderError> {
        if settings.count_traversal {
            return Err(RenderError::Unsupported(
                "counting traversal (`bench render --count`) is for the megakernels: add --wavefront off".into(),
            ));
        }
        let shadow = shadow_rays_per_slot(join).ok_or_else(|| {
            RenderError::Unsupported(format!(
                "the wavefront camera pass joins through the light vertex cache with 1 to {} connections (bdpt, bdpt:lvc=N), not {}: add --wavefront off",
                abi::BDPT_WF_SHADOW_RAYS - 1,
                join.name()
            ))
        })?;
        let kernel = ctx.create_kernel(&kernels::BDPT_CAMERA_WAVEFRONT, specs)?;
        let what = ("the wavefront camera pass", "bdpt_wavefront");
        let bytes = slot_bytes(shadow);
        let buffer = |name: &str, b: u64| slot_buffer(ctx, what.0, &format!("{}.{name}", what.1), slots, b, bytes);
        Ok(WavefrontCameraPass {
            kernel,
            queues: Queues::new(ctx, scene, what, slots, shadow, bytes)?,
            state: buffer("state", std::mem::size_of::<abi::BdptCameraState>() as u64)?,
            // Two halves, written by launches of alternate parity (bdpt_camera_wavefront.comp).
            contrib: buffer("contrib", 2 * 16 * shadow as u64)?,
            index: buffer("queue_index", 16)?,
            slots,
            shadow_per_slot: shadow,
            launches: Cell::new(12),
        })
    }

    pub fn kernels(&self) -> Vec<&Kernel> {
        let [closest, any] = self.queues.kernels();
        vec![&self.kernel, closest, any]
    }

    pub fn bytes(&self) -> u64 {
        self.slots * slot_bytes(self.shadow_per_slot)
    }

    /// The slots' buffers, bound beside BDPT's own.
    pub fn binds(&self) -> Vec<Bind<'_>> {
        let mut b = vec![
            Bind::buffer(abi::BIND_PT_SUSPENDED, &self.state),
            Bind::buffer(abi::BIND_WF_CONTRIB, &self.contrib),
            Bind::buffer(abi::BIND_WF_INDEX, &self.index),
        ];
        b.extend(self.queues.binds());
        b
    }

    /// Slots of an iteration of `samples` camera samples on a window of `width` x `height`.
    pub fn slots_for(width: u32, height: u32, samples: u32) -> u32 {
        crate::gpu_data::tiled_invocations(width, height) * samples.max(1)
    }

    /// Records the start of a camera pass (every slot fresh, nothing pending) and its first
    /// batch of launches; returns how many.
    pub fn record_start(&self, rec: &mut Recorder, binds: &[Bind], geometry: &[Bind], push: &BdptPush, slots: u32) -> Result<u32> {
        rec.fill_buffer(&self.state, 0);
        rec.fill_buffer(&self.index, 0);
        let launches = even_batch(self.launches.get() + 2);
        self.record_batch(rec, binds, geometry, push, slots, launches)?;
        Ok(launches)
    }

    /// Records `launches` launches of a camera pass, each followed by the two traces, and the
    /// read-back of their ray counts.
    pub fn record_batch(
        &self,
        rec: &mut Recorder,
        binds: &[Bind],
        geometry: &[Bind],
        push: &BdptPush,
        slots: u32,
        launches: u32,
    ) -> Result<()> {
        let groups = self.kernel.groups_for(slots);
        self.queues.record_batch(rec, geometry, slots, launches, |rec, launch| {
            rec.dispatch(&self.kernel, binds, bytemuck::bytes_of(&wavefront_push(push, launch)), [groups, 1, 1])
        })
    }

    /// After a batch of `launches` (with `done` before it): None where a launch queued no ray
    /// (the pass is over; its length is remembered for the next pass), else the launches of
    /// the next batch (a quarter of those so far, at least 4).
    pub fn after_batch(&self, done: u32, launches: u32) -> Result<Option<u32>> {
        Ok(match self.queues.first_idle_launch(launches)? {
            Some(last) => {
                self.launches.set(done + last + 1);
                None
            }
            None => Some(even_batch((done + launches) / 4)),
        })
    }
}

/// Launches of a batch: `n`, at least 4 and at most `WF_MAX_BATCH`, rounded up to an even
/// number so that every batch starts at an even launch (the contributions' halves alternate
/// with the launch's parity within the pass).
fn even_batch(n: u32) -> u32 {
    const _: () = assert!(abi::WF_MAX_BATCH % 2 == 0);
    (n.clamp(4, abi::WF_MAX_BATCH) + 1) & !1
}

/// The camera kernel's push constants for launch `launch` of a batch.
fn wavefront_push(p: &BdptPush, launch: u32) -> BdptWavefrontPush {
    debug_assert_eq!(p.join, abi::JOIN_LVC);
    BdptWavefrontPush {
        camera: p.camera,
        sample_base: p.sample_base,
        seed: p.seed,
        emitter_count: p.emitter_count,
        emitter_weight: p.emitter_weight,
        max_depth: p.max_depth,
        rr_depth: p.rr_depth,
        light_path_len: p.light_path_len,
        launch,
        join_k: p.join_k,
        light_paths: p.light_paths,
        camera_samples: p.camera_samples,
        light_path_total: p.light_path_total,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn batches_are_even() {
        assert_eq!(even_batch(0), 4);
        assert_eq!(even_batch(5), 6);
        assert_eq!(even_batch(14), 14);
        assert_eq!(even_batch(1000), abi::WF_MAX_BATCH);
    }

    #[test]
    fn only_fixed_cache_joins_run_as_a_wavefront() {
        assert_eq!(shadow_rays_per_slot(Join::Lvc(1)), Some(2));
        assert_eq!(shadow_rays_per_slot(Join::Lvc(3)), Some(4));
        assert_eq!(shadow_rays_per_slot(Join::Lvc(4)), None);
        assert_eq!(shadow_rays_per_slot(Join::Lvc(0)), None);
        assert_eq!(shadow_rays_per_slot(Join::Full), None);
        assert_eq!(shadow_rays_per_slot(Join::K(1)), None);
    }
}
