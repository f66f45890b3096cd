//! Alpha and the AOVs (arbitrary output variables) a denoiser takes, as sums over a pixel's
//! camera samples and as the EXR channels they become.
//!
//! Channel names follow what Intel Open Image Denoise users read from an EXR: `A` (alpha),
//! `albedo.R`, `albedo.G`, `albedo.B`, `normal.X`, `normal.Y`, `normal.Z` and `depth.Z`
//! (single-part EXR, layer prefix before the dot, as Nuke, Blender and OpenImageIO name
//! layers).

use std::str::FromStr;

/// Which AOV layers an EXR carries besides the colour and alpha (`--aov albedo,normal,depth`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Aovs {
    pub albedo: bool,
    pub normal: bool,
    pub depth: bool,
}

impl FromStr for Aovs {
    type Err = String;
    fn from_str(s: &str) -> Result<Aovs, String> {
        let mut a = Aovs::default();
        for name in s.split(',').map(str::trim) {
            let flag = match name {
                "albedo" => &mut a.albedo,
                "normal" => &mut a.normal,
                "depth" => &mut a.depth,
                _ => return Err(format!("unknown AOV '{}' (albedo | normal | depth, comma-separated)", crate::text::quote(name))),
            };
            if *flag {
                return Err(format!("AOV '{name}' given twice"));
            }
            *flag = true;
        }
        Ok(a)
    }
}

/// Index of each quantity in a [`FirstHit::sums`] entry.
pub mod slot {
    pub const HITS: usize = 0;
    pub const ALBEDO: usize = 1;
    pub const NORMAL: usize = 4;
    pub const DEPTH: usize = 7;
}

/// Per pixel, sums over camera samples of what the camera ray found (the first-hit pass):
/// hits (samples whose camera ray hit geometry), albedo (rgb), normal (xyz), depth; see
/// [`slot`]. Divided by the samples per pixel they are alpha and the AOVs.
#[derive(Clone, Debug, PartialEq)]
pub struct FirstHit {
    pub sums: Vec<[f64; 8]>,
    /// The AOV layers to write (alpha is always written).
    pub aovs: Aovs,
}

impl FirstHit {
    /// EXR channels (name, values per pixel) of the means over `spp` samples per pixel:
    /// `A`, then the layers `aovs` asks for.
    pub fn channels(&self, spp: u64) -> Vec<(&'static str, Vec<f32>)> {
        let inv = 1.0 / spp.max(1) as f64;
        let mean = |k: usize| self.sums.iter().map(|p| (p[k] * inv) as f32).collect::<Vec<f32>>();
        let mut out = vec![("A", mean(slot::HITS))];
        if self.aovs.albedo {
            out.extend([("albedo.R", mean(slot::ALBEDO)), ("albedo.G", mean(slot::ALBEDO + 1)), ("albedo.B", mean(slot::ALBEDO + 2))]);
        }
        if self.aovs.normal {
            out.extend([("normal.X", mean(slot::NORMAL)), ("normal.Y", mean(slot::NORMAL + 1)), ("normal.Z", mean(slot::NORMAL + 2))]);
        }
        if self.aovs.depth {
            out.push(("depth.Z", mean(slot::DEPTH)));
        }
        out
    }
}

impl Aovs {
    /// The layers both have (what a merge of parts can write).
    pub fn common(self, o: Aovs) -> Aovs {
        Aovs { albedo: self.albedo && o.albedo, normal: self.normal && o.normal, depth: self.depth && o.depth }
    }

    /// The layers whose channels are all among `names`; `None` without an `A` channel.
    pub fn from_channel_names(names: &[String]) -> Option<Aovs> {
        let has = |n: &str| names.iter().any(|c| c == n);
        has("A").then(|| Aovs {
            albedo: ["albedo.R", "albedo.G", "albedo.B"].iter().all(|c| has(c)),
            normal: ["normal.X", "normal.Y", "normal.Z"].iter().all(|c| has(c)),
            depth: has("depth.Z"),
        })
    }
}

impl FirstHit {
    /// Zero sums for `pixels` pixels.
    pub fn zero(pixels: usize, aovs: Aovs) -> FirstHit {
        FirstHit { sums: vec![[0.0; 8]; pixels], aovs }
    }

    /// The sums back from an EXR's means over `spp` samples per pixel (`channel` gives a
    /// channel's values by name; layers `aovs` lacks stay zero).
    pub fn from_means(pixels: usize, aovs: Aovs, spp: u64, channel: impl Fn(&str) -> Vec<f64>) -> FirstHit {
        let mut f = FirstHit::zero(pixels, aovs);
        let n = spp as f64;
        let mut take = |name: &str, k: usize| {
            for (p, v) in f.sums.iter_mut().zip(channel(name)) {
                p[k] = v * n;
            }
        };
        take("A", slot::HITS);
        if aovs.albedo {
            ["albedo.R", "albedo.G", "albedo.B"].iter().enumerate().for_each(|(i, c)| take(c, slot::ALBEDO + i));
        }
        if aovs.normal {
            ["normal.X", "normal.Y", "normal.Z"].iter().enumerate().for_each(|(i, c)| take(c, slot::NORMAL + i));
        }
        if aovs.depth {
            take("depth.Z", slot::DEPTH);
        }
        f
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn aov_lists_parse() {
        assert_eq!("albedo".parse::<Aovs>(), Ok(Aovs { albedo: true, normal: false, depth: false }));
        assert_eq!("depth, normal".parse::<Aovs>(), Ok(Aovs { albedo: false, normal: true, depth: true }));
        assert!("albedo,albedo".parse::<Aovs>().is_err());
        assert!("position".parse::<Aovs>().unwrap_err().contains("unknown AOV"));
        assert!("".parse::<Aovs>().is_err());
    }

    #[test]
    fn channels_are_means_over_samples() {
        let fh = FirstHit { sums: vec![[2.0, 1.0, 0.5, 0.25, 0.0, 0.0, 4.0, 8.0]], aovs: Aovs { albedo: true, normal: true, depth: true } };
        let ch = fh.channels(4);
        let get = |n: &str| ch.iter().find(|c| c.0 == n).unwrap().1[0];
        assert_eq!(get("A"), 0.5);
        assert_eq!(get("albedo.R"), 0.25);
        assert_eq!(get("albedo.B"), 0.0625);
        assert_eq!(get("normal.Z"), 1.0);
        assert_eq!(get("depth.Z"), 2.0);
        let alpha_only = FirstHit { aovs: Aovs::default(), ..fh };
        assert_eq!(alpha_only.channels(4).len(), 1);
    }
}
