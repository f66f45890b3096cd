use super::RenderError;
use crate::gpu::abi;
use crate::imaging::RgbImage;
use crate::vk::{Buffer, Context, Memory, Result, VkError};

fn mib(bytes: u64) -> String {
    format!("{:.1} MiB", bytes as f64 / (1u64 << 20) as f64)
}
use glam::Vec4;

/// Progressive accumulation on the GPU: per pixel the sum of sample radiance (rgb) and the
/// number of samples that reached it (w), in float32. Counting per pixel lets samples that
/// came out NaN/Inf be dropped without biasing their pixel's average.
///
/// Light tracing (BDPT's t = 1 strategy) splats into a separate rgb buffer with atomic adds;
/// it has no per-pixel count and is divided by the number of iterations.
pub struct Film {
    pub(crate) accum: Buffer,
    pub(crate) stats: Buffer,
    pub(crate) splat: Option<Buffer>,
    /// Per-slice partial sums when a pass renders several samples of a pixel at once (see
    /// `Renderer`'s sample slices), added into `accum` by `film_slices.comp`.
    pub(crate) slices: Option<(Buffer, crate::vk::Kernel)>,
    /// Slices the buffer holds (1: none).
    pub max_slices: u32,
    pub width: u32,
    pub height: u32,
}

impl Film {
    /// A cleared film; `max_slices` > 1 adds room for that many sample slices. A film that does
    /// not fit is an error naming the flags that size it, not the internal buffer.
    pub fn new(ctx: &Context, width: u32, height: u32, with_splat: bool, max_slices: u32) -> Result<Film, RenderError> {
        let pixels = width as u64 * height as u64;
        fn too_big(what: String, flags: &'static str) -> impl FnOnce(VkError) -> RenderError {
            move |e| RenderError::Memory(format!("{what} does not fit on the GPU ({e}): lower {flags}"))
        }
        let film = || too_big(format!("the film of {width}x{height} pixels ({})", mib(pixels * 16)), "--width/--height");
        let accum = ctx.create_buffer("film.accum", pixels * 16, Memory::Device).map_err(film())?;
        let max_slices = max_slices.max(1);
        let slices = if max_slices > 1 {
            let what = format!("{max_slices} sample slices of the {width}x{height} film ({})", mib(max_slices as u64 * pixels * 16));
            Some((
                ctx.create_buffer("film.slices", max_slices as u64 * pixels * 16, Memory::Device)
                    .map_err(too_big(what, "--sample-slices or --width/--height"))?,
                ctx.create_kernel(&crate::gpu::kernels::FILM_SLICES, &[])?,
            ))
        } else {
            None
        };
        let stats = ctx.create_buffer("film.stats", abi::STAT_COUNT as u64 * 4, Memory::Device)?;
        let splat = match with_splat {
            true => Some(ctx.create_buffer("film.splat", pixels * 12, Memory::Device).map_err(film())?),
            false => None,
        };
        let f = Film { accum, stats, splat, slices, max_slices, width, height };
        f.clear(ctx)?;
        Ok(f)
    }

    pub fn clear(&self, ctx: &Context) -> Result<()> {
        ctx.submit("film clear", |rec| {
            rec.fill_buffer(&self.accum, 0);
            rec.fill_buffer(&self.stats, 0);
            if let Some(s) = &self.splat {
                rec.fill_buffer(s, 0);
            }
            Ok(())
        })
    }

    /// Average radiance per pixel after `iterations` passes of one sample per pixel.
    pub fn resolve(&self, ctx: &Context, iterations: u32) -> Result<RgbImage> {
        let acc: Vec<Vec4> = ctx.read_buffer(&self.accum)?;
        let splat: Option<Vec<f32>> = self.splat.as_ref().map(|s| ctx.read_buffer(s)).transpose()?;
        let mut img = RgbImage::new(self.width, self.height);
        let inv_iter = 1.0 / iterations.max(1) as f32;
        for (i, a) in acc.iter().take((self.width * self.height) as usize).enumerate() {
            let n = a.w.max(1.0);
            let mut c = [a.x / n, a.y / n, a.z / n];
            if let Some(s) = &splat {
                for k in 0..3 {
                    c[k] += s[3 * i + k] * inv_iter;
                }
            }
            img.data[3 * i..3 * i + 3].copy_from_slice(&c);
        }
        Ok(img)
    }

    /// The film's sums after `samples` samples per pixel (one BDPT iteration per sample).
    pub fn sums(&self, ctx: &Context, samples: u32) -> Result<crate::imaging::part::Accumulation> {
        let acc: Vec<Vec4> = ctx.read_buffer(&self.accum)?;
        let splat: Option<Vec<f32>> = self.splat.as_ref().map(|s| ctx.read_buffer(s)).transpose()?;
        let n = (self.width * self.height) as usize;
        Ok(crate::imaging::part::Accumulation {
            width: self.width,
            height: self.height,
            camera: acc.iter().take(n).map(|a| [a.x as f64, a.y as f64, a.z as f64, a.w as f64]).collect(),
            light: splat.map(|s| s.chunks_exact(3).take(n).map(|c| [c[0] as f64, c[1] as f64, c[2] as f64]).collect()),
            spp: samples as u64,
            first_hit: None,
        })
    }

    /// The slices buffer for kernels to bind (the film's own accumulation buffer stands in
    /// when there is none; kernels then write `accum` directly).
    pub(crate) fn slices_buffer(&self) -> &Buffer {
        self.slices.as_ref().map_or(&self.accum, |(b, _)| b)
    }

    /// Records the addition of the first `slices` slices into the film (nothing for 1).
    pub(crate) fn record_add_slices(&self, rec: &mut crate::vk::Recorder, slices: u32) -> Result<()> {
        if slices <= 1 {
            return Ok(());
        }
        let (buf, kernel) = self.slices.as_ref().expect("a film with sample slices");
        assert!(slices <= self.max_slices);
        let pixels = self.width * self.height;
        let push = abi::SlicesPush { pixels, slices, ..Default::default() };
        rec.dispatch(
            kernel,
            &[crate::vk::Bind::buffer(abi::BIND_ACCUM, &self.accum), crate::vk::Bind::buffer(abi::BIND_SLICES, buf)],
            bytemuck::bytes_of(&push),
            [kernel.groups_for(pixels), 1, 1],
        )
    }

    /// Rays, node visits and triangle tests counted by the integrator kernels (STAT_RAYS..).
    pub fn traversal_counts(&self, ctx: &Context) -> Result<[u32; 3]> {
        let s = ctx.read_buffer::<u32>(&self.stats)?;
        Ok([s[abi::STAT_RAYS as usize], s[abi::STAT_NODES as usize], s[abi::STAT_TRIS as usize]])
    }

    pub fn nan_samples(&self, ctx: &Context) -> Result<u32> {
        Ok(ctx.read_buffer::<u32>(&self.stats)?[abi::STAT_NAN_SAMPLES as usize])
    }
}
