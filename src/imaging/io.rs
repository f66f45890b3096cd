use super::RgbImage;
use crate::limits::{thousands, MAX_IMAGE_PIXELS};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, MutexGuard};

/// Temporary files being written by [`write_atomically`], for [`abort_writes`].
static TEMPORARY: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());
/// Set by [`abort_writes`]: no new write starts.
static ABORTED: AtomicBool = AtomicBool::new(false);

fn temporary() -> MutexGuard<'static, Vec<PathBuf>> {
    TEMPORARY.lock().unwrap_or_else(|e| e.into_inner())
}

/// For an abort (the second Ctrl-C): removes the temporary file of every write in progress
/// and refuses new writes; returns how many files were removed. The caller then exits.
pub fn abort_writes() -> usize {
    let list = temporary();
    ABORTED.store(true, Ordering::SeqCst);
    list.iter().filter(|p| std::fs::remove_file(p).is_ok()).count()
}

/// Why an image could not be read or written.
#[derive(Debug, thiserror::Error)]
pub enum ImageIoError {
    #[error("{path}: unsupported image extension (use .exr or .png)")]
    Extension { path: PathBuf },
    #[error("{path}: {msg}")]
    Write { path: PathBuf, msg: String },
    #[error("{path}: cannot read EXR: {msg}")]
    Read { path: PathBuf, msg: String },
    #[error("{path}: EXR too large: its header says {width}x{height} pixels, over the limit of {} pixels", thousands(MAX_IMAGE_PIXELS))]
    TooLarge { path: PathBuf, width: u64, height: u64 },
}

/// Writes `img` as EXR (linear float RGB) or PNG (8-bit sRGB of `exposure`-scaled values,
/// clamped), chosen by extension. The file appears complete or not at all.
pub fn write_image(path: &Path, img: &RgbImage, exposure: f32) -> Result<(), ImageIoError> {
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("exr") => write_atomically(path, |tmp| write_exr(tmp, img).map_err(|e| e.to_string())),
        Some("png") => write_atomically(path, |tmp| write_png_rgb8(tmp, &to_srgb8(img, exposure), img.width, img.height)),
        _ => Err(ImageIoError::Extension { path: path.to_path_buf() }),
    }
}

/// Runs `write` on a temporary file beside `path` (hidden, named for this process) and renames
/// it onto `path`, so readers see the whole file or none of it; the temporary file is removed
/// when anything fails.
pub fn write_atomically(path: &Path, write: impl FnOnce(&Path) -> Result<(), String>) -> Result<(), ImageIoError> {
    let werr = |msg: String| ImageIoError::Write { path: path.to_path_buf(), msg };
    let tmp = temporary_path(path)?;
    {
        let mut list = temporary();
        if ABORTED.load(Ordering::SeqCst) {
            return Err(werr("aborted".into()));
        }
        list.push(tmp.clone());
    }
    let result = match write(&tmp) {
        Err(e) => Err(werr(e)),
        Ok(()) => std::fs::rename(&tmp, path).map_err(|e| werr(e.to_string())),
    };
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    temporary().retain(|p| p != &tmp);
    result
}

/// Whether `path` can be written by [`write_image`] (or [`write_atomically`]): a supported
/// extension, an existing directory, not a directory itself, and the directory writable
/// (tried by creating and removing the temporary file). Lets a command check every output
/// before it spends time rendering.
pub fn check_writable(path: &Path) -> Result<(), ImageIoError> {
    let werr = |msg: String| ImageIoError::Write { path: path.to_path_buf(), msg };
    if path.is_dir() {
        return Err(werr("is a directory".into()));
    }
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    if !dir.is_dir() {
        return Err(werr(format!("directory {} does not exist", dir.display())));
    }
    let tmp = temporary_path(path)?;
    std::fs::File::create(&tmp).map_err(|e| werr(e.to_string()))?;
    std::fs::remove_file(&tmp).map_err(|e| werr(e.to_string()))
}

/// The temporary file beside `path`: hidden, named for this process.
fn temporary_path(path: &Path) -> Result<PathBuf, ImageIoError> {
    let file_name = path.file_name().ok_or_else(|| ImageIoError::Write { path: path.to_path_buf(), msg: "not a file path".into() })?;
    let mut tmp_name = std::ffi::OsString::from(".");
    tmp_name.push(file_name);
    tmp_name.push(format!(".{}.tmp", std::process::id()));
    Ok(path.with_file_name(tmp_name))
}

fn write_exr(path: &Path, img: &RgbImage) -> exr::error::Result<()> {
    let w = img.width as usize;
    exr::prelude::write_rgb_file(path, w, img.height as usize, |x, y| {
        let i = (y * w + x) * 3;
        (img.data[i], img.data[i + 1], img.data[i + 2])
    })
}

/// sRGB transfer function (IEC 61966-2-1).
pub fn linear_to_srgb(x: f32) -> f32 {
    if x <= 0.003_130_8 {
        12.92 * x
    } else {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    }
}

/// 8-bit sRGB of `exposure`-scaled (stops) linear values, clamped; non-finite values black.
pub fn to_srgb8(img: &RgbImage, exposure: f32) -> Vec<u8> {
    let scale = 2f32.powf(exposure);
    img.data
        .iter()
        .map(|&v| {
            let v = if v.is_finite() { v * scale } else { 0.0 };
            (linear_to_srgb(v.clamp(0.0, 1.0)) * 255.0 + 0.5) as u8
        })
        .collect()
}

/// Writes 8-bit RGB rows (top to bottom) as PNG; not atomic by itself (see [`write_atomically`]).
pub fn write_png_rgb8(path: &Path, rgb: &[u8], width: u32, height: u32) -> Result<(), String> {
    image::save_buffer_with_format(path, rgb, width, height, image::ColorType::Rgb8, image::ImageFormat::Png).map_err(|e| e.to_string())
}

/// Reads the first RGB(A) layer of an EXR file as linear RGB.
pub fn read_exr(path: &Path) -> Result<RgbImage, ImageIoError> {
    use exr::prelude::*;
    let rerr = |msg: String| ImageIoError::Read { path: path.to_path_buf(), msg };
    // The header first: the pixel buffer is allocated from its claimed size.
    let meta = exr::meta::MetaData::read_from_file(path, false).map_err(|e| rerr(e.to_string()))?;
    for h in &meta.headers {
        let (w, h) = (h.layer_size.width() as u64, h.layer_size.height() as u64);
        if w.saturating_mul(h) > MAX_IMAGE_PIXELS {
            return Err(ImageIoError::TooLarge { path: path.to_path_buf(), width: w, height: h });
        }
    }
    let image = read_first_rgba_layer_from_file(
        path,
        |res, _| (res.width(), res.height(), vec![0f32; res.width() * res.height() * 3]),
        |(w, _, data): &mut (usize, usize, Vec<f32>), pos, (r, g, b, _a): (f32, f32, f32, f32)| {
            let i = (pos.y() * *w + pos.x()) * 3;
            data[i] = r;
            data[i + 1] = g;
            data[i + 2] = b;
        },
    )
    .map_err(|e| rerr(e.to_string()))?;
    let (w, h, data) = image.layer_data.channel_data.pixels;
    Ok(RgbImage { width: w as u32, height: h as u32, data })
}
