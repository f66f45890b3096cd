//! BDPT's passes as wavefronts (`--wavefront` with bdpt; `glsl/kernels/bdpt_light_wavefront.comp`,
//! `bdpt_camera_wavefront.comp`): the megakernels' light and camera subpaths with their segments
//! and shadow rays (the light paths' joins to the eye; the camera paths' light samples and
//! connections) traced by the trace kernels of `crate::trace`, as the wavefront path tracer
//! does (pt_wavefront.rs). The light vertex cache between them is the megakernels'. Each pass is
//! a loop of launches (path kernel, closest-hit trace of the segments, any-hit trace of the
//! shadow rays), recorded in batches, each ending in a read of how many rays each launch
//! queued, until a launch queues none. Each pass has its slots' storage of its own, so that
//! an iteration's camera pass may run beside the next one's light pass (`record_side_by_side`).
//!
//! A pass's tail is long: on the Cornell box at 256 x 256 and 128 samples a pixel, 8 M camera
//! paths are down to 64 K after 10 launches and the last ends after 38, each launch three
//! dispatches behind barriers. So by default a pass runs `finish_at` launches and then one of
//! its finishing kernel (`bdpt_*_finish.comp`), in which every path still live runs to its end,
//! tracing its own rays; the pass is then one submission. `finish_at` follows the last pass of
//! its kind: the launch after the first that left fewer paths live (scaled by the ratio of the
//! two passes' slots) than a quarter of what the trace kernels run at once
//! (`--wavefront-finish`: `off`, or a fixed count of launches).

use std::cell::Cell;

use super::bdpt::Join;
use super::wavefront_queues::{even_batch, launch_word, queue_bytes, slot_buffer, Queues, Step, LIVE_SLOT_BYTES, STATE_BYTES};
use super::{gpu_scene::GpuScene, settings::WavefrontFinish, RenderError};
use crate::gpu::{abi, abi::BdptPush, abi::BdptWavefrontPush, kernels};
use crate::vk::{Bind, Buffer, Context, Kernel, Recorder, Result, Spec};

/// Slots BDPT's passes aim at (within the memory budget of `render::slices::sample_slices`, which the
/// light-vertex store also caps): twice the path tracer's `pt_wavefront::TARGET_SLOTS`. An
/// NVIDIA H100 (session 48, `bench render --spp 1920`, GPU ms; docs/results.md, "Megakernel
/// launches of a million invocations; BDPT's passes at 16 M slots"): the Cornell box 256²
/// 208.2 at 128 slices (8 M slots), 203.8 at 192, 201.3 at 240; the box whose light hides
/// above a panel 230.0, 226.1, 223.8. Session 22 had found 16 M level on the H200, when a
/// slot's state was twice today's.
pub const TARGET_SLOTS: u64 = 1 << 24;

/// Shadow rays a slot queues per launch at most for `join`: the light sample and the
/// connections; None where the wavefront camera pass cannot run the join (it draws a fixed
/// number of cache vertices, at most `BDPT_WF_SHADOW_RAYS - 1`).
pub fn shadow_rays_per_slot(join: Join) -> Option<u32> {
    match join {
        Join::Lvc(k) if (1..abi::BDPT_WF_SHADOW_RAYS).contains(&k) => Some(1 + k),
        _ => None,
    }
}

// The camera pass's state keeps a slot's shadow-ray count above WF_SHADOW_COUNT_SHIFT.
const _: () = assert!(abi::BDPT_WF_SHADOW_RAYS < 1 << (32 - abi::WF_SHADOW_COUNT_SHIFT));

/// Bytes per camera slot with `shadow` shadow rays: the path, its rays and hits (and its places
/// in the lists of live slots) and the shadow rays' contributions (twice: launches of alternate
/// parity; 8 bytes each, packed_contrib.glsl). A path keeps where its rays went in the queues in
/// its state.
pub fn camera_slot_bytes(shadow: u32) -> u64 {
    STATE_BYTES + queue_bytes(shadow) + LIVE_SLOT_BYTES + shadow as u64 * 2 * CAMERA_CONTRIB_BYTES
}

/// Bytes per light slot: as a camera slot's (`camera_slot_bytes`) with one shadow ray a launch
/// (the path's join to the eye), whose contribution takes 16 bytes (rgb and the film pixel).
pub const LIGHT_SLOT_BYTES: u64 = STATE_BYTES + queue_bytes(1) + LIVE_SLOT_BYTES + 2 * LIGHT_CONTRIB_BYTES;

/// A shadow ray's contribution in BIND_WF_CONTRIB: the camera pass's (`uvec2`, contrib_pack), the
/// light pass's (`uvec4`, with its film pixel).
const CAMERA_CONTRIB_BYTES: u64 = 8;
const LIGHT_CONTRIB_BYTES: u64 = 16;

/// One of BDPT's two passes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pass {
    /// The light subpaths (bdpt_light_wavefront.comp): a slot per light path of the iteration.
    Light,
    /// The camera subpaths (bdpt_camera_wavefront.comp): a slot per pixel of the window and
    /// camera sample of the iteration.
    Camera,
}

/// The launches a batch records over `slots` slots, and whether the finishing launch follows
/// them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Batch {
    pub launches: u32,
    pub finish: bool,
    pub slots: u32,
}

/// What the last finished pass of a kind left live: the segments each of its launches before
/// the finishing one queued, over how many slots.
#[derive(Clone, Debug, Default)]
struct Tail {
    segments: Vec<u32>,
    slots: u32,
}

/// Launches before the finishing one of a pass over `slots` slots, from the last pass of its
/// kind (`tail`): the launch after the first whose live paths, scaled to this pass's slots, were
/// fewer than `live`, rounded up to an even count, at least 2; where none were, four more than
/// that pass ran; 10 without one.
fn finish_at(tail: &Tail, slots: u32, live: u32) -> u32 {
    if tail.slots == 0 {
        return 10;
    }
    let scale = f64::from(slots) / f64::from(tail.slots);
    let f = match tail.segments.iter().position(|&n| f64::from(n) * scale < f64::from(live)) {
        Some(l) => l as u32 + 1,
        None => tail.segments.len() as u32 + 4,
    };
    ((f.max(2) + 1) & !1).min(abi::WF_MAX_BATCH - 2)
}

/// A pass's slots: its queues, its paths' states and their shadow rays' contributions.
struct Storage {
    queues: Queues,
    state: Buffer,
    contrib: Buffer,
    slots: u64,
}

impl Storage {
    #[allow(clippy::too_many_arguments)]
    fn new(
        ctx: &Context,
        queues: Queues,
        what: &str,
        prefix: &str,
        slots: u64,
        slot_bytes: u64,
        contrib_bytes: u64,
    ) -> std::result::Result<Self, RenderError> {
        let buffer = |name: &str, b: u64| slot_buffer(ctx, what, &format!("{prefix}.{name}"), slots, b, slot_bytes);
        Ok(Storage {
            queues,
            state: buffer("state", STATE_BYTES)?,
            // Two halves, written by launches of alternate parity (bdpt_camera_wavefront.comp).
            contrib: buffer("contrib", 2 * contrib_bytes)?,
            slots,
        })
    }
}

/// The wavefront passes' kernels and each pass's per-slot storage, for iterations of up to
/// `slots` camera slots (pixels of the window times camera samples) and `light_slots` light
/// paths.
pub struct WavefrontPasses {
    light: Kernel,
    camera: Kernel,
    /// The finishing launches' kernels (None where `finish` is Off).
    finishers: Option<[Kernel; 2]>,
    finish: WavefrontFinish,
    /// Per pass: what the last one left live, for the next one's finishing launch.
    tails: [std::cell::RefCell<Tail>; 2],
    /// Per pass (`Pass as usize`): its slots.
    storage: [Storage; 2],
    /// Launches the last light and camera pass took: sizes the first batch of the next.
    launches: [Cell<u32>; 2],
}

/// A pass's batch as `WavefrontPasses::record_step` records it: with the kernels' bindings
/// `binds`, `push`'s iteration; `start`: the batch begins the pass; its ray counts read back
/// into the pass's buffer `readback` (0 or 1: a pass may run while the host reads the last
/// one's).
#[derive(Clone, Copy)]
pub struct Run<'a> {
    pub pass: Pass,
    pub binds: &'a [Bind<'a>],
    pub push: &'a BdptPush,
    pub batch: Batch,
    pub start: bool,
    pub readback: usize,
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
        light_slots: u64,
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
        let what = "BDPT's wavefront passes";
        let (camera_prefix, light_prefix) = ("bdpt_wavefront.camera", "bdpt_wavefront.light");
        let bytes = camera_slot_bytes(shadow);
        let camera_queues = Queues::new(ctx, scene, (what, camera_prefix), slots, shadow, bytes, true)?;
        let light_queues = camera_queues.sharing(ctx, (what, light_prefix), light_slots, 1, LIGHT_SLOT_BYTES)?;
        // Each pass's kernels bound the traces' workgroups its own queues may ask for.
        let specs_for = |q: &Queues| [specs, &[q.trace_groups_spec()], &q.ray_specs()].concat();
        let (light_specs, camera_specs) = (specs_for(&light_queues), specs_for(&camera_queues));
        let light = ctx.create_kernel(&kernels::BDPT_LIGHT_WAVEFRONT, &light_specs)?;
        let camera = ctx.create_kernel(&kernels::BDPT_CAMERA_WAVEFRONT, &camera_specs)?;
        let finish = settings.wavefront_finish;
        let finishers = match finish {
            WavefrontFinish::Off => None,
            _ => Some([
                ctx.create_kernel(scene.bvh.kernel(&kernels::BDPT_LIGHT_FINISH_FORMS), &light_specs)?,
                ctx.create_kernel(scene.bvh.kernel(&kernels::BDPT_CAMERA_FINISH_FORMS), &camera_specs)?,
            ]),
        };
        let light_storage = Storage::new(ctx, light_queues, what, light_prefix, light_slots, LIGHT_SLOT_BYTES, LIGHT_CONTRIB_BYTES)?;
        let camera_storage = Storage::new(ctx, camera_queues, what, camera_prefix, slots, bytes, CAMERA_CONTRIB_BYTES * shadow as u64)?;
        Ok(WavefrontPasses {
            light,
            camera,
            finishers,
            finish,
            tails: Default::default(),
            storage: [light_storage, camera_storage],
            launches: [Cell::new(12), Cell::new(12)],
        })
    }

    pub fn kernels(&self) -> Vec<&Kernel> {
        let mut k = vec![&self.light, &self.camera];
        k.extend(self.finishers.iter().flatten());
        // (The light pass's queues trace with the camera pass's kernels.)
        k.extend(self.storage[Pass::Camera as usize].queues.kernels());
        k
    }

    fn kernel(&self, pass: Pass) -> &Kernel {
        match pass {
            Pass::Light => &self.light,
            Pass::Camera => &self.camera,
        }
    }

    pub fn bytes(&self) -> u64 {
        let [light, camera] = &self.storage;
        light.slots * LIGHT_SLOT_BYTES + camera.slots * camera_slot_bytes(camera.queues.shadow())
    }

    /// `pass`'s slots' buffers, bound beside BDPT's own.
    pub fn binds(&self, pass: Pass) -> Vec<Bind<'_>> {
        let s = &self.storage[pass as usize];
        let mut b = vec![Bind::buffer(abi::BIND_PT_SUSPENDED, &s.state), Bind::buffer(abi::BIND_WF_CONTRIB, &s.contrib)];
        b.extend(s.queues.binds());
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

    /// The first batch of `pass` over `slots` slots: launches and the finishing one (`After`'s
    /// count, or `finish_at` of the last pass's tail), or (Off) as many launches as the last
    /// such pass took, and two more.
    pub fn first_batch(&self, pass: Pass, slots: u32) -> Batch {
        let launches = match self.finish {
            WavefrontFinish::Off => return Batch { launches: even_batch(self.launches[pass as usize].get() + 2), finish: false, slots },
            WavefrontFinish::After(n) => n,
            WavefrontFinish::Auto => {
                finish_at(&self.tails[pass as usize].borrow(), slots, self.storage[pass as usize].queues.finish_below())
            }
        };
        Batch { launches, finish: true, slots }
    }

    /// Records `run`'s batch over its slots, each of its `steps` behind a barrier: its launches,
    /// each followed by the two traces, then its finishing launch if it has one, and the
    /// read-back of their ray counts. `run.start`: the batch begins the pass (its first launch
    /// starts every slot's path; `first_batch`); every other launch runs the slots the launch
    /// before listed (`Queues::record_batch`).
    pub fn record_batch(&self, rec: &mut Recorder, geometry: &[Bind], run: &Run) -> Result<()> {
        for step in self.steps(run.batch) {
            rec.concurrent(|rec| self.record_step(rec, geometry, run, step))?;
        }
        Ok(())
    }

    /// The steps of `batch` (`wavefront_queues::steps`).
    pub fn steps(&self, batch: Batch) -> Vec<Step> {
        super::wavefront_queues::steps(batch.launches, batch.finish)
    }

    /// Records the passes' `lanes` side by side, without barriers between them: each lane a
    /// run, the steps of it to record and the group of its first; the steps of all lanes in one
    /// group behind one barrier (`Recorder::concurrent`), the groups in turn. The lanes must
    /// share no storage in a group (the light and the camera pass, or a camera pass's steps after
    /// the last one's readback).
    pub fn record_side_by_side(&self, rec: &mut Recorder, geometry: &[Bind], lanes: &[(Run, &[Step], usize)]) -> Result<()> {
        let groups = lanes.iter().map(|(_, steps, first)| first + steps.len()).max().unwrap_or(0);
        for g in 0..groups {
            rec.concurrent(|rec| {
                for (run, steps, first) in lanes {
                    if let Some(&step) = g.checked_sub(*first).and_then(|i| steps.get(i)) {
                        self.record_step(rec, geometry, run, step)?;
                    }
                }
                Ok(())
            })?;
        }
        Ok(())
    }

    /// Records `step` of `run`'s batch without a barrier (inside `Recorder::concurrent`).
    pub fn record_step(&self, rec: &mut Recorder, geometry: &[Bind], run: &Run, step: Step) -> Result<()> {
        let (pass, batch) = (run.pass, run.batch);
        let queues = &self.storage[pass as usize].queues;
        let slots = batch.slots;
        match step {
            Step::Launch(l) => {
                // The launch after the pass's first starts its paths again (WF_FIRST_HITS).
                let word = launch_word(l, run.start);
                let flags = if run.start && word == 1 { abi::WF_FIRST_HITS } else { 0 };
                let push = wavefront_push(run.push, word | flags);
                queues.dispatch_path(rec, self.kernel(pass), run.binds, bytemuck::bytes_of(&push), slots, word)
            }
            Step::Finish => {
                let finisher = &self.finishers.as_ref().expect("a finishing batch has its kernels")[pass as usize];
                // Launch `launches` of the batch, over the slots the last one listed.
                let push = wavefront_push(run.push, batch.launches);
                queues.dispatch_path(rec, finisher, run.binds, bytemuck::bytes_of(&push), slots, batch.launches)
            }
            step => queues.record_step(rec, geometry, slots, (batch.launches, run.readback), step),
        }
    }

    /// After `batch` of `pass` (with `done` launches before it), its counts read back into
    /// `readback`: None where the pass is over (a launch queued no ray, or the batch finished
    /// it; what it took is remembered for the next), else the next batch (a quarter of the
    /// launches so far, at least 4).
    pub fn after_batch(&self, pass: Pass, done: u32, batch: Batch, readback: usize) -> Result<Option<Batch>> {
        let queued = self.storage[pass as usize].queues.queued(batch.launches, readback)?;
        if batch.finish {
            let segments = queued.iter().map(|c| c[0]).collect();
            *self.tails[pass as usize].borrow_mut() = Tail { segments, slots: batch.slots };
            return Ok(None);
        }
        Ok(match Queues::first_idle_launch(&queued) {
            Some(last) => {
                self.launches[pass as usize].set(done + last + 1);
                None
            }
            None => Some(Batch { launches: even_batch((done + batch.launches) / 4), ..batch }),
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
    fn a_pass_finishes_after_the_launch_that_left_few_paths() {
        let tail = Tail { segments: vec![1000, 800, 300, 90, 40, 10], slots: 1000 };
        // Launch 3 left 90 < 100 paths: finish at launch 4 (launches 0..=3 before it).
        assert_eq!(finish_at(&tail, 1000, 100), 4);
        // Odd counts round up, and at least 2 launches run.
        assert_eq!(finish_at(&tail, 1000, 500), 4);
        assert_eq!(finish_at(&tail, 1000, 2000), 2);
        // A pass of 8 times the slots leaves 8 times as many live: 40 x 8 < 400 at launch 4.
        assert_eq!(finish_at(&tail, 8000, 400), 6);
        // None fell below: four more than that pass ran, at most a batch's worth.
        assert_eq!(finish_at(&tail, 1000, 5), 10);
        let long = Tail { segments: vec![1000; abi::WF_MAX_BATCH as usize], slots: 1000 };
        assert_eq!(finish_at(&long, 1000, 5), abi::WF_MAX_BATCH - 2);
        // No pass yet: 10.
        assert_eq!(finish_at(&Tail::default(), 1000, 5), 10);
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
