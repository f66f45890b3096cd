//! Parts of a render that merge exactly: a film's raw sums with the metadata that says which
//! samples and which window they hold, written to (and read from) EXR.
//!
//! A part's EXR holds the estimate as `R`, `G`, `B` (what any viewer shows) and the film's
//! sums: `camera.R/G/B` (radiance summed over camera samples), `camera.N` (samples that
//! reached the pixel) and, for BDPT, `light.R/G/B` (light-tracing splats summed over every
//! iteration). Merging adds sums, so parts of disjoint sample ranges merge into the image a
//! single render of their union makes: camera sums over summed counts, light sums over the
//! summed samples per pixel (`Film::resolve` divides them the same way).
//!
//! A render that asked for them adds alpha `A` and the AOV layers (`aov.rs`) as means over
//! the part's samples (every sample counts in them), so a merge takes them back as sums and
//! writes the layers every part has.

use super::{Crop, RgbImage, SampleRange};
use std::path::{Path, PathBuf};

/// A film's sums for a window.
#[derive(Clone, Debug, PartialEq)]
pub struct Accumulation {
    pub width: u32,
    pub height: u32,
    /// Per pixel: radiance summed over camera samples (rgb) and their number.
    pub camera: Vec<[f64; 4]>,
    /// BDPT: light-tracing splats summed over all iterations (rgb), one iteration per sample.
    pub light: Option<Vec<[f64; 3]>>,
    /// Samples per pixel the sums hold (the light splats' divisor).
    pub spp: u64,
    /// What the camera rays found (alpha and AOVs), where the render asked for it; summed
    /// over all `spp` samples of a pixel.
    pub first_hit: Option<super::aov::FirstHit>,
}

impl Accumulation {
    pub fn new(width: u32, height: u32, with_light: bool) -> Accumulation {
        let n = width as usize * height as usize;
        Accumulation { width, height, camera: vec![[0.0; 4]; n], light: with_light.then(|| vec![[0.0; 3]; n]), spp: 0, first_hit: None }
    }

    /// The estimate: camera sums over their counts plus light sums over the samples.
    pub fn resolve(&self) -> RgbImage {
        let mut img = RgbImage::new(self.width, self.height);
        let inv_spp = 1.0 / self.spp.max(1) as f64;
        for (i, c) in self.camera.iter().enumerate() {
            let n = c[3].max(1.0);
            for k in 0..3 {
                let light = self.light.as_ref().map_or(0.0, |l| l[i][k] * inv_spp);
                img.data[3 * i + k] = (c[k] / n + light) as f32;
            }
        }
        img
    }

    /// Adds `o`'s sums (same size, both with or both without light) at window offset `at`.
    pub fn add_at(&mut self, o: &Accumulation, at: (u32, u32)) {
        for y in 0..o.height {
            for x in 0..o.width {
                let (src, dst) = ((y * o.width + x) as usize, ((y + at.1) * self.width + x + at.0) as usize);
                for k in 0..4 {
                    self.camera[dst][k] += o.camera[src][k];
                }
                if let (Some(d), Some(s)) = (self.light.as_mut(), o.light.as_ref()) {
                    for k in 0..3 {
                        d[dst][k] += s[src][k];
                    }
                }
                if let (Some(d), Some(s)) = (self.first_hit.as_mut(), o.first_hit.as_ref()) {
                    for k in 0..8 {
                        d.sums[dst][k] += s.sums[src][k];
                    }
                }
            }
        }
    }
}

/// Metadata keys a part carries (as EXR text attributes `bidir.KEY`), in print order.
pub mod keys {
    pub const VERSION: &str = "version";
    pub const SCENE: &str = "scene";
    pub const SCENE_HASH: &str = "scene_hash";
    pub const CAMERA: &str = "camera";
    pub const FULL_SIZE: &str = "full_size";
    pub const CROP: &str = "crop";
    pub const INTEGRATOR: &str = "integrator";
    pub const SETTINGS: &str = "settings";
    pub const SEED: &str = "seed";
    pub const SAMPLE_RANGE: &str = "sample_range";
    pub const SPP: &str = "spp";
    pub const RENDER_TIME: &str = "render_time_s";
    pub const DEVICE: &str = "device";
    /// How the kernels ran (BVH layout, path regeneration): informative, not compared by
    /// `bidir merge` (parts from different devices may differ here and still merge).
    pub const KERNELS: &str = "kernels";
    pub const MERGED_FROM: &str = "merged_from";
    /// Keys whose values must agree for parts to merge.
    pub const MUST_MATCH: &[&str] = &[SCENE_HASH, CAMERA, FULL_SIZE, INTEGRATOR, SETTINGS, SEED];
}

const PREFIX: &str = "bidir.";

/// What a render was: ordered `key = value` text.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RenderInfo {
    pub entries: Vec<(String, String)>,
}

impl RenderInfo {
    pub fn get(&self, key: &str) -> Option<&str> {
        self.entries.iter().find(|(k, _)| k == key).map(|(_, v)| v.as_str())
    }
    /// Sets `key` (in place if present, else appended).
    pub fn set(&mut self, key: &str, value: impl Into<String>) {
        let value = value.into();
        match self.entries.iter_mut().find(|(k, _)| k == key) {
            Some(e) => e.1 = value,
            None => self.entries.push((key.to_string(), value)),
        }
    }
}

/// Sample ranges as `a..b,c..d`.
pub fn format_ranges(ranges: &[SampleRange]) -> String {
    ranges.iter().map(|r| r.to_string()).collect::<Vec<_>>().join(",")
}

/// A part read back: its metadata, window, sample ranges and sums.
#[derive(Clone, Debug)]
pub struct Part {
    pub info: RenderInfo,
    pub full: (u32, u32),
    pub crop: Crop,
    pub ranges: Vec<SampleRange>,
    pub sums: Accumulation,
}

/// What a part is, without its pixels (all a merge checks; read from the EXR header).
#[derive(Clone, Debug)]
pub struct PartHeader {
    pub info: RenderInfo,
    pub full: (u32, u32),
    pub crop: Crop,
    pub ranges: Vec<SampleRange>,
    /// Whether it has light-tracing sums (BDPT).
    pub has_light: bool,
    /// Its alpha and AOV layers (`None`: no alpha).
    pub first_hit: Option<super::aov::Aovs>,
}

impl Part {
    pub fn header(&self) -> PartHeader {
        PartHeader {
            info: self.info.clone(),
            full: self.full,
            crop: self.crop,
            ranges: self.ranges.clone(),
            has_light: self.sums.light.is_some(),
            first_hit: self.sums.first_hit.as_ref().map(|f| f.aovs),
        }
    }
}

/// Why a part could not be read or written, or parts not merged.
#[derive(Debug, thiserror::Error)]
pub enum PartError {
    #[error("{path}: {msg}")]
    File { path: PathBuf, msg: String },
    #[error("{0}")]
    Merge(String),
}

fn ferr(path: &Path, msg: impl Into<String>) -> PartError {
    PartError::File { path: path.to_path_buf(), msg: msg.into() }
}

/// Writes a part: the estimate, the sums and `info` (which must name `full_size`, `crop`),
/// atomically.
pub fn write_part(path: &Path, sums: &Accumulation, info: &RenderInfo, crop: Crop) -> Result<(), PartError> {
    use exr::prelude::*;
    let img = sums.resolve();
    let (w, h) = (sums.width as usize, sums.height as usize);
    let mut channels: Vec<AnyChannel<FlatSamples>> = Vec::new();
    let mut add = |name: &str, v: Vec<f32>| channels.push(AnyChannel::new(name, FlatSamples::F32(v)));
    for (k, c) in ["R", "G", "B"].iter().enumerate() {
        add(c, img.data.iter().skip(k).step_by(3).copied().collect());
        add(&format!("camera.{c}"), sums.camera.iter().map(|p| p[k] as f32).collect());
        if let Some(l) = &sums.light {
            add(&format!("light.{c}"), l.iter().map(|p| p[k] as f32).collect());
        }
    }
    add("camera.N", sums.camera.iter().map(|p| p[3] as f32).collect());
    if let Some(fh) = &sums.first_hit {
        for (name, values) in fh.channels(sums.spp) {
            add(name, values);
        }
    }
    let mut attrs = LayerAttributes { layer_position: Vec2(crop.x0 as i32, crop.y0 as i32), ..LayerAttributes::default() };
    for (k, v) in &info.entries {
        attrs.other.insert(Text::from(format!("{PREFIX}{k}").as_str()), AttributeValue::Text(Text::from(v.as_str())));
    }
    let layer = Layer::new((w, h), attrs, Encoding::default(), AnyChannels::sort(SmallVec::from_vec(channels)));
    let full = info.get(keys::FULL_SIZE).and_then(parse_size).unwrap_or((crop.x1, crop.y1));
    let image = Image::new(ImageAttributes::new(IntegerBounds::new((0, 0), (full.0 as usize, full.1 as usize))), layer);
    super::write_atomically(path, |tmp| image.write().to_file(tmp).map_err(|e| e.to_string())).map_err(|e| ferr(path, e.to_string()))
}

fn parse_size(s: &str) -> Option<(u32, u32)> {
    let (w, h) = s.split_once('x')?;
    Some((w.parse().ok()?, h.parse().ok()?))
}

/// Text attributes `bidir.*` in print order.
fn render_info<'a>(attrs: impl Iterator<Item = (&'a exr::meta::attribute::Text, &'a exr::meta::attribute::AttributeValue)>) -> RenderInfo {
    let mut entries: Vec<(String, String)> = attrs
        .filter_map(|(k, v)| match v {
            exr::meta::attribute::AttributeValue::Text(t) => k.to_string().strip_prefix(PREFIX).map(|k| (k.to_string(), t.to_string())),
            _ => None,
        })
        .collect();
    // HashMap order is arbitrary: print in the order parts are written.
    let order = [
        keys::VERSION,
        keys::SCENE,
        keys::SCENE_HASH,
        keys::CAMERA,
        keys::FULL_SIZE,
        keys::CROP,
        keys::INTEGRATOR,
        keys::SETTINGS,
        keys::SEED,
        keys::SAMPLE_RANGE,
        keys::SPP,
        keys::RENDER_TIME,
        keys::DEVICE,
        keys::KERNELS,
        keys::MERGED_FROM,
    ];
    entries.sort_by_key(|(k, _)| (order.iter().position(|o| o == k).unwrap_or(order.len()), k.clone()));
    RenderInfo { entries }
}

/// The header of a part: metadata checked against the image's size and channels.
fn header(path: &Path, info: RenderInfo, size: (u32, u32), channels: &[String]) -> Result<PartHeader, PartError> {
    let need = |k: &str| info.get(k).ok_or_else(|| ferr(path, format!("no bidir.{k} attribute: not a part written by bidir render")));
    let full = parse_size(need(keys::FULL_SIZE)?).ok_or_else(|| ferr(path, "bidir.full_size is not WxH"))?;
    let crop: super::Crop = need(keys::CROP)?.parse().map_err(|e: String| ferr(path, e))?;
    crop.check(full.0, full.1).map_err(|e| ferr(path, e))?;
    let ranges = need(keys::SAMPLE_RANGE)?
        .split(',')
        .map(|r| r.parse::<SampleRange>())
        .collect::<std::result::Result<Vec<_>, String>>()
        .map_err(|e| ferr(path, e))?;
    if size != (crop.width(), crop.height()) {
        return Err(ferr(path, format!("the image is {}x{} but its crop {crop} is {}x{}", size.0, size.1, crop.width(), crop.height())));
    }
    for name in ["camera.R", "camera.G", "camera.B", "camera.N"] {
        if !channels.iter().any(|c| c == name) {
            return Err(ferr(path, format!("no {name} channel: not a part written by bidir render")));
        }
    }
    let has_light = ["light.R", "light.G", "light.B"].iter().all(|l| channels.iter().any(|c| c == l));
    let first_hit = super::aov::Aovs::from_channel_names(channels);
    Ok(PartHeader { info, full, crop, ranges, has_light, first_hit })
}

/// Reads only the header of a part written by [`write_part`] (for checks before reading
/// pixels).
pub fn read_part_header(path: &Path) -> Result<PartHeader, PartError> {
    let meta = exr::meta::MetaData::read_from_file(path, false).map_err(|e| ferr(path, format!("cannot read EXR: {e}")))?;
    let h = meta.headers.first().ok_or_else(|| ferr(path, "no image layer"))?;
    let info = render_info(h.own_attributes.other.iter().chain(h.shared_attributes.other.iter()));
    let channels: Vec<String> = h.channels.list.iter().map(|c| c.name.to_string()).collect();
    header(path, info, (h.layer_size.0 as u32, h.layer_size.1 as u32), &channels)
}

/// Reads a part written by [`write_part`] (an EXR without bidir's sums is refused, naming
/// what is missing).
pub fn read_part(path: &Path) -> Result<Part, PartError> {
    use exr::prelude::*;
    let image = read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .all_layers()
        .all_attributes()
        .from_file(path)
        .map_err(|e| ferr(path, format!("cannot read EXR: {e}")))?;
    let layer = image.layer_data.first().ok_or_else(|| ferr(path, "no image layer"))?;
    let info = render_info(layer.attributes.other.iter().chain(image.attributes.other.iter()));
    let names: Vec<String> = layer.channel_data.list.iter().map(|c| c.name.to_string()).collect();
    let (w, h) = (layer.size.0 as u32, layer.size.1 as u32);
    let head = header(path, info, (w, h), &names)?;
    let channel = |name: &str| -> Vec<f64> {
        layer
            .channel_data
            .list
            .iter()
            .find(|c| c.name.to_string() == name)
            .map_or_else(Vec::new, |c| c.sample_data.values_as_f32().map(f64::from).collect())
    };
    let cam = [channel("camera.R"), channel("camera.G"), channel("camera.B"), channel("camera.N")];
    let light = head.has_light.then(|| {
        let (r, g, b) = (channel("light.R"), channel("light.G"), channel("light.B"));
        (0..r.len()).map(|i| [r[i], g[i], b[i]]).collect()
    });
    let spp: u64 = head.ranges.iter().map(|r| r.len() as u64).sum();
    let sums = Accumulation {
        width: w,
        height: h,
        camera: (0..cam[0].len()).map(|i| [cam[0][i], cam[1][i], cam[2][i], cam[3][i]]).collect(),
        light,
        spp,
        first_hit: head.first_hit.map(|aovs| super::aov::FirstHit::from_means((w * h) as usize, aovs, spp, channel)),
    };
    Ok(Part { info: head.info, full: head.full, crop: head.crop, ranges: head.ranges, sums })
}
