//! BDPT's passes as wavefronts (`--wavefront` with bdpt; `glsl/kernels/bdpt_light_wavefront.comp`,
//! `bdpt_camera_wavefront.comp`): the megakernels' light and camera subpaths with their segments
//! and shadow rays (the light paths' joins to the eye; the camera paths' light samples and
//! connections) traced by the trace kernels of `crate::trace`, as the wavefront path tracer
//! does (pt_wavefront.rs). The light vertex cache between them is the megakernels'. Each pass is
//! a loop of launches (path kernel, closest-hit trace of the segments, any-hit trace of the
//! shadow rays), recorded in batches, each ending in a read of how many rays each launch
//! queued, until a launch queues none. The two passes share their slots' storage.

use std::cell::Cell;

use super::bdpt::Join;
use super::wavefront_queues::{even_batch, queue_bytes, slot_buffer, Queues, LIVE_SLOT_BYTES};
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

/// Bytes of a slot's path: the larger of a camera path's (`BdptCameraState`) and a light
/// path's (`BdptLightState`).
const STATE_BYTES: u64 = {
    let (camera, light) = (std::mem::size_of::<abi::BdptCameraState>(), std::mem::size_of::<abi::BdptLightState>());
    (if camera > light { camera } else { light }) as u64
};

/// Bytes per slot with `shadow` shadow rays: the path, its rays and hits (and its places in the
/// lists of live slots), the shadow rays' contributions (twice: launches of alternate parity),
/// and where its rays went in the queues. A light path queues one shadow ray a launch (its
/// join to the eye), a camera path `shadow`.
pub fn slot_bytes(shadow: u32) -> u64 {
    STATE_BYTES + queue_bytes(shadow) + LIVE_SLOT_BYTES + shadow as u64 * 2 * 16 + 16
}

/// One of BDPT's two passes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pass {
    /// The light subpaths (bdpt_light_wavefront.comp): a slot per light path of the iteration.
    Light,
    /// The camera subpaths (bdpt_camera_wavefront.comp): a slot per pixel of the window and
    /// camera sample of the iteration.
    Camera,
}

/// The wavefront passes' kernels and the per-slot storage they share, for iterations of up to
/// `slots` slots (light paths, or pixels of the window times camera samples).
pub struct WavefrontPasses {
    light: Kernel,
    camera: Kernel,
    queues: Queues,
    state: Buffer,
    contrib: Buffer,
    index: Buffer,
    slots: u64,
    shadow_per_slot: u32,
    /// Launches the last light and camera pass took: sizes the first batch of the next.
    launches: [Cell<u32>; 2],
}

impl WavefrontPasses {
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
        let what = ("BDPT's wavefront passes", "bdpt_wavefront");
        let bytes = slot_bytes(shadow);
        let queues = Queues::new(ctx, scene, what, slots, shadow, bytes, true)?;
        let specs = [specs, &[queues.trace_groups_spec()]].concat();
        let light = ctx.create_kernel(&kernels::BDPT_LIGHT_WAVEFRONT, &specs)?;
        let camera = ctx.create_kernel(&kernels::BDPT_CAMERA_WAVEFRONT, &specs)?;
        let buffer = |name: &str, b: u64| slot_buffer(ctx, what.0, &format!("{}.{name}", what.1), slots, b, bytes);
        Ok(WavefrontPasses {
            light,
            camera,
            queues,
            state: buffer("state", STATE_BYTES)?,
            // Two halves, written by launches of alternate parity (bdpt_camera_wavefront.comp).
            contrib: buffer("contrib", 2 * 16 * shadow as u64)?,
            index: buffer("queue_index", 16)?,
            slots,
            shadow_per_slot: shadow,
            launches: [Cell::new(12), Cell::new(12)],
        })
    }

    pub fn kernels(&self) -> Vec<&Kernel> {
        let mut k = vec![&self.light, &self.camera];
        k.extend(self.queues.kernels());
        k
    }

    fn kernel(&self, pass: Pass) -> &Kernel {
        match pass {
            Pass::Light => &self.light,
            Pass::Camera => &self.camera,
        }
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

    /// Slots of `pass` in an iteration of `push` (its light paths, or its camera samples on a
    /// window of `width` x `height`).
    pub fn slots_for(pass: Pass, push: &BdptPush, width: u32, height: u32) -> u32 {
        match pass {
            Pass::Light => push.light_path_total,
            Pass::Camera => crate::gpu_data::tiled_invocations(width, height) * push.camera_samples.max(1),
        }
    }

    /// Launches of the first batch of `pass`: as many as the last such pass took, and two more.
    pub fn first_batch(&self, pass: Pass) -> u32 {
        even_batch(self.launches[pass as usize].get() + 2)
    }

    /// Records a batch of `launches` launches of `pass` over `slots` slots, each followed by the
    /// two traces, and the read-back of their ray counts. `start`: the batch begins the pass
    /// (its first launch starts every slot's path; `first_batch` launches); every other launch
    /// runs the slots the launch before listed (`Queues::record_batch`).
    #[allow(clippy::too_many_arguments)]
    pub fn record_batch(
        &self,
        rec: &mut Recorder,
        pass: Pass,
        binds: &[Bind],
        geometry: &[Bind],
        push: &BdptPush,
        slots: u32,
        launches: u32,
        start: bool,
    ) -> Result<()> {
        let kernel = self.kernel(pass);
        self.queues.record_batch(rec, geometry, slots, launches, start, |rec, word| {
            let push = wavefront_push(push, word);
            self.queues.dispatch_path(rec, kernel, binds, bytemuck::bytes_of(&push), slots, word)
        })
    }

    /// After a batch of `launches` of `pass` (with `done` before it): None where a launch
    /// queued no ray (the pass is over; its length is remembered for the next), else the
    /// launches of the next batch (a quarter of those so far, at least 4).
    pub fn after_batch(&self, pass: Pass, done: u32, launches: u32) -> Result<Option<u32>> {
        Ok(match self.queues.first_idle_launch(launches)? {
            Some(last) => {
                self.launches[pass as usize].set(done + last + 1);
                None
            }
            None => Some(even_batch((done + launches) / 4)),
        })
    }
}

/// The path kernels' push constants for launch `launch` of a batch.
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
    fn only_fixed_cache_joins_run_as_a_wavefront() {
        assert_eq!(shadow_rays_per_slot(Join::Lvc(1)), Some(2));
        assert_eq!(shadow_rays_per_slot(Join::Lvc(3)), Some(4));
        assert_eq!(shadow_rays_per_slot(Join::Lvc(4)), None);
        assert_eq!(shadow_rays_per_slot(Join::Lvc(0)), None);
        assert_eq!(shadow_rays_per_slot(Join::Full), None);
        assert_eq!(shadow_rays_per_slot(Join::K(1)), None);
    }
}
