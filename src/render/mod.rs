//! Integrators on the GPU and the progressive film they accumulate into.
//!
//! ```no_run
//! # fn main() -> Result<(), Box<dyn std::error::Error>> {
//! use bidir::render::{Integrator, RenderSettings, Renderer};
//! let ctx = bidir::vk::Context::new(&bidir::vk::ContextOptions::from_env())?;
//! let scene = bidir::scene::Scene::builtin_cornell_box();
//! let camera = scene.cameras[0].clone();
//! let mut r = Renderer::new(&ctx, &scene, &camera, RenderSettings::new(Integrator::PtNee))?;
//! r.render_spp(64, |_| {})?;
//! let image = r.image()?;
//! # Ok(()) }
//! ```

mod bdpt;
mod bdpt_wavefront;
mod defaults;
pub mod env;
mod film;
mod first_hit;
pub mod gpu_scene;
mod integrator;
pub mod lights;
pub mod multi;
mod pacing;
mod pt;
mod pt_wavefront;
mod settings;
mod shadow_queue;
mod slices;
mod stop;
mod tonemap;
pub mod vcm;
mod wavefront_queues;

pub use bdpt::{Bdpt, Join};
use defaults::{auto_bvh_layout, on_cpu, resolve_shadow_queue, wavefront};
pub use defaults::{
    default_bvh_build, default_bvh_layout, default_camera_pass_queue, default_connection_candidates, default_light_path_ratio,
    default_lvc_listing_per_slot, default_mis, default_one_trace, default_path_regeneration, default_shadow_queue, default_wavefront,
    wavefront_bvh_layout, QUALITY_4_MAX_TRIANGLES,
};
pub use film::Film;
pub use gpu_scene::GpuScene;
pub use integrator::{IntegratorKernels, PassInputs};
pub use pacing::PassModel;
pub use pt::PathTracer;
pub use settings::{
    default_rr_depth, Integrator, Mis, RenderSettings, Sampler, WavefrontFinish, DEFAULT_WAVEFRONT_OVERLAP, MAX_CONNECTION_CANDIDATES,
};
pub use shadow_queue::ShadowQueue;
use slices::{sample_slices, slice_pixels};
pub use stop::{request_stop, stop_requested};
pub use tonemap::{Tonemap, TonemapSettings};

use crate::bvh::{Bvh, BvhError, BvhLayout};
use crate::gpu::abi::GpuCamera;
use crate::gpu_data::SceneFeatures;
use crate::imaging::{part::Accumulation, Crop, RgbImage};
use crate::scene::{Camera, Scene};
use crate::vk::{Context, Image, Recorder, VkError};
use std::time::{Duration, Instant};

/// Why rendering failed.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    #[error(transparent)]
    Vk(#[from] VkError),
    #[error("building the BVH: {0}")]
    Bvh(#[from] BvhError),
    #[error("camera '{0}' has an empty image ({1}x{2})")]
    EmptyImage(String, u32, u32),
    #[error("{0}")]
    Crop(String),
    #[error("{0}")]
    Unsupported(String),
    #[error("{0}")]
    Memory(String),
}

/// The integrator's kernels, storage and passes.
type Kernels = Box<dyn IntegratorKernels>;

/// A scene on the GPU with an integrator and a film.
pub struct Renderer {
    ctx: Context,
    scene: GpuScene,
    film: Film,
    kernels: Kernels,
    camera: GpuCamera,
    settings: RenderSettings,
    /// Samples per pixel accumulated so far.
    samples: u32,
    /// How long passes take, learnt from the passes so far: sizes the next one.
    pacing: PassModel,
    /// Most sample slices per pass (the film's and BDPT's storage are sized for it).
    slices: u32,
    /// Alpha and AOVs, where the settings ask for them.
    first_hit: Option<first_hit::FirstHitPass>,
}

/// The integrator kernels are built for the binary BVH of 64-byte nodes, the compressed
/// wide BVH and the 4-wide one (build.rs, `WIDE_VARIANTS`): quantised nodes would be read as
/// one of those and the image would be quietly wrong.
fn check_layout(layout: BvhLayout) -> Result<(), RenderError> {
    match layout {
        BvhLayout::Bvh2 | BvhLayout::Cwbvh | BvhLayout::Bvh4 => Ok(()),
        other => Err(RenderError::Unsupported(format!(
            "the integrators traverse bvh2, cwbvh or bvh4; the '{}' layout is for `bidir bench traversal --bvh {}`",
            other.name(),
            other.name()
        ))),
    }
}

/// How the kernels of `settings` run, for logs and image metadata (neither changes the image):
/// the BVH layout, and for pt/pt-nee whether paths are regenerated.
pub fn kernel_form(settings: &RenderSettings) -> String {
    let layout = settings.bvh.layout.name();
    match (settings.integrator, settings.path_regeneration) {
        (Integrator::Pt | Integrator::PtNee, Some(r)) => format!("{layout}, path regeneration {}", if r { "on" } else { "off" }),
        _ => layout.to_string(),
    }
}

/// The window of `camera`'s image that `settings` render (the whole image without a crop).
fn window(settings: &RenderSettings, camera: &Camera) -> Result<Crop, RenderError> {
    let crop = settings.crop.unwrap_or(Crop::full(camera.width, camera.height));
    crop.check(camera.width, camera.height).map_err(RenderError::Crop)?;
    Ok(crop)
}

/// The kernels of `integrator` for a film of `pixels` pixels (the full image's) showing
/// `window`: the integrators' registration.
fn build_kernels(
    ctx: &Context,
    scene: &GpuScene,
    integrator: Integrator,
    pixels: u32,
    window: Crop,
    settings: &RenderSettings,
    slices: u32,
) -> Result<Kernels, RenderError> {
    check_layout(scene.bvh.layout)?;
    let mut invocations = shadow_queue::invocations(window.width(), window.height(), slices);
    if integrator.stores_light_vertices() {
        invocations = bdpt::queue_invocations(invocations, pixels, settings.light_path_ratio_for(&scene.estimator_features), slices);
    }
    if settings.wavefront == Some(true) && !defaults::wavefront_supported(integrator) {
        return Err(RenderError::Unsupported(format!(
            "{} has no wavefront form (pt, pt-nee, and bdpt with the light vertex cache's 1 to 3 connections have): drop --wavefront on",
            integrator.name()
        )));
    }
    let wavefront_slots =
        wavefront(ctx, settings, integrator, &scene.features).then(|| shadow_queue::invocations(window.width(), window.height(), slices));
    let queue = resolve_shadow_queue(ctx, settings, integrator, &scene.features, scene.bvh.layout, invocations);
    Ok(match integrator {
        Integrator::Pt | Integrator::PtNee if wavefront(ctx, settings, integrator, &scene.features) => {
            let slots = shadow_queue::invocations(window.width(), window.height(), slices);
            Box::new(pt_wavefront::WavefrontPathTracer::new(ctx, scene, integrator == Integrator::PtNee, settings, slots)?)
        }
        Integrator::Pt | Integrator::PtNee => {
            // Resolved by `Renderer::new` (`None` only where kernels are built without it).
            let regenerate = settings.path_regeneration.unwrap_or(true);
            let one_trace = settings.one_trace.unwrap_or_else(|| default_one_trace(on_cpu(ctx), scene.bvh.layout, &scene.features));
            let nee = integrator == Integrator::PtNee;
            Box::new(PathTracer::new(ctx, scene, nee, settings, regenerate, one_trace, queue, invocations)?)
        }
        Integrator::Bdpt(join) => {
            Box::new(Bdpt::new(ctx, scene, pixels, settings, join, slices, None, queue, invocations, wavefront_slots)?)
        }
        Integrator::Vcm(mode) => {
            let config = bdpt::VcmConfig { mode, radius: settings.vcm_radius.resolve(0.0), alpha: settings.vcm_alpha };
            Box::new(Bdpt::new(ctx, scene, pixels, settings, Join::DEFAULT, slices, Some(config), queue, invocations, None)?)
        }
    })
}

/// Progress after a pass.
#[derive(Clone, Copy, Debug)]
pub struct Progress {
    pub samples: u32,
    pub elapsed: Duration,
}

impl Renderer {
    pub fn new(ctx: &Context, scene: &Scene, camera: &Camera, mut settings: RenderSettings) -> Result<Renderer, RenderError> {
        if camera.width == 0 || camera.height == 0 {
            return Err(RenderError::EmptyImage(camera.name.clone(), camera.width, camera.height));
        }
        let features = SceneFeatures::of(scene);
        settings.bvh.layout = auto_bvh_layout(ctx, &settings, settings.integrator, &features);
        let (leaf_size, quality) = default_bvh_build(settings.bvh.layout, scene.triangles.len());
        settings.bvh.max_leaf_tris = settings.bvh_leaf_size.unwrap_or(leaf_size);
        settings.bvh.quality = settings.bvh_quality.unwrap_or(quality);
        // Resolved once from what the scene has, so `settings()` says what runs.
        settings.path_regeneration = Some(settings.path_regeneration.unwrap_or_else(|| default_path_regeneration(on_cpu(ctx), &features)));
        check_layout(settings.bvh.layout)?;
        // VCM's relative radius becomes scene units once, so integrator switches keep it.
        settings.vcm_radius = vcm::VcmRadius::Absolute(settings.vcm_radius.resolve(scene.bounds().diagonal().length()));
        let bvh = Bvh::build(&scene.positions, &scene.triangles, &settings.bvh)?;
        let mut gscene = GpuScene::upload(ctx, scene, &bvh)?;
        if settings.all_material_code {
            gscene.features = gscene.features.with_all_material_code();
        }
        let window = window(&settings, camera)?;
        let pixels = camera.width * camera.height;
        let slices = sample_slices(ctx, &settings, &gscene, slice_pixels(&settings, pixels, window));
        let kernels = build_kernels(ctx, &gscene, settings.integrator, pixels, window, &settings, slices)?;
        let film = Film::new(ctx, window.width(), window.height(), kernels.splats(), slices)?;
        let camera = crate::gpu_data::gpu_camera_window(&crate::gpu_data::gpu_camera(camera), window);
        let first_hit = settings
            .first_hit
            .map(|aovs| first_hit::FirstHitPass::new(ctx, &gscene, settings.sampler, window.width(), window.height(), aovs))
            .transpose()?;
        Ok(Renderer {
            ctx: ctx.clone(),
            scene: gscene,
            film,
            kernels,
            camera,
            settings,
            samples: 0,
            pacing: PassModel::default(),
            slices,
            first_hit,
        })
    }

    /// Most samples of a pixel one pass renders at once (BDPT iterations hold this many
    /// camera samples, aligned to multiples of it: see [`Renderer::pass`]).
    pub fn sample_slices(&self) -> u32 {
        self.slices
    }

    /// The film's sums (camera samples, light-tracing splats) and the samples they hold,
    /// for parts that merge (`film::part`).
    pub fn sums(&self) -> Result<Accumulation, RenderError> {
        let mut sums = self.film.sums(&self.ctx, self.samples)?;
        sums.first_hit = self.first_hit.as_ref().map(|f| f.read(&self.ctx)).transpose()?;
        Ok(sums)
    }

    pub fn gpu_scene(&self) -> &GpuScene {
        &self.scene
    }
    pub fn samples(&self) -> u32 {
        self.samples
    }
    pub fn settings(&self) -> &RenderSettings {
        &self.settings
    }

    /// Clears the film (e.g. after the camera moved).
    pub fn reset(&mut self, camera: Option<&Camera>) -> Result<(), RenderError> {
        if let Some(c) = camera {
            self.camera = crate::gpu_data::gpu_camera_window(&crate::gpu_data::gpu_camera(c), window(&self.settings, c)?);
        }
        self.film.clear(&self.ctx)?;
        if let Some(f) = &self.first_hit {
            f.clear(&self.ctx)?;
        }
        self.samples = 0;
        Ok(())
    }

    /// Renders with `seed` from now on and clears the film: another seed gives an
    /// independent estimate (another scramble of the same sample sequence), which is how tests
    /// measure an estimator's own variance.
    pub fn set_seed(&mut self, seed: u32) -> Result<(), RenderError> {
        self.settings.seed = seed;
        self.reset(None)
    }

    /// The film the integrator accumulates into (for display passes such as [`Tonemap`]).
    pub fn film(&self) -> &Film {
        &self.film
    }

    /// Records the film's current estimate, tonemapped, into `target` (see [`Tonemap::record`]).
    pub fn record_tonemap(
        &self,
        rec: &mut Recorder,
        tonemap: &Tonemap,
        target: &Image,
        settings: TonemapSettings,
    ) -> crate::vk::Result<()> {
        tonemap.record(rec, &self.film, self.samples, target, settings)
    }

    /// Renders from `camera` from now on and clears the film. A camera with another image size
    /// gets a new film (and BDPT a light-vertex store for the new number of pixels); on error
    /// the renderer is unchanged.
    pub fn set_camera(&mut self, camera: &Camera) -> Result<(), RenderError> {
        if camera.width == 0 || camera.height == 0 {
            return Err(RenderError::EmptyImage(camera.name.clone(), camera.width, camera.height));
        }
        let window = window(&self.settings, camera)?;
        if (camera.width, camera.height) != (self.camera.size.x, self.camera.size.y) {
            let pixels = camera.width * camera.height;
            let slices = sample_slices(&self.ctx, &self.settings, &self.scene, slice_pixels(&self.settings, pixels, window));
            // Path tracers keep their kernels unless their shadow-ray queue is sized by the
            // film; BDPT's store is sized by the pixel count.
            let kernels = if self.kernels.sized_by_pixels() {
                Some(build_kernels(&self.ctx, &self.scene, self.settings.integrator, pixels, window, &self.settings, slices)?)
            } else {
                None
            };
            let film = Film::new(&self.ctx, window.width(), window.height(), self.kernels.splats(), slices)?;
            let first_hit_sums = self
                .first_hit
                .as_ref()
                .map(|_| first_hit::FirstHitPass::sums_buffer(&self.ctx, window.width(), window.height()))
                .transpose()?;
            if let (Some(f), Some(sums)) = (self.first_hit.as_mut(), first_hit_sums) {
                f.resize(&self.ctx, sums, window.width(), window.height())?;
            }
            if let Some(k) = kernels {
                self.kernels = k;
            }
            self.film = film;
            self.slices = slices;
        }
        self.reset(Some(camera))
    }

    /// Switches to another integrator, keeping the scene and its BVH on the GPU, and clears
    /// the film. On error the renderer is unchanged.
    pub fn set_integrator(&mut self, integrator: Integrator) -> Result<(), RenderError> {
        let pixels = self.camera.size.x * self.camera.size.y;
        let settings = self.settings.with_integrator(integrator);
        let (x0, y0) = (self.camera.window_x, self.camera.window_y);
        let window = Crop { x0, y0, x1: x0 + self.film.width, y1: y0 + self.film.height };
        let slices = sample_slices(&self.ctx, &settings, &self.scene, slice_pixels(&settings, pixels, window));
        let kernels = build_kernels(&self.ctx, &self.scene, integrator, pixels, window, &settings, slices)?;
        let film = Film::new(&self.ctx, self.film.width, self.film.height, kernels.splats(), slices)?;
        self.kernels = kernels;
        self.film = film;
        self.slices = slices;
        self.settings.rr_depth = settings.rr_depth;
        self.settings.integrator = integrator;
        self.pacing = PassModel::default();
        self.samples = 0;
        if let Some(f) = &self.first_hit {
            f.clear(&self.ctx)?;
        }
        Ok(())
    }

    /// Switches to another integrator as [`Renderer::set_integrator`] does, except that where
    /// the new integrator's BVH layout (`--bvh`, or its default for the device and scene)
    /// differs from the one on the GPU, the renderer is rebuilt over that layout from `scene`
    /// and `camera` (the ones it renders). On error the renderer is unchanged.
    pub fn switch_integrator(&mut self, scene: &Scene, camera: &Camera, integrator: Integrator) -> Result<(), RenderError> {
        if auto_bvh_layout(&self.ctx, &self.settings, integrator, &SceneFeatures::of(scene)) == self.settings.bvh.layout {
            return self.set_integrator(integrator);
        }
        *self = Renderer::new(&self.ctx, scene, camera, self.settings.with_integrator(integrator))?;
        Ok(())
    }

    /// How the kernels run, for logs and image metadata: [`kernel_form`] of the settings, the
    /// shadow-ray queue in use (with the slots that fit), and the light vertex cache's
    /// connection candidates and light paths per pixel where they are not 1 (they follow the
    /// scene by default: `default_connection_candidates`, `default_light_path_ratio`).
    pub fn kernel_form(&self) -> String {
        let mut form = match (self.kernels.shadow_queue(), self.settings.integrator) {
            (Some(q), Integrator::PtNee) => format!("{}, shadow queue {q}", kernel_form(&self.settings)),
            (Some(q), _) => format!("{}, shadow queue {}", kernel_form(&self.settings), q.slots),
            (None, _) => kernel_form(&self.settings),
        };
        if self.kernels.wavefront() {
            form += ", wavefront";
        }
        if let Integrator::Bdpt(Join::Lvc(_)) | Integrator::Vcm(_) = self.settings.integrator {
            let features = &self.scene.estimator_features;
            let candidates = self.settings.connection_candidates_for(features);
            if candidates > 1 {
                form += &format!(", {candidates} connection candidates");
            }
            let ratio = self.settings.light_path_ratio_for(features);
            if ratio != 1.0 {
                form += &format!(", {ratio} light paths per pixel");
            }
        }
        form
    }

    /// The integrator's kernels (e.g. for their compile statistics, `Kernel::statistics`).
    pub fn kernels(&self) -> Vec<&crate::vk::Kernel> {
        self.kernels.kernels()
    }

    /// Bytes of integrator-specific GPU memory (BDPT light vertices).
    pub fn integrator_bytes(&self) -> u64 {
        self.kernels.storage_bytes()
    }

    /// Renders `spp` more samples per pixel in one submission (the ones after those
    /// rendered so far, from `sample_start`).
    pub fn pass(&mut self, spp: u32) -> Result<(), RenderError> {
        self.pass_at(self.settings.sample_start + self.samples, spp)
    }

    /// Renders samples `first..first + spp` of every pixel in one submission and adds them to
    /// the film (several devices render the passes of one image this way).
    pub fn pass_at(&mut self, first: u32, spp: u32) -> Result<(), RenderError> {
        let inputs =
            PassInputs { scene: &self.scene, film: &self.film, camera: self.camera, settings: &self.settings, slices: self.slices };
        self.kernels.pass(&self.ctx, &inputs, first, spp)?;
        if let Some(f) = &self.first_hit {
            // Alpha and AOVs: the same samples' camera rays, whatever the integrator.
            let seed = self.settings.seed;
            self.ctx.submit("first-hit pass", |rec| f.record(rec, &self.scene, self.camera, first, spp, seed))?;
        }
        self.samples += spp;
        Ok(())
    }

    /// One adaptive pass, at most `max_spp` samples: sized by the pass model to take about
    /// `pass_target`, or one sample per pixel while nothing has been measured (calibration).
    fn adaptive_pass(&mut self, max_spp: u32) -> Result<u32, RenderError> {
        let first = self.settings.sample_start + self.samples;
        let mut spp = self.next_pass_spp().min(max_spp).max(1);
        if self.kernels.slice_aligned() && self.slices > 1 {
            // Whole BDPT iterations (see `pass_at`): a pass ends at a multiple of the slices
            // unless the render ends first.
            spp = ((first + spp).next_multiple_of(self.slices) - first).min(max_spp);
        }
        self.adaptive_pass_at(first, spp)?;
        Ok(spp)
    }

    /// Samples the next adaptive pass would render: sized by the pass model to take about
    /// `pass_target`, or one sample per pixel while nothing has been measured (calibration).
    pub fn next_pass_spp(&self) -> u32 {
        let target = self.settings.pass_target.as_secs_f64();
        let sized = if self.pacing.known() { self.pacing.spp_within(target) } else { 1 };
        sized.clamp(1, self.max_pass_spp())
    }

    /// Most samples per pixel a pass can render in `seconds` by the pass model (1 before
    /// anything was measured), for callers that schedule passes themselves (`multi`).
    pub fn pass_spp_within(&self, seconds: f64) -> u32 {
        if self.pacing.known() {
            self.pacing.spp_within(seconds).clamp(1, self.max_pass_spp())
        } else {
            1
        }
    }

    /// Renders samples `first..first + spp` and teaches the pass model how long it took.
    /// With `BIDIR_PASS_LOG` set, each pass prints its size, the model's prediction, the time
    /// it took, its submissions (each a host round trip) and the sample slices to stderr.
    pub fn adaptive_pass_at(&mut self, first: u32, spp: u32) -> Result<(), RenderError> {
        let predicted = self.pacing.known().then(|| self.pacing.seconds(spp));
        let submissions = self.ctx.submissions();
        let t = Instant::now();
        self.pass_at(first, spp)?;
        let took = t.elapsed().as_secs_f64();
        if std::env::var_os("BIDIR_PASS_LOG").is_some() {
            let predicted = predicted.map_or("-".to_string(), |p| format!("{:.2} ms", p * 1e3));
            let submissions = self.ctx.submissions() - submissions;
            eprintln!(
                "pass: samples {first}..{} ({spp} spp), predicted {predicted}, took {:.2} ms, {submissions} submissions, slices {}",
                first + spp,
                took * 1e3,
                self.slices
            );
        }
        self.pacing.record(spp, took);
        Ok(())
    }

    /// Most samples per pixel in one pass. On CPU devices 16: llvmpipe (Mesa's gallivm loop
    /// limiter) silently ends every loop of an invocation once it has run 65,535 iterations
    /// in all, so a pass of many samples (each one path of bounces, each bounce a traversal
    /// loop) per invocation would drop samples' light and darken the image
    /// (`furnace_many_samples_per_pass`).
    fn max_pass_spp(&self) -> u32 {
        if on_cpu(&self.ctx) {
            16
        } else {
            4096
        }
    }

    /// Renders until `spp` samples per pixel in total, or until [`request_stop`] (then after
    /// the pass in flight).
    pub fn render_spp(&mut self, spp: u32, mut progress: impl FnMut(Progress)) -> Result<(), RenderError> {
        let start = Instant::now();
        while self.samples < spp && !(self.samples > 0 && stop_requested()) {
            self.adaptive_pass(spp - self.samples)?;
            progress(Progress { samples: self.samples, elapsed: start.elapsed() });
        }
        Ok(())
    }

    /// Renders passes until `time` has passed or [`request_stop`] is called (at least one
    /// sample either way). After one calibration pass (none if this renderer has rendered
    /// before) every pass is sized by the pass model to fill what is left of the budget, up to
    /// `pass_target` and to [`PassModel::spp_within_budget`]'s growth limit, so the render
    /// runs at the GPU's steady rate from its first moments; a last pass that would overshoot
    /// the budget by more than 10 % is not started.
    pub fn render_time(&mut self, time: Duration, mut progress: impl FnMut(Progress)) -> Result<(), RenderError> {
        let start = Instant::now();
        let budget = time.as_secs_f64();
        loop {
            let left = budget - start.elapsed().as_secs_f64();
            if self.samples > 0 && (left <= 0.0 || stop_requested()) {
                break;
            }
            let cap = if !self.pacing.known() {
                1
            } else {
                match self.pacing.spp_within(left) {
                    0 if self.samples > 0 && self.pacing.seconds(1) - left > 0.1 * budget => break,
                    0 => 1,
                    _ => self.pacing.spp_within_budget(left, budget).max(1),
                }
            };
            self.adaptive_pass(cap)?;
            progress(Progress { samples: self.samples, elapsed: start.elapsed() });
        }
        Ok(())
    }

    /// The film's current estimate.
    pub fn image(&self) -> Result<RgbImage, RenderError> {
        Ok(self.film.resolve(&self.ctx, self.samples)?)
    }

    /// Samples that came out NaN or infinite and were dropped.
    /// Rays traced, inner nodes visited and triangles tested by the integrator kernels since
    /// the film was last cleared: zeros unless `RenderSettings::count_traversal` is set.
    pub fn traversal_counts(&self) -> Result<[u32; 3], RenderError> {
        Ok(self.film.traversal_counts(&self.ctx)?)
    }

    pub fn nan_samples(&self) -> Result<u32, RenderError> {
        Ok(self.film.nan_samples(&self.ctx)?)
    }
}
