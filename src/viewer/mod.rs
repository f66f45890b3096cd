//! `bidir view`: the progressive film in a window (winit + a Vulkan swapchain), with a fly
//! camera.
//!
//! Every frame renders a batch of samples ([`pacing`]), tonemaps the film on the GPU
//! ([`crate::render::Tonemap`]) into an RGBA8 image and copies that into the swapchain
//! ([`crate::vk::Swapchain`]); nothing is read back except for screenshots.
//!
//! **The film follows the window**: one film pixel per window pixel. A resize gives the
//! camera the window's size (same vertical field of view, so a wider window sees more at
//! the sides) and restarts the accumulation, as any camera change does. BDPT's light-vertex
//! store grows with the window; where it would exceed the device's limits the viewer says so
//! and falls back to pt-nee instead of quitting.
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

use crate::imaging::ImageIoError;
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

/// The window's starting size: the camera's, shrunk (keeping its aspect) to 90 % of the
/// monitor where it would not fit.
fn fit_to_monitor(w: u32, h: u32, monitor: Option<winit::dpi::PhysicalSize<u32>>) -> (u32, u32) {
    let Some(m) = monitor.filter(|m| m.width > 0 && m.height > 0) else {
        return (w, h);
    };
    let scale = (0.9 * m.width as f64 / w as f64).min(0.9 * m.height as f64 / h as f64);
    if scale >= 1.0 {
        return (w, h);
    }
    (((w as f64 * scale) as u32).max(1), ((h as f64 * scale) as u32).max(1))
}

/// `bidir-view-NNN.exr` and `.png` in `dir`, NNN the first number neither file uses.
fn next_screenshot(dir: &std::path::Path) -> Vec<PathBuf> {
    let mut n = 0u32;
    loop {
        let base = dir.join(format!("bidir-view-{n:03}"));
        let (exr, png) = (base.with_extension("exr"), base.with_extension("png"));
        if !exr.exists() && !png.exists() {
            return vec![exr, png];
        }
        n += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use winit::dpi::PhysicalSize;

    #[test]
    fn window_fits_the_monitor() {
        assert_eq!(fit_to_monitor(256, 256, None), (256, 256));
        assert_eq!(fit_to_monitor(256, 256, Some(PhysicalSize::new(1280, 1024))), (256, 256));
        let (w, h) = fit_to_monitor(1920, 1080, Some(PhysicalSize::new(1280, 1024)));
        assert_eq!(w, 1152);
        assert!((w as f64 / h as f64 - 1920.0 / 1080.0).abs() < 0.01);
    }

    #[test]
    fn screenshots_take_the_next_free_number() {
        let dir = std::env::temp_dir().join(format!("bidir-view-shots-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        assert_eq!(next_screenshot(&dir)[0], dir.join("bidir-view-000.exr"));
        std::fs::write(dir.join("bidir-view-000.png"), b"").unwrap();
        assert_eq!(next_screenshot(&dir), vec![dir.join("bidir-view-001.exr"), dir.join("bidir-view-001.png")]);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
