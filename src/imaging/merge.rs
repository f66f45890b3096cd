//! `bidir merge`: parts of one render (disjoint sample ranges, disjoint crop windows) summed
//! into the image one render of their union makes.

use super::part::{format_ranges, keys, Accumulation, Part, PartError, PartHeader};
use super::{Crop, SampleRange};
use std::collections::BTreeMap;
use std::path::PathBuf;

/// The merged part and what the merge has to report without failing (missing samples).
pub struct Merged {
    pub part: Part,
    pub warnings: Vec<String>,
}

fn names(parts: &[(PathBuf, PartHeader)], idx: &[usize]) -> String {
    idx.iter().map(|&i| parts[i].0.display().to_string()).collect::<Vec<_>>().join(", ")
}

/// Merges `parts` (path, part). Refused, naming the files: parts that differ in any of
/// [`keys::MUST_MATCH`], overlapping sample ranges in a window, overlapping windows, windows
/// with different sample ranges, and windows that leave a hole in the rectangle they span.
/// Sample ranges missing between the first and the last, and tiles missing around the
/// rectangle the windows span, are reported as warnings (the merge is still an unbiased
/// estimate, with fewer samples; or a crop of the image).
pub fn merge(parts: &[(PathBuf, Part)]) -> Result<Merged, PartError> {
    let headers: Vec<(PathBuf, PartHeader)> = parts.iter().map(|(p, part)| (p.clone(), part.header())).collect();
    let plan = plan(&headers)?;
    let mut sums = plan.empty();
    for (_, p) in parts {
        plan.add(&mut sums, p);
    }
    Ok(plan.finish(sums))
}

/// A checked merge: the merged part's header and the warnings, before any pixel is read.
pub struct Plan {
    pub header: PartHeader,
    pub warnings: Vec<String>,
}

impl Plan {
    /// The merged window's sums, zero.
    pub fn empty(&self) -> Accumulation {
        let mut a = Accumulation::new(self.header.crop.width(), self.header.crop.height(), self.header.has_light);
        a.spp = self.header.ranges.iter().map(|r| r.len() as u64).sum();
        a.first_hit = self.header.first_hit.map(|aovs| super::aov::FirstHit::zero(a.camera.len(), aovs));
        a
    }
    /// Adds a part (one of those planned) into `sums`.
    pub fn add(&self, sums: &mut Accumulation, part: &Part) {
        let b = self.header.crop;
        sums.add_at(&part.sums, (part.crop.x0 - b.x0, part.crop.y0 - b.y0));
    }
    pub fn finish(self, sums: Accumulation) -> Merged {
        let h = self.header;
        Merged { part: Part { info: h.info, full: h.full, crop: h.crop, ranges: h.ranges, sums }, warnings: self.warnings }
    }
}

/// Checks `parts` (path, header) as [`merge`] does and plans the merge: the files are read
/// one at a time afterwards, so a merge holds one part and the result in memory.
pub fn plan(parts: &[(PathBuf, PartHeader)]) -> Result<Plan, PartError> {
    let merr = |m: String| Err(PartError::Merge(m));
    let Some((first_path, first)) = parts.first() else {
        return merr("nothing to merge".into());
    };
    for (path, p) in &parts[1..] {
        for key in keys::MUST_MATCH {
            let (a, b) = (first.info.get(key).unwrap_or("(none)"), p.info.get(key).unwrap_or("(none)"));
            if a != b {
                return merr(format!("{key} differs: {} has '{a}', {} has '{b}'", first_path.display(), path.display()));
            }
        }
        if p.has_light != first.has_light {
            return merr(format!("{} has light-tracing sums and {} has none", first_path.display(), path.display()));
        }
    }
    // Windows, each with its parts' sample ranges.
    let mut windows: BTreeMap<Crop, Vec<usize>> = BTreeMap::new();
    for (i, (_, p)) in parts.iter().enumerate() {
        windows.entry(p.crop).or_default().push(i);
    }
    let mut window_ranges: Vec<(Crop, Vec<usize>, Vec<SampleRange>)> = Vec::new();
    for (crop, idx) in &windows {
        let mut ranges: Vec<(SampleRange, usize)> = idx.iter().flat_map(|&i| parts[i].1.ranges.iter().map(move |r| (*r, i))).collect();
        ranges.sort();
        for w in ranges.windows(2) {
            if w[1].0.start < w[0].0.end {
                return merr(format!(
                    "sample ranges {} ({}) and {} ({}) overlap in window {crop}",
                    w[0].0,
                    parts[w[0].1].0.display(),
                    w[1].0,
                    parts[w[1].1].0.display()
                ));
            }
        }
        window_ranges.push((*crop, idx.clone(), ranges.into_iter().map(|r| r.0).collect()));
    }
    for (a, b) in window_ranges.iter().enumerate().flat_map(|(i, a)| window_ranges[i + 1..].iter().map(move |b| (a, b))) {
        if a.0.overlaps(&b.0) {
            return merr(format!("tiles {} (crop {}) and {} (crop {}) overlap", names(parts, &a.1), a.0, names(parts, &b.1), b.0));
        }
        if a.2 != b.2 {
            return merr(format!(
                "tiles have different sample ranges: {} (crop {}) holds {}, {} (crop {}) holds {}",
                names(parts, &a.1),
                a.0,
                format_ranges(&a.2),
                names(parts, &b.1),
                b.0,
                format_ranges(&b.2)
            ));
        }
    }
    let bounds = window_ranges.iter().fold(window_ranges[0].0, |u, w| u.union(&w.0));
    let covered: u64 = window_ranges.iter().map(|w| w.0.pixels()).sum();
    if covered != bounds.pixels() {
        let hole = (bounds.y0..bounds.y1)
            .flat_map(|y| (bounds.x0..bounds.x1).map(move |x| (x, y)))
            .find(|&(x, y)| !window_ranges.iter().any(|w| x >= w.0.x0 && x < w.0.x1 && y >= w.0.y0 && y < w.0.y1));
        let (x, y) = hole.unwrap_or_default();
        return merr(format!(
            "tiles are missing: they cover {covered} of the {} pixels of window {bounds} (pixel {x},{y} is in none)",
            bounds.pixels()
        ));
    }
    let ranges = window_ranges[0].2.clone();
    let mut warnings = Vec::new();
    if bounds != Crop::full(first.full.0, first.full.1) {
        warnings.push(format!(
            "the parts cover window {bounds} of the {}x{} image, not all of it: the merge is that window",
            first.full.0, first.full.1
        ));
    }
    for w in ranges.windows(2) {
        if w[0].end < w[1].start {
            warnings.push(format!(
                "samples {}..{} are missing (no part holds them): the merge has {} spp",
                w[0].end,
                w[1].start,
                ranges.iter().map(|r| r.len() as u64).sum::<u64>()
            ));
        }
    }
    let spp: u64 = ranges.iter().map(|r| r.len() as u64).sum();
    // Contiguous ranges print as one.
    let mut joined: Vec<SampleRange> = Vec::new();
    for r in &ranges {
        match joined.last_mut() {
            Some(l) if l.end == r.start => l.end = r.end,
            _ => joined.push(*r),
        }
    }
    let mut info = first.info.clone();
    info.set(keys::CROP, bounds.to_string());
    info.set(keys::SAMPLE_RANGE, format_ranges(&joined));
    info.set(keys::SPP, spp.to_string());
    let time: f64 = parts.iter().filter_map(|(_, p)| p.info.get(keys::RENDER_TIME)?.parse::<f64>().ok()).sum();
    info.set(keys::RENDER_TIME, format!("{time:.3}"));
    info.set(keys::MERGED_FROM, parts.len().to_string());
    // Where and how the parts ran may differ (they need not match): every distinct value.
    for key in [keys::DEVICE, keys::KERNELS] {
        let mut values: Vec<&str> = Vec::new();
        for v in parts.iter().filter_map(|(_, p)| p.info.get(key)) {
            if !values.contains(&v) {
                values.push(v);
            }
        }
        if !values.is_empty() {
            info.set(key, values.join("; "));
        }
    }
    // Alpha and the AOV layers every part has.
    let first_hit = parts.iter().try_fold(first.first_hit.unwrap_or_default(), |a, (_, p)| p.first_hit.map(|b| a.common(b)));
    let header = PartHeader { info, full: first.full, crop: bounds, ranges: joined, has_light: first.has_light, first_hit };
    Ok(Plan { header, warnings })
}
