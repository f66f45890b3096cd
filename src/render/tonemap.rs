//! The film as display bytes, on the GPU (`glsl/kernels/tonemap.comp`): what the viewer
//! shows every frame without reading the film back.

use super::film::Film;
use crate::gpu::{abi, abi::TonemapPush, kernels};
use crate::vk::{Bind, Context, Format, Image, Kernel, Recorder, Result, VkError};

/// How film values become display bytes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TonemapSettings {
    /// Stops: values are scaled by 2^exposure before clamping (as `film::write_image` does
    /// for PNG).
    pub exposure: f32,
    /// Store bytes as B, G, R, A (for B8G8R8A8 swapchains) instead of R, G, B, A.
    pub bgra: bool,
}

/// The tonemap kernel.
pub struct Tonemap {
    kernel: Kernel,
}

impl Tonemap {
    pub fn new(ctx: &Context) -> Result<Tonemap> {
        Ok(Tonemap { kernel: ctx.create_kernel(&kernels::TONEMAP, &[])? })
    }

    /// The format of the images [`Tonemap::record`] writes.
    pub const FORMAT: Format = Format::R8G8B8A8_UNORM;

    /// Records: `film`'s estimate after `iterations` passes (the value `Film::resolve`
    /// returns), exposure-scaled, clamped and sRGB-encoded, into `target`, an
    /// [`Tonemap::FORMAT`] image of the film's size.
    pub fn record(&self, rec: &mut Recorder, film: &Film, iterations: u32, target: &Image, settings: TonemapSettings) -> Result<()> {
        if (target.width(), target.height()) != (film.width, film.height) || target.format() != Self::FORMAT {
            return Err(VkError::Usage {
                name: target.name().into(),
                msg: format!(
                    "tonemap target is {}x{} {:?}; the film needs {}x{} {:?}",
                    target.width(),
                    target.height(),
                    target.format(),
                    film.width,
                    film.height,
                    Self::FORMAT
                ),
            });
        }
        let push = TonemapPush {
            width: film.width,
            height: film.height,
            inv_iterations: 1.0 / iterations.max(1) as f32,
            scale: 2f32.powf(settings.exposure),
            has_splat: film.splat.is_some() as u32,
            bgra: settings.bgra as u32,
            pad0: 0,
            pad1: 0,
        };
        // A film without splats binds its accumulation buffer in the splat slot; the kernel
        // does not read it then.
        let splat = film.splat.as_ref().unwrap_or(&film.accum);
        let binds = [
            Bind::buffer(abi::TONEMAP_BIND_ACCUM, &film.accum),
            Bind::buffer(abi::TONEMAP_BIND_SPLAT, splat),
            Bind::image(abi::TONEMAP_BIND_OUT, target),
        ];
        let wg = abi::IMAGE_WG_SIZE;
        rec.dispatch(&self.kernel, &binds, bytemuck::bytes_of(&push), [film.width.div_ceil(wg), film.height.div_ceil(wg), 1])
    }
}
