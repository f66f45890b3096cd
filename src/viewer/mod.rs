//! `bidir view`: the progressive film in a window (winit + a Vulkan swapchain), with a fly
//! camera.
//!
//! Every frame renders a batch of samples ([`pacing`]), tonemaps the film on the GPU
//! ([`crate::render::Tonemap`]) into an RGBA8 image and copies that into the swapchain
//! ([`crate::vk::Swapchain`]); nothing is read back except for screenshots.
//!
//! **The film follows the window**: one film pixel per window pixel. A resize gives the
//! camera the window's size (same vertical field of view, so a wider window sees more at
//! the sides) and restarts the accumulation, as any camera change does.
//!
//! Controls: drag with the left mouse button to look, W/A/S/D to move, Q/E down/up, scroll
//! to change speed, F frames the scene, R resets the camera; 1/2/3 switch to pt / pt-nee /
//! bdpt (only the integrator's kernels are rebuilt, not the scene or its BVH); +/- change the
//! exposure by half a stop; P saves the film as EXR and PNG; Esc quits.
//!
//! The viewer may use `render` (the renderer, tonemap), `film` (screenshots), `scene` and
//! `vk` (context, swapchain); like every layer but `vk`, it has no `unsafe`.

mod app;
pub mod controls;
pub mod pacing;

use crate::film::ImageIoError;
use crate::render::{RenderError, RenderSettings};
use crate::scene::{Camera, Scene};
use crate::vk::{ContextOptions, VkError, Vsync};
use std::path::PathBuf;
use std::time::Duration;

/// What to show and how.
#[derive(Clone, Debug)]
pub struct ViewOptions {
    pub scene: Scene,
    /// The starting camera; its size is the window's starting inner size (shrunk to fit the
    /// monitor if larger).
    pub camera: Camera,
    pub settings: RenderSettings,
    /// Stops (display and PNG screenshots).
    pub exposure: f32,
    pub vsync: Vsync,
    /// Quit after this many presented frames (tests, scripted screenshots).
    pub frames: Option<u32>,
    /// Written (.exr or .png) from the film when the viewer quits.
    pub screenshots: Vec<PathBuf>,
    /// Where P saves `bidir-view-NNN.exr` / `.png`.
    pub screenshot_dir: PathBuf,
    /// A frame's target duration; batches of samples are sized to it.
    pub frame_budget: Duration,
    /// Device, validation, GPU timeout; the viewer adds the surface and swapchain extensions.
    pub context: ContextOptions,
    /// Testing: after presenting frame `.0`, ask the window system for an inner size of
    /// `.1` x `.2` pixels, as a user dragging the window's border would.
    pub resize_at: Option<(u32, u32, u32)>,
}

impl ViewOptions {
    /// Defaults: no exposure, vsync, interactive (no frame limit), 16 ms frames, P saves
    /// into the current directory.
    pub fn new(scene: Scene, camera: Camera, settings: RenderSettings) -> ViewOptions {
        ViewOptions {
            scene,
            camera,
            settings,
            exposure: 0.0,
            vsync: Vsync::On,
            frames: None,
            screenshots: Vec::new(),
            screenshot_dir: PathBuf::from("."),
            frame_budget: Duration::from_millis(16),
            context: ContextOptions::from_env(),
            resize_at: None,
        }
    }
}

/// What a viewer session did.
#[derive(Clone, Debug)]
pub struct ViewSummary {
    /// Frames presented.
    pub frames: u32,
    /// Samples per pixel in the film at the end.
    pub samples: u32,
    /// The camera at the end (its size is the film's).
    pub camera: Camera,
    pub integrator: crate::render::Integrator,
    /// Wall time of each presented frame (render, tonemap, copy, present, events).
    pub frame_times: Vec<Duration>,
    /// Samples per pixel rendered by each presented frame.
    pub frame_spp: Vec<u32>,
    pub present_mode: &'static str,
    pub device: String,
    /// Screenshot files written (on P and at the end).
    pub screenshots: Vec<PathBuf>,
    /// Every validation message of the session, destruction included (empty without
    /// validation).
    pub validation_messages: Vec<String>,
}

/// Why the viewer stopped with an error.
#[derive(Debug, thiserror::Error)]
pub enum ViewerError {
    #[error(
        "cannot open a window: {0}. The viewer needs an X display: set DISPLAY, run it as \
         `xvfb-run -a bidir view ...` on a machine without one, or render headless with `bidir render`"
    )]
    NoDisplay(String),
    #[error("window: {0}")]
    Window(String),
    #[error("{0}")]
    Usage(String),
    #[error(transparent)]
    Vk(#[from] VkError),
    #[error(transparent)]
    Render(#[from] RenderError),
    #[error("screenshot: {0}")]
    Image(#[from] ImageIoError),
}

/// Opens the window and runs until Esc, the window closing, or `opts.frames` frames.
/// Runs on any thread, but once per process (a winit limitation).
pub fn run(opts: &ViewOptions) -> Result<ViewSummary, ViewerError> {
    for s in &opts.screenshots {
        match s.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
            Some("exr") | Some("png") => {}
            _ => return Err(ViewerError::Usage(format!("{}: a screenshot must end in .exr or .png", s.display()))),
        }
    }
    if opts.frames == Some(0) {
        return Err(ViewerError::Usage("--frames must be at least 1".into()));
    }
    app::run(opts)
}
