use crate::film::RgbImage;
use crate::gpu::abi;
use crate::vk::{Buffer, Context, Memory, Result};
use glam::Vec4;

/// Progressive accumulation on the GPU: per pixel the sum of sample radiance (rgb) and the
/// number of samples that reached it (w), in float32. Counting per pixel lets samples that
/// came out NaN/Inf be dropped without biasing their pixel's average.
pub struct Film {
    pub(crate) accum: Buffer,
    pub(crate) stats: Buffer,
    pub width: u32,
    pub height: u32,
}

impl Film {
    pub fn new(ctx: &Context, width: u32, height: u32) -> Result<Film> {
        let accum = ctx.create_buffer("film.accum", width as u64 * height as u64 * 16, Memory::Device)?;
        let stats = ctx.create_buffer("film.stats", abi::STAT_COUNT as u64 * 4, Memory::Device)?;
        let f = Film { accum, stats, width, height };
        f.clear(ctx)?;
        Ok(f)
    }

    pub fn clear(&self, ctx: &Context) -> Result<()> {
        ctx.submit("film clear", |rec| {
            rec.fill_buffer(&self.accum, 0);
            rec.fill_buffer(&self.stats, 0);
            Ok(())
        })
    }

    /// Average radiance per pixel.
    pub fn resolve(&self, ctx: &Context) -> Result<RgbImage> {
        let acc: Vec<Vec4> = ctx.read_buffer(&self.accum)?;
        let mut img = RgbImage::new(self.width, self.height);
        for (i, a) in acc.iter().take((self.width * self.height) as usize).enumerate() {
            let n = a.w.max(1.0);
            img.data[3 * i..3 * i + 3].copy_from_slice(&[a.x / n, a.y / n, a.z / n]);
        }
        Ok(img)
    }

    pub fn nan_samples(&self, ctx: &Context) -> Result<u32> {
        Ok(ctx.read_buffer::<u32>(&self.stats)?[abi::STAT_NAN_SAMPLES as usize])
    }
}
