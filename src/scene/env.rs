//! The environment light: radiance arriving from infinitely far away, either uniform or an
//! equirectangular (latitude-longitude) map, linear RGB. `--env R,G,B | FILE.hdr | FILE.exr`.
//!
//! Conventions (shared with `glsl/common/env.glsl`): +Y is up. A direction w toward the
//! environment has theta = acos(w.y) (0 at the zenith) and phi = atan2(w.x, -w.z) + rotation
//! in [0, 2 pi); map column = phi / (2 pi) * width, row = theta / pi * height (row 0 at the
//! top). So the middle of the map is seen looking along -Z (as the glTF front view does), +X
//! lies to its right, and a positive rotation turns the map about +Y. Radiance is piecewise constant per texel
//! (nearest lookup), which is what makes the sampling density exactly proportional to it.

use std::path::{Path, PathBuf};

use glam::Vec3;

/// An environment map: `width * height` texels of linear radiance, rows top to bottom.
#[derive(Clone, Debug, PartialEq)]
pub struct Environment {
    /// Where it came from (file path or `uniform R,G,B`), for messages.
    pub source: String,
    pub width: u32,
    pub height: u32,
    pub texels: Vec<Vec3>,
    /// Multiplies every texel (`--env-scale`).
    pub scale: f32,
    /// Turn about +Y in degrees (`--env-rotate`; the sun is not turned).
    pub rotate_deg: f32,
    /// A sun added to the map (`--sun`).
    pub sun: Option<Sun>,
}

/// A sun: a small disk of directions of uniform radiance, `--sun "DIR;R,G,B;ANGLE"`: the
/// direction toward it, the irradiance it gives a surface facing it, and its apparent
/// diameter in degrees (0.53 by default).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sun {
    /// Unit direction toward the sun.
    pub direction: Vec3,
    pub irradiance: Vec3,
    pub angle_deg: f32,
}

impl Sun {
    /// Cosine of the disk's angular radius.
    pub fn cos_max(&self) -> f32 {
        (0.5 * self.angle_deg).to_radians().cos()
    }

    /// Solid angle of the disk, 2 pi (1 - cos_max).
    pub fn solid_angle(&self) -> f32 {
        2.0 * std::f32::consts::PI * (1.0 - self.cos_max())
    }

    /// Radiance of the disk: E = L pi sin^2(radius) on a surface facing it.
    pub fn radiance(&self) -> Vec3 {
        let sin_r = (0.5 * self.angle_deg).to_radians().sin();
        self.irradiance / (std::f32::consts::PI * sin_r * sin_r)
    }
}

impl std::str::FromStr for Sun {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        let usage = || {
            format!("--sun '{s}': expected \"DIR;R,G,B\" or \"DIR;R,G,B;ANGLE\" (direction toward the sun, irradiance >= 0, diameter in degrees in (0, 90])")
        };
        let parts: Vec<&str> = s.split(';').collect();
        if !(2..=3).contains(&parts.len()) {
            return Err(usage());
        }
        let vec3 = |t: &str| -> Option<Vec3> {
            let v: Vec<f32> = t.split(',').map(|x| x.trim().parse::<f32>()).collect::<Result<_, _>>().ok()?;
            (v.len() == 3 && v.iter().all(|c| c.is_finite())).then(|| Vec3::new(v[0], v[1], v[2]))
        };
        let direction = vec3(parts[0]).and_then(|d| d.try_normalize()).ok_or_else(usage)?;
        let irradiance = vec3(parts[1]).filter(|e| e.min_element() >= 0.0).ok_or_else(usage)?;
        let angle_deg = match parts.get(2) {
            Some(a) => a.trim().parse::<f32>().ok().filter(|a| *a > 0.0 && *a <= 90.0).ok_or_else(usage)?,
            None => 0.53,
        };
        Ok(Sun { direction, irradiance, angle_deg })
    }
}

/// Why an environment could not be read.
#[derive(Debug, thiserror::Error)]
pub enum EnvError {
    #[error("{file}: cannot read the environment map: {msg}")]
    Read { file: PathBuf, msg: String },
    #[error("{file}: unsupported environment map extension (use .hdr or .exr)")]
    Extension { file: PathBuf },
    #[error("{file}: environment texel ({x}, {y}) is not finite")]
    NotFinite { file: PathBuf, x: u32, y: u32 },
    #[error("--env '{0}': expected none, R,G,B (three non-negative finite numbers) or a .hdr/.exr file")]
    Spec(String),
}

/// What `--env` asked for.
#[derive(Clone, Debug, PartialEq)]
pub enum EnvSpec {
    /// `--env none`: no environment, not even the default one.
    None,
    Uniform(Vec3),
    File(PathBuf),
}

impl std::str::FromStr for EnvSpec {
    type Err = EnvError;
    fn from_str(s: &str) -> Result<Self, EnvError> {
        if s.eq_ignore_ascii_case("none") {
            return Ok(EnvSpec::None);
        }
        let ext = Path::new(s).extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
        if matches!(ext.as_deref(), Some("hdr") | Some("exr")) {
            return Ok(EnvSpec::File(PathBuf::from(s)));
        }
        let parts: Vec<&str> = s.split(',').collect();
        let rgb: Vec<f32> = parts.iter().filter_map(|p| p.trim().parse::<f32>().ok()).collect();
        match rgb.as_slice() {
            [r, g, b] if parts.len() == 3 && rgb.iter().all(|c| c.is_finite() && *c >= 0.0) => Ok(EnvSpec::Uniform(Vec3::new(*r, *g, *b))),
            _ => Err(EnvError::Spec(s.to_owned())),
        }
    }
}

impl Environment {
    /// The same radiance from every direction (a 1 x 1 map).
    pub fn uniform(radiance: Vec3) -> Environment {
        Environment {
            source: format!("uniform {},{},{}", radiance.x, radiance.y, radiance.z),
            width: 1,
            height: 1,
            texels: vec![radiance],
            scale: 1.0,
            rotate_deg: 0.0,
            sun: None,
        }
    }

    /// A map from texels (rows top to bottom); negative values are clamped to 0.
    pub fn from_texels(source: &str, width: u32, height: u32, texels: Vec<Vec3>) -> Environment {
        assert_eq!(texels.len(), (width * height) as usize, "environment texel count");
        let texels = texels.into_iter().map(|t| t.max(Vec3::ZERO)).collect();
        Environment { source: source.to_owned(), width, height, texels, scale: 1.0, rotate_deg: 0.0, sun: None }
    }

    /// Reads an equirectangular `.hdr` (Radiance RGBE) or `.exr` (first RGB(A) layer) map.
    pub fn load(path: &Path) -> Result<Environment, EnvError> {
        let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
        let rerr = |msg: String| EnvError::Read { file: path.to_path_buf(), msg };
        let (w, h, data) = match ext.as_deref() {
            Some("hdr") => {
                let img = image::ImageReader::open(path)
                    .map_err(|e| rerr(e.to_string()))?
                    .with_guessed_format()
                    .map_err(|e| rerr(e.to_string()))?;
                let img = img.decode().map_err(|e| rerr(e.to_string()))?.into_rgb32f();
                (img.width(), img.height(), img.into_raw())
            }
            Some("exr") => read_exr_rgb(path).map_err(rerr)?,
            _ => return Err(EnvError::Extension { file: path.to_path_buf() }),
        };
        if w == 0 || h == 0 {
            return Err(rerr("the image is empty".into()));
        }
        let texels: Vec<Vec3> = data.chunks_exact(3).map(|c| Vec3::new(c[0], c[1], c[2])).collect();
        if let Some(i) = texels.iter().position(|t| !t.is_finite()) {
            return Err(EnvError::NotFinite { file: path.to_path_buf(), x: i as u32 % w, y: i as u32 / w });
        }
        Ok(Environment::from_texels(&path.display().to_string(), w, h, texels))
    }

    /// The environment `spec` names (`None` for `--env none`).
    pub fn from_spec(spec: &EnvSpec) -> Result<Option<Environment>, EnvError> {
        match spec {
            EnvSpec::None => Ok(None),
            EnvSpec::Uniform(c) => Ok(Some(Environment::uniform(*c))),
            EnvSpec::File(p) => Environment::load(p).map(Some),
        }
    }

    /// Whether nothing emits (no texel, no sun).
    pub fn is_black(&self) -> bool {
        (self.scale <= 0.0 || self.texels.iter().all(|t| t.max_element() <= 0.0))
            && !self.sun.is_some_and(|s| s.irradiance.max_element() > 0.0)
    }

    /// Solid angle of texel row `row`: (2 pi / width) (cos theta0 - cos theta1).
    pub fn texel_solid_angle(&self, row: u32) -> f32 {
        let h = self.height as f64;
        let (t0, t1) = (std::f64::consts::PI * row as f64 / h, std::f64::consts::PI * (row + 1) as f64 / h);
        (2.0 * std::f64::consts::PI / self.width as f64 * (t0.cos() - t1.cos())) as f32
    }

    /// Radiance arriving from unit direction `w` (toward the environment), scale included.
    pub fn radiance(&self, w: Vec3) -> Vec3 {
        let theta = w.y.clamp(-1.0, 1.0).acos();
        let tau = std::f32::consts::TAU;
        let phi = (std::f32::consts::PI + w.x.atan2(-w.z) + self.rotate_deg.to_radians()).rem_euclid(tau);
        let x = ((phi / tau * self.width as f32) as u32).min(self.width - 1);
        let y = ((theta / std::f32::consts::PI * self.height as f32) as u32).min(self.height - 1);
        self.texels[(y * self.width + x) as usize] * self.scale
    }
}

/// The first RGB(A) layer of an EXR file: (width, height, rgb floats).
fn read_exr_rgb(path: &Path) -> Result<(u32, u32, Vec<f32>), String> {
    use exr::prelude::*;
    let image = read_first_rgba_layer_from_file(
        path,
        |res, _| (res.width(), vec![0f32; res.width() * res.height() * 3]),
        |(w, data): &mut (usize, Vec<f32>), pos, (r, g, b, _a): (f32, f32, f32, f32)| {
            let i = (pos.y() * *w + pos.x()) * 3;
            data[i..i + 3].copy_from_slice(&[r, g, b]);
        },
    )
    .map_err(|e| e.to_string())?;
    let size = image.layer_data.size;
    Ok((size.width() as u32, size.height() as u32, image.layer_data.channel_data.pixels.1))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spec_parses_none_colour_and_files() {
        assert_eq!("none".parse::<EnvSpec>().unwrap(), EnvSpec::None);
        assert_eq!("1,0.5,2".parse::<EnvSpec>().unwrap(), EnvSpec::Uniform(Vec3::new(1.0, 0.5, 2.0)));
        assert_eq!("sky.HDR".parse::<EnvSpec>().unwrap(), EnvSpec::File("sky.HDR".into()));
        for bad in ["1,2", "1,2,3,4", "-1,0,0", "a,b,c", "nan,1,1", "sky.png"] {
            assert!(bad.parse::<EnvSpec>().is_err(), "{bad}");
        }
    }

    #[test]
    fn sun_parses_and_gives_its_irradiance() {
        let s: Sun = "0,2,0;800,760,700".parse().unwrap();
        assert_eq!((s.direction, s.angle_deg), (Vec3::Y, 0.53));
        // E = L pi sin^2(radius) for a surface facing it.
        let r = (0.5f32 * 0.53).to_radians();
        let e = s.radiance() * std::f32::consts::PI * r.sin() * r.sin();
        assert!((e - s.irradiance).abs().max_element() < 1e-2, "{e}");
        assert_eq!("1,0,0;1,1,1;5".parse::<Sun>().unwrap().angle_deg, 5.0);
        for bad in ["0,0,0;1,1,1", "0,1,0;1,1", "0,1,0;1,-1,1", "0,1,0;1,1,1;0", "0,1,0;1,1,1;91", "0,1,0"] {
            let e = bad.parse::<Sun>().unwrap_err();
            assert!(e.contains("--sun") && e.contains(bad), "{bad}: {e}");
        }
    }

    /// The texel solid angles of a map cover the sphere.
    #[test]
    fn texel_solid_angles_sum_to_the_sphere() {
        let env = Environment::from_texels("t", 7, 5, vec![Vec3::ONE; 35]);
        let total: f32 = (0..5).map(|r| env.texel_solid_angle(r) * 7.0).sum();
        assert!((total - 4.0 * std::f32::consts::PI).abs() < 1e-4, "{total}");
    }

    #[test]
    fn lookup_follows_the_conventions() {
        // 4 x 2: top row 0..4, bottom row 4..8.
        let texels = (0..8).map(|i| Vec3::splat(i as f32)).collect();
        let mut env = Environment::from_texels("t", 4, 2, texels);
        let near = |w: Vec3| env_index(&env, w);
        assert_eq!(near(Vec3::new(0.01, 0.5, -1.0).normalize()), 2.0); // just right of -Z, upper
        assert_eq!(near(Vec3::new(0.99, -0.1, 0.0).normalize()), 7.0); // +X, lower
        assert_eq!(near(Vec3::new(-0.01, 0.3, -1.0).normalize()), 1.0); // just left of -Z
        assert_eq!(near(Vec3::new(-0.01, 0.3, 1.0).normalize()), 0.0); // +Z, just past the seam
        env.rotate_deg = 90.0;
        assert_eq!(env_index(&env, Vec3::new(0.01, 0.5, -1.0).normalize()), 3.0);
    }

    fn env_index(env: &Environment, w: Vec3) -> f32 {
        env.radiance(w).x
    }
}
