//! Images on the host: the resolved film, EXR/PNG files (written to a temporary file and
//! renamed, so a crash never leaves half an image), and error metrics against references.

pub mod aov;
mod crop;
mod io;
pub mod merge;
pub mod metrics;
pub mod part;

pub use crop::{Crop, SampleRange};
pub use io::{
    abort_writes, check_writable, linear_to_srgb, read_exr, to_srgb8, write_atomically, write_image, write_png_rgb8, ImageIoError,
};

/// A linear RGB float image, rows top to bottom.
#[derive(Clone, Debug, PartialEq)]
pub struct RgbImage {
    pub width: u32,
    pub height: u32,
    /// `width * height * 3` floats.
    pub data: Vec<f32>,
}

impl RgbImage {
    pub fn new(width: u32, height: u32) -> Self {
        RgbImage { width, height, data: vec![0.0; (width * height * 3) as usize] }
    }
    pub fn pixel(&self, x: u32, y: u32) -> [f32; 3] {
        let i = ((y * self.width + x) * 3) as usize;
        [self.data[i], self.data[i + 1], self.data[i + 2]]
    }
    /// Mean of each channel over the pixels whose three values are finite.
    pub fn mean(&self) -> [f64; 3] {
        let mut m = [0.0f64; 3];
        let mut n = 0usize;
        for p in self.data.chunks_exact(3).filter(|p| p.iter().all(|v| v.is_finite())) {
            for c in 0..3 {
                m[c] += p[c] as f64;
            }
            n += 1;
        }
        m.map(|x| x / n.max(1) as f64)
    }

    /// Pixels with a NaN or infinite value (they are left out of [`RgbImage::mean`] and the
    /// [`metrics`]).
    pub fn non_finite_pixels(&self) -> usize {
        self.data.chunks_exact(3).filter(|p| !p.iter().all(|v| v.is_finite())).count()
    }
}
