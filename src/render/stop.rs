//! A request to stop rendering early (the CLI's first Ctrl-C): [`Renderer::render_spp`] and
//! [`Renderer::render_time`](super::Renderer::render_time) end after the pass in flight, and
//! a convergence run after the current integrator. Process-wide, as signals are.

use std::sync::atomic::{AtomicBool, Ordering};

static STOP: AtomicBool = AtomicBool::new(false);

/// Asks every render loop to stop after its current pass.
pub fn request_stop() {
    STOP.store(true, Ordering::SeqCst);
}

/// Whether [`request_stop`] was called.
pub fn stop_requested() -> bool {
    STOP.load(Ordering::SeqCst)
}
