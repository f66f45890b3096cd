//! `bidir merge`: parts (sample ranges, crop windows) into one image, and `bidir info
//! IMAGE.exr`.

use anyhow::bail;
use bidir::imaging::{self, merge, part};
use std::path::{Path, PathBuf};

#[derive(clap::Args, Debug)]
pub struct MergeArgs {
    /// Parts written by `bidir render` (.exr)
    #[arg(required = true, value_name = "PART.exr")]
    pub parts: Vec<PathBuf>,
    /// Output: .exr (a part again, with the merged sums and metadata) and/or .png; may repeat.
    #[arg(short = 'o', long = "output", required = true)]
    pub outputs: Vec<PathBuf>,
    /// Exposure in stops applied to PNG output.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub exposure: f32,
}

pub fn run(args: &MergeArgs) -> anyhow::Result<()> {
    let mut exr = None;
    for o in &args.outputs {
        match o.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
            Some("exr") if exr.is_none() => exr = Some(o),
            Some("exr") => bail!("{}: give one .exr output (and PNGs)", o.display()),
            Some("png") => {}
            _ => bail!("{}: output must end in .exr or .png", o.display()),
        }
    }
    let start = std::time::Instant::now();
    // Every header is checked before a pixel is read or anything written; then the parts
    // are read and added one at a time.
    let headers = args.parts.iter().map(|p| Ok((p.clone(), part::read_part_header(p)?))).collect::<anyhow::Result<Vec<_>>>()?;
    let plan = merge::plan(&headers)?;
    for w in &plan.warnings {
        eprintln!("warning: {w}");
    }
    let mut sums = plan.empty();
    for (path, head) in &headers {
        let p = part::read_part(path)?;
        if p.crop != head.crop || p.ranges != head.ranges {
            bail!("{}: changed while merging", path.display());
        }
        plan.add(&mut sums, &p);
    }
    let merged = plan.finish(sums);
    let m = &merged.part;
    // Everything is checked before anything is written.
    for o in &args.outputs {
        if Some(o) == exr {
            part::write_part(o, &m.sums, &m.info, m.crop)?;
        } else {
            imaging::write_image(o, &m.sums.resolve(), args.exposure)?;
        }
    }
    println!(
        "merged {} parts: window {} of {}x{}, samples {} ({} spp), in {:.3} s",
        headers.len(),
        m.crop,
        m.full.0,
        m.full.1,
        part::format_ranges(&m.ranges),
        m.sums.spp,
        start.elapsed().as_secs_f64()
    );
    for o in &args.outputs {
        println!("wrote {}", o.display());
    }
    Ok(())
}

/// `bidir info IMAGE.exr`: the render's metadata.
pub fn info(path: &Path) -> anyhow::Result<()> {
    let p = part::read_part(path)?;
    println!("{}: {}x{} pixels", path.display(), p.sums.width, p.sums.height);
    for (k, v) in &p.info.entries {
        println!("  {k:<14} {v}");
    }
    println!(
        "  {:<14} {}",
        "channels",
        if p.sums.light.is_some() { "R G B, camera.R/G/B/N, light.R/G/B" } else { "R G B, camera.R/G/B/N" }
    );
    Ok(())
}
