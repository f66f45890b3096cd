//! `bidir diff`: error metrics between two EXR images and an optional false-colour heatmap.

use anyhow::bail;
use bidir::imaging::{self, metrics, RgbImage};
use std::path::PathBuf;

#[derive(clap::Args, Debug)]
pub struct DiffArgs {
    /// The image to judge (EXR).
    pub a: PathBuf,
    /// The reference (EXR).
    pub b: PathBuf,
    /// Write a false-colour map of the per-pixel relative error (PNG).
    #[arg(long)]
    pub heatmap: Option<PathBuf>,
    /// Also print the mean ratio a/b of every BLOCKxBLOCK tile.
    #[arg(long)]
    pub blocks: Option<u32>,
    /// Also print the RMSE away from bright pixels: over the pixels more than 2 pixels from any
    /// whose mean over its channels exceeds LEVEL in either image (a light seen directly, whose
    /// edge converges at its own rate). Between two renders that differ only in their seed,
    /// RMSE^2 / 2 is the variance per pixel and channel of either.
    #[arg(long, value_name = "LEVEL")]
    pub below: Option<f32>,
}

pub fn run(args: &DiffArgs) -> anyhow::Result<()> {
    if args.blocks == Some(0) {
        bail!("--blocks must be at least 1");
    }
    if args.below.is_some_and(|l| !l.is_finite()) {
        bail!("--below must be a finite number");
    }
    if let Some(path) = &args.heatmap {
        super::render::check_output(path)?;
    }
    super::signals::on_interrupt(super::signals::FirstInterrupt::Abort)?;
    let a = imaging::read_exr(&args.a)?;
    let b = imaging::read_exr(&args.b)?;
    if a.width != b.width || a.height != b.height {
        bail!("{} is {}x{} but {} is {}x{}", args.a.display(), a.width, a.height, args.b.display(), b.width, b.height);
    }
    warn_non_finite(&args.a, &a);
    warn_non_finite(&args.b, &b);
    let ratio = metrics::mean_ratio(&a, &b);
    println!("RMSE      {:.6}", metrics::rmse(&a, &b));
    println!("relMSE    {:.6}", metrics::rel_mse(&a, &b));
    println!("mean a    {:.5} {:.5} {:.5}", a.mean()[0], a.mean()[1], a.mean()[2]);
    println!("mean b    {:.5} {:.5} {:.5}", b.mean()[0], b.mean()[1], b.mean()[2]);
    println!("ratio a/b {:.4} {:.4} {:.4}", ratio[0], ratio[1], ratio[2]);
    if let Some(level) = args.below {
        let (r, n) = metrics::rmse_where(&a, &b, &metrics::away_from_bright(&a, &b, level, 2));
        println!("RMSE away from pixels above {level}: {r:.6} ({n} of {} pixels)", a.width as u64 * a.height as u64);
    }
    if let Some(block) = args.blocks {
        let (ba, bb) = (metrics::block_means(&a, block), metrics::block_means(&b, block));
        let cols = a.width.div_ceil(block);
        for (i, ((_, _, ma), (_, _, mb))) in ba.iter().zip(&bb).enumerate() {
            let r = (ma[0] + ma[1] + ma[2]) / (mb[0] + mb[1] + mb[2]).max(1e-12);
            print!("{r:6.3}{}", if (i as u32 + 1) % cols == 0 { "\n" } else { " " });
        }
    }
    if let Some(path) = &args.heatmap {
        imaging::write_image(path, &heatmap(&a, &b), 0.0)?;
        println!("wrote {}", path.display());
    }
    Ok(())
}

/// Warns that `img`'s NaN/Inf pixels are left out of the metrics.
pub fn warn_non_finite(path: &std::path::Path, img: &RgbImage) {
    let n = img.non_finite_pixels();
    if n > 0 {
        eprintln!(
            "warning: {}: {n} of {} pixels are NaN or infinite; the metrics are over the finite pixels",
            path.display(),
            img.width as u64 * img.height as u64
        );
    }
}

/// Per-pixel |a - b| / (b + 0.01) (mean over channels) mapped blue (0) -> green -> red (>= 0.5).
fn heatmap(a: &RgbImage, b: &RgbImage) -> RgbImage {
    let mut out = RgbImage::new(a.width, a.height);
    for i in 0..(a.width * a.height) as usize {
        let mut e = 0.0;
        for c in 0..3 {
            e += (a.data[3 * i + c] - b.data[3 * i + c]).abs() / (b.data[3 * i + c].abs() + 0.01);
        }
        let x = (e / 3.0 / 0.5).clamp(0.0, 1.0);
        let rgb = if x < 0.5 { [0.0, 2.0 * x, 1.0 - 2.0 * x] } else { [2.0 * x - 1.0, 2.0 - 2.0 * x, 0.0] };
        out.data[3 * i..3 * i + 3].copy_from_slice(&rgb);
    }
    out
}
