//! The winit application: the window, the Vulkan context with its swapchain, the renderer,
//! input, and the frame loop (one frame per `about_to_wait`, so input is handled between
//! frames).

use super::controls::{FlyCamera, Motion};
use super::pacing::{FrameStats, Pacer};
use super::{fit_to_monitor, next_screenshot, ViewOptions, ViewSummary, ViewerError};
use crate::imaging;
use crate::render::{Integrator, Join, RenderError, Renderer, Tonemap, TonemapSettings};
use crate::vk::{self, Context, Image, Presented, Swapchain};
use std::collections::HashSet;
use std::path::PathBuf;
use std::sync::Arc;
use std::time::{Duration, Instant};
use winit::application::ApplicationHandler;
use winit::dpi::{PhysicalPosition, PhysicalSize};
use winit::event::{ElementState, KeyEvent, MouseButton, MouseScrollDelta, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::keyboard::{Key, KeyCode, PhysicalKey};
use winit::window::{Window, WindowId};

/// Exposure change per +/- key press, in stops.
const EXPOSURE_STEP: f32 = 0.5;
/// Longest time step a frame moves the camera by (a slow frame must not teleport it).
const MAX_STEP: Duration = Duration::from_millis(250);
/// How often the title is refreshed.
const TITLE_PERIOD: Duration = Duration::from_millis(250);

pub(super) fn run(opts: &ViewOptions) -> Result<ViewSummary, ViewerError> {
    let mut builder = EventLoop::builder();
    #[cfg(target_os = "linux")]
    {
        // Callers may run the viewer on any thread (a test's, say); X11 has no main-thread rule.
        use winit::platform::x11::EventLoopBuilderExtX11;
        builder.with_any_thread(true);
    }
    let event_loop = builder.build().map_err(|e| match e {
        winit::error::EventLoopError::RecreationAttempt => ViewerError::Window("the viewer runs only once per process".into()),
        e => ViewerError::NoDisplay(e.to_string()),
    })?;
    let mut app = App { opts, state: None, error: None, summary: None, started: false };
    let ran = event_loop.run_app(&mut app);
    app.close();
    ran.map_err(|e| ViewerError::Window(e.to_string()))?;
    if let Some(e) = app.error {
        return Err(e);
    }
    app.summary.ok_or_else(|| ViewerError::Window("the event loop ended before the window opened".into()))
}

struct App<'a> {
    opts: &'a ViewOptions,
    state: Option<State>,
    error: Option<ViewerError>,
    summary: Option<ViewSummary>,
    started: bool,
}

impl App<'_> {
    fn fail(&mut self, el: &ActiveEventLoop, e: ViewerError) {
        self.error.get_or_insert(e);
        el.exit();
    }

    /// Writes the requested screenshots and tears everything down (once).
    fn close(&mut self) {
        if let Some(mut st) = self.state.take() {
            if self.error.is_none() {
                if let Err(e) = st.save(&self.opts.screenshots, self.opts.exposure) {
                    self.error = Some(e);
                }
            }
            self.summary = Some(st.close());
        }
    }
}

impl ApplicationHandler for App<'_> {
    fn resumed(&mut self, el: &ActiveEventLoop) {
        if std::mem::replace(&mut self.started, true) {
            return;
        }
        match State::open(self.opts, el) {
            Ok(st) => {
                self.state = Some(st);
                el.set_control_flow(ControlFlow::Poll);
            }
            Err(e) => self.fail(el, e),
        }
    }

    fn window_event(&mut self, el: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        let Some(st) = self.state.as_mut() else { return };
        match st.on_event(self.opts, event) {
            Ok(true) => {}
            Ok(false) => el.exit(),
            Err(e) => self.fail(el, e),
        }
    }

    fn about_to_wait(&mut self, el: &ActiveEventLoop) {
        if el.exiting() {
            return;
        }
        let Some(st) = self.state.as_mut() else { return };
        match st.frame(self.opts) {
            Ok(Step::Continue) => el.set_control_flow(ControlFlow::Poll),
            Ok(Step::Idle) => el.set_control_flow(ControlFlow::WaitUntil(Instant::now() + Duration::from_millis(50))),
            Ok(Step::Done) => el.exit(),
            Err(e) => self.fail(el, e),
        }
    }

    fn exiting(&mut self, _el: &ActiveEventLoop) {
        self.close();
    }
}

/// What the loop does after a frame.
enum Step {
    Continue,
    /// Nothing to draw into (minimised): wait for events.
    Idle,
    /// `--frames` reached.
    Done,
}

/// Held keys and the mouse.
#[derive(Default)]
struct Input {
    held: HashSet<KeyCode>,
    dragging: bool,
    cursor: Option<PhysicalPosition<f64>>,
    /// Pixels dragged since the last frame.
    look: (f64, f64),
}

const MOVE_KEYS: [KeyCode; 6] = [KeyCode::KeyW, KeyCode::KeyA, KeyCode::KeyS, KeyCode::KeyD, KeyCode::KeyQ, KeyCode::KeyE];

impl Input {
    fn motion(&self) -> Motion {
        let axis = |pos, neg| (self.held.contains(&pos) as i8 - self.held.contains(&neg) as i8) as f32;
        Motion {
            forward: axis(KeyCode::KeyW, KeyCode::KeyS),
            right: axis(KeyCode::KeyD, KeyCode::KeyA),
            up: axis(KeyCode::KeyE, KeyCode::KeyQ),
        }
    }
}

/// Everything that lives while the window is open. `close` drops the GPU objects before the
/// context (so it can report leaks and validation messages) and the window last.
struct State {
    swapchain: Swapchain,
    display: Image,
    tonemap: Tonemap,
    renderer: Renderer,
    ctx: Context,
    window: Arc<Window>,
    fly: FlyCamera,
    pacer: Pacer,
    stats: FrameStats,
    input: Input,
    integrator: Integrator,
    exposure: f32,
    /// The swapchain must be recreated before the next frame.
    stale: bool,
    last_frame: Instant,
    title_at: Option<Instant>,
    frame_times: Vec<Duration>,
    frame_spp: Vec<u32>,
    screenshots: Vec<PathBuf>,
}

impl State {
    fn open(opts: &ViewOptions, el: &ActiveEventLoop) -> Result<State, ViewerError> {
        let (w, h) = fit_to_monitor(opts.camera.width, opts.camera.height, el.primary_monitor().map(|m| m.size()));
        let attributes = Window::default_attributes().with_title("bidir view").with_inner_size(PhysicalSize::new(w, h));
        let window = Arc::new(el.create_window(attributes).map_err(|e| ViewerError::Window(e.to_string()))?);

        let mut ctx_opts = opts.context.clone();
        for ext in vk::surface_extensions(el)? {
            if !ctx_opts.instance_extensions.contains(&ext) {
                ctx_opts.instance_extensions.push(ext);
            }
        }
        if !ctx_opts.device_extensions.contains(&vk::SWAPCHAIN_EXTENSION) {
            ctx_opts.device_extensions.push(vk::SWAPCHAIN_EXTENSION);
        }
        let ctx = Context::new(&ctx_opts)?;
        let inner = window.inner_size();
        let swapchain = Swapchain::new(&ctx, window.clone(), [inner.width, inner.height], opts.vsync)?;
        let (fw, fh) = match swapchain.extent() {
            [0, _] | [_, 0] => (w, h),
            [sw, sh] => (sw, sh),
        };
        let mut fly = FlyCamera::new(opts.camera.clone(), opts.scene.bounds());
        fly.resize(fw, fh);
        let renderer = Renderer::new(&ctx, &opts.scene, &fly.camera, opts.settings.clone())?;
        let tonemap = Tonemap::new(&ctx)?;
        let display = ctx.create_image("viewer.display", fw, fh, Tonemap::FORMAT)?;
        eprintln!(
            "view: {} on {}, {fw}x{fh}, present mode {}, swapchain {:?}",
            opts.settings.integrator.name(),
            ctx.info().name,
            swapchain.present_mode(),
            swapchain.format()
        );
        Ok(State {
            swapchain,
            display,
            tonemap,
            renderer,
            ctx,
            window,
            fly,
            pacer: Pacer::new(opts.frame_budget),
            stats: FrameStats::default(),
            input: Input::default(),
            integrator: opts.settings.integrator,
            exposure: opts.exposure,
            stale: false,
            last_frame: Instant::now(),
            title_at: None,
            frame_times: Vec::new(),
            frame_spp: Vec::new(),
            screenshots: Vec::new(),
        })
    }

    /// Handles one window event; `Ok(false)` asks to quit.
    fn on_event(&mut self, opts: &ViewOptions, event: WindowEvent) -> Result<bool, ViewerError> {
        match event {
            WindowEvent::CloseRequested => return Ok(false),
            WindowEvent::Resized(_) => self.stale = true,
            WindowEvent::Focused(false) => {
                self.input.held.clear();
                self.input.dragging = false;
            }
            WindowEvent::MouseInput { state, button: MouseButton::Left, .. } => self.input.dragging = state == ElementState::Pressed,
            WindowEvent::CursorMoved { position, .. } => {
                if let (true, Some(last)) = (self.input.dragging, self.input.cursor) {
                    self.input.look.0 += position.x - last.x;
                    self.input.look.1 += position.y - last.y;
                }
                self.input.cursor = Some(position);
            }
            WindowEvent::CursorLeft { .. } => self.input.cursor = None,
            WindowEvent::MouseWheel { delta, .. } => self.fly.scroll(match delta {
                MouseScrollDelta::LineDelta(_, y) => y,
                MouseScrollDelta::PixelDelta(p) => p.y as f32 / 40.0,
            }),
            WindowEvent::KeyboardInput { event, .. } => return self.on_key(opts, event),
            _ => {}
        }
        Ok(true)
    }

    fn on_key(&mut self, opts: &ViewOptions, event: KeyEvent) -> Result<bool, ViewerError> {
        let pressed = event.state == ElementState::Pressed;
        let PhysicalKey::Code(code) = event.physical_key else {
            return Ok(true);
        };
        if MOVE_KEYS.contains(&code) {
            if pressed {
                self.input.held.insert(code);
            } else {
                self.input.held.remove(&code);
            }
            return Ok(true);
        }
        if !pressed {
            return Ok(true);
        }
        let once = !event.repeat;
        match code {
            KeyCode::Escape => return Ok(false),
            KeyCode::Digit1 | KeyCode::Numpad1 if once => self.switch(opts, Integrator::Pt)?,
            KeyCode::Digit2 | KeyCode::Numpad2 if once => self.switch(opts, Integrator::PtNee)?,
            KeyCode::Digit3 | KeyCode::Numpad3 if once => {
                // BDPT with the join the viewer was started with, else the default one.
                let join = match opts.settings.integrator {
                    Integrator::Bdpt(j) => j,
                    _ => Join::DEFAULT,
                };
                self.switch(opts, Integrator::Bdpt(join))?
            }
            KeyCode::KeyF if once => {
                self.fly.frame_scene();
                self.apply_camera()?;
            }
            KeyCode::KeyR if once => {
                self.fly.reset();
                self.apply_camera()?;
            }
            KeyCode::KeyP if once => {
                let paths = next_screenshot(&opts.screenshot_dir);
                self.save(&paths, self.exposure)?;
            }
            KeyCode::NumpadAdd | KeyCode::Equal => self.exposure += EXPOSURE_STEP,
            KeyCode::NumpadSubtract | KeyCode::Minus => self.exposure -= EXPOSURE_STEP,
            _ => match event.logical_key.as_ref() {
                Key::Character("+") => self.exposure += EXPOSURE_STEP,
                Key::Character("-") => self.exposure -= EXPOSURE_STEP,
                _ => {}
            },
        }
        Ok(true)
    }

    /// Switches the integrator (over its own default BVH layout: `Renderer::switch_integrator`);
    /// one the device cannot run is reported and skipped.
    fn switch(&mut self, opts: &ViewOptions, integrator: Integrator) -> Result<(), ViewerError> {
        if integrator == self.integrator {
            return Ok(());
        }
        match self.renderer.switch_integrator(&opts.scene, &self.fly.camera, integrator) {
            Ok(()) => {
                self.integrator = integrator;
                self.pacer.restart();
                eprintln!("view: {}", integrator.name());
                Ok(())
            }
            Err(e @ (RenderError::Unsupported(_) | RenderError::Memory(_))) => {
                eprintln!("view: cannot switch to {}: {e}", integrator.name());
                Ok(())
            }
            Err(e) => Err(e.into()),
        }
    }

    /// Renders from the fly camera from now on. BDPT's light-vertex store grows with the
    /// window: where a bigger one does not fit, the viewer falls back to pt-nee rather than quit.
    fn apply_camera(&mut self) -> Result<(), ViewerError> {
        match self.renderer.set_camera(&self.fly.camera) {
            Err(RenderError::Memory(msg)) if matches!(self.integrator, Integrator::Bdpt(_) | Integrator::Vcm(_)) => {
                eprintln!("view: {msg}; switching to pt-nee");
                self.renderer.set_integrator(Integrator::PtNee)?;
                self.integrator = Integrator::PtNee;
                self.pacer.restart();
                Ok(self.renderer.set_camera(&self.fly.camera)?)
            }
            r => Ok(r?),
        }
    }

    /// Writes the film's current estimate to each path (EXR linear, PNG with `exposure`).
    fn save(&mut self, paths: &[PathBuf], exposure: f32) -> Result<(), ViewerError> {
        if paths.is_empty() {
            return Ok(());
        }
        let image = self.renderer.image()?;
        for p in paths {
            imaging::write_image(p, &image, exposure)?;
            eprintln!("view: saved {} ({} spp)", p.display(), self.renderer.samples());
            self.screenshots.push(p.clone());
        }
        Ok(())
    }

    /// Renders, tonemaps and presents one frame.
    fn frame(&mut self, opts: &ViewOptions) -> Result<Step, ViewerError> {
        let size = self.window.inner_size();
        if size.width == 0 || size.height == 0 {
            return Ok(Step::Idle);
        }
        if self.stale || self.swapchain.extent() != [size.width, size.height] {
            self.swapchain.resize([size.width, size.height])?;
            self.stale = false;
        }
        let [w, h] = self.swapchain.extent();
        if w == 0 || h == 0 {
            return Ok(Step::Idle);
        }
        let start = Instant::now();
        let dt = start.duration_since(self.last_frame).min(MAX_STEP);
        self.last_frame = start;

        // The film follows the window; any camera change restarts the accumulation.
        let mut moved = false;
        if (w, h) != (self.fly.camera.width, self.fly.camera.height) {
            self.fly.resize(w, h);
            self.display = self.ctx.create_image("viewer.display", w, h, Tonemap::FORMAT)?;
            moved = true;
        }
        let (dx, dy) = std::mem::take(&mut self.input.look);
        moved |= self.fly.look(dx as f32, dy as f32);
        moved |= self.fly.fly(self.input.motion(), dt.as_secs_f32());
        if moved {
            self.apply_camera()?;
        }

        let spp = self.pacer.spp();
        let t = Instant::now();
        self.renderer.pass(spp)?;
        self.pacer.update(spp, t.elapsed());
        let settings = TonemapSettings { exposure: self.exposure, bgra: self.swapchain.bgra() };
        let (renderer, tonemap, display) = (&self.renderer, &self.tonemap, &self.display);
        match self.swapchain.present(&self.ctx, display, |rec| renderer.record_tonemap(rec, tonemap, display, settings))? {
            Presented::Shown => {}
            Presented::Suboptimal => self.stale = true,
            Presented::OutOfDate => {
                self.stale = true;
                return Ok(Step::Continue);
            }
        }
        let took = start.elapsed();
        self.stats.add(took, w as u64 * h as u64 * spp as u64);
        self.frame_times.push(took);
        self.frame_spp.push(spp);
        let frames = self.frame_times.len() as u32;
        if self.title_at.is_none_or(|t| t.elapsed() >= TITLE_PERIOD) {
            self.window.set_title(&self.stats.title(&self.integrator.name(), self.renderer.samples(), self.exposure));
            self.title_at = Some(Instant::now());
        }
        if let Some((at, rw, rh)) = opts.resize_at {
            if frames == at {
                // Applied by the window system; the next frames pick the new size up.
                let _ = self.window.request_inner_size(PhysicalSize::new(rw, rh));
            }
        }
        Ok(if opts.frames == Some(frames) { Step::Done } else { Step::Continue })
    }

    /// Drops the GPU objects, then closes the context to collect validation messages.
    fn close(self) -> ViewSummary {
        let State { swapchain, display, tonemap, renderer, ctx, window, fly, integrator, frame_times, frame_spp, screenshots, .. } = self;
        let samples = renderer.samples();
        let present_mode = swapchain.present_mode();
        let device = ctx.info().name.clone();
        drop((swapchain, display, tonemap, renderer));
        let validation_messages = match ctx.close() {
            Ok(m) => m,
            Err(e) => vec![format!("closing the Vulkan context: {e}")],
        };
        drop(window);
        ViewSummary {
            frames: frame_times.len() as u32,
            samples,
            camera: fly.camera,
            integrator,
            frame_times,
            frame_spp,
            present_mode,
            device,
            screenshots,
            validation_messages,
        }
    }
}
