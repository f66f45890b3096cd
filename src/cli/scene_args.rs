//! The scene and camera arguments shared by every subcommand that needs a scene (`info`
//! now; `render`, `view` and `bench` later): `#[command(flatten)] scene: SceneArgs`.

use std::path::PathBuf;
use std::time::{Duration, Instant};

use anyhow::{bail, Context as _};
use bidir::scene::{self, Camera, LoadOptions, Scene, DEFAULT_IMAGE_SIZE};
use glam::Vec3;

#[derive(clap::Args, Debug, Clone, Default)]
pub struct SceneArgs {
    /// Scene file: .obj (with its .mtl), .gltf or .glb [default: the built-in Cornell box]
    #[arg(value_name = "SCENE")]
    pub scene: Option<PathBuf>,
    /// Scene camera to use, by name or index [default: the first; a scene without cameras is
    /// framed from -Z]
    #[arg(long, value_name = "NAME|INDEX")]
    pub camera: Option<String>,
    /// Camera position, e.g. 278,273,-800 (overrides the chosen camera's)
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_vec3, allow_hyphen_values = true)]
    pub eye: Option<Vec3>,
    /// Point the camera looks at
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_vec3, allow_hyphen_values = true)]
    pub target: Option<Vec3>,
    /// Camera up direction
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_vec3, allow_hyphen_values = true)]
    pub up: Option<Vec3>,
    /// Vertical field of view in degrees
    #[arg(long, value_name = "DEG")]
    pub fov: Option<f32>,
    /// Image width in pixels
    #[arg(long, value_name = "PIXELS")]
    pub width: Option<u32>,
    /// Image height in pixels
    #[arg(long, value_name = "PIXELS")]
    pub height: Option<u32>,
    /// Treat a missing or undecodable material library or texture, or an unknown material
    /// name, as an error instead of a warning
    #[arg(long)]
    pub strict: bool,
}

/// A loaded scene with the camera the flags chose.
pub struct LoadedScene {
    pub scene: Scene,
    /// Loader warnings, for the caller to print.
    pub warnings: Vec<String>,
    pub camera: Camera,
    /// Index into `scene.cameras` of the camera the flags started from, if any.
    pub camera_index: Option<usize>,
    pub load_time: Duration,
}

impl SceneArgs {
    /// Whether any camera flag was given.
    pub fn has_camera_flags(&self) -> bool {
        self.camera.is_some()
            || self.eye.is_some()
            || self.target.is_some()
            || self.up.is_some()
            || self.fov.is_some()
            || self.width.is_some()
            || self.height.is_some()
    }

    /// Loads the scene file (or the built-in Cornell box) and resolves the camera.
    pub fn load(&self) -> anyhow::Result<LoadedScene> {
        let start = Instant::now();
        let (scene, warnings) = match &self.scene {
            Some(path) => {
                let loaded = scene::load(path, &LoadOptions { strict: self.strict })?;
                (loaded.scene, loaded.warnings)
            }
            None => (Scene::builtin_cornell_box(), Vec::new()),
        };
        let load_time = start.elapsed();
        let (camera, camera_index) = self.resolve_camera(&scene)?;
        Ok(LoadedScene { scene, warnings, camera, camera_index, load_time })
    }

    /// The camera: `--camera` (or the scene's first, or a framing of its bounds), then each
    /// flag given overrides its field. Fails if the result cannot form an image.
    pub fn resolve_camera(&self, scene: &Scene) -> anyhow::Result<(Camera, Option<usize>)> {
        let (mut cam, index) = match &self.camera {
            Some(sel) => {
                let i = find_camera(scene, sel)?;
                (scene.cameras[i].clone(), Some(i))
            }
            None => match scene.cameras.first() {
                Some(c) => (c.clone(), Some(0)),
                None => {
                    let (w, h) = DEFAULT_IMAGE_SIZE;
                    (Camera::framing(&scene.bounds(), self.width.unwrap_or(w), self.height.unwrap_or(h)), None)
                }
            },
        };
        if let Some(v) = self.eye {
            cam.eye = v;
        }
        if let Some(v) = self.target {
            cam.target = v;
        }
        if let Some(v) = self.up {
            cam.up = v;
        }
        if let Some(v) = self.fov {
            cam.fov_y_deg = v;
        }
        if let Some(v) = self.width {
            cam.width = v;
        }
        if let Some(v) = self.height {
            cam.height = v;
        }
        cam.validate()?;
        Ok((cam, index))
    }
}

/// A camera by exact name, else by index.
fn find_camera(scene: &Scene, sel: &str) -> anyhow::Result<usize> {
    if let Some(i) = scene.cameras.iter().position(|c| c.name == sel) {
        return Ok(i);
    }
    if let Ok(i) = sel.parse::<usize>() {
        if i < scene.cameras.len() {
            return Ok(i);
        }
    }
    if scene.cameras.is_empty() {
        bail!("--camera {sel}: {} has no cameras (use --eye, --target, --up, --fov instead)", scene.source);
    }
    let names: Vec<String> = scene.cameras.iter().enumerate().map(|(i, c)| format!("{i} {}", c.name)).collect();
    bail!("--camera {sel}: no such camera in {}; it has: {}", scene.source, names.join(", "))
}

/// `x,y,z`, e.g. `278,273,-800`.
pub fn parse_vec3(s: &str) -> Result<Vec3, String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != 3 {
        return Err(format!("expected three numbers separated by commas (like 278,273,-800), got '{s}'"));
    }
    let mut v = [0.0f32; 3];
    for (out, p) in v.iter_mut().zip(&parts) {
        *out = p
            .parse::<f32>()
            .ok()
            .filter(|x| x.is_finite())
            .with_context(|| format!("'{p}' in '{s}' is not a finite number"))
            .map_err(|e| e.to_string())?;
    }
    Ok(Vec3::from_array(v))
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(Parser)]
    struct Cli {
        #[command(flatten)]
        scene: SceneArgs,
    }

    fn args(a: &[&str]) -> Result<SceneArgs, clap::Error> {
        Cli::try_parse_from(std::iter::once("t").chain(a.iter().copied())).map(|c| c.scene)
    }

    #[test]
    fn vectors_parse_with_clear_errors() {
        assert_eq!(parse_vec3("278,273,-800").unwrap(), Vec3::new(278.0, 273.0, -800.0));
        assert_eq!(parse_vec3(" 1, 2.5 ,3e2").unwrap(), Vec3::new(1.0, 2.5, 300.0));
        assert!(parse_vec3("1,2").unwrap_err().contains("three numbers"));
        assert!(parse_vec3("1,2,x").unwrap_err().contains("'x' in '1,2,x' is not a finite number"));
        assert!(parse_vec3("1,2,inf").is_err());
        let e = args(&["--eye", "1,2"]).err().unwrap().to_string();
        assert!(e.contains("--eye") && e.contains("three numbers"), "{e}");
        // A leading minus is a value, not a flag.
        assert_eq!(args(&["--eye", "-1,2,3"]).unwrap().eye, Some(Vec3::new(-1.0, 2.0, 3.0)));
    }

    #[test]
    fn flags_override_the_builtin_camera() {
        let a = args(&["--eye", "0,1,2", "--fov", "60", "--width", "64"]).unwrap();
        let l = a.load().unwrap();
        assert_eq!(l.scene.source, scene::BUILTIN_SOURCE);
        assert_eq!(l.camera_index, Some(0));
        let c = Camera::cornell_box();
        assert_eq!(l.camera, Camera { eye: Vec3::new(0.0, 1.0, 2.0), fov_y_deg: 60.0, width: 64, ..c });
    }

    #[test]
    fn camera_selection() {
        let mut s = Scene::builtin_cornell_box();
        s.cameras.push(Camera { name: "side".into(), eye: Vec3::ZERO, target: Vec3::X, ..Camera::cornell_box() });
        let pick = |sel: &str| args(&["--camera", sel]).unwrap().resolve_camera(&s).map(|(c, i)| (c.name, i));
        assert_eq!(pick("side").unwrap(), ("side".to_owned(), Some(1)));
        assert_eq!(pick("1").unwrap(), ("side".to_owned(), Some(1)));
        assert_eq!(pick("0").unwrap(), ("cornell-box".to_owned(), Some(0)));
        let e = pick("7").unwrap_err().to_string();
        assert!(e.contains("0 cornell-box, 1 side"), "{e}");
        // Flags that make the camera unusable are refused.
        let e = args(&["--target", "278,273,-800"]).unwrap().resolve_camera(&s).unwrap_err().to_string();
        assert!(e.contains("eye and target are the same point"), "{e}");
    }

    #[test]
    fn scene_without_camera_is_framed() {
        let mut s = Scene::builtin_cornell_box();
        s.cameras.clear();
        let (c, i) = args(&["--width", "100", "--height", "50"]).unwrap().resolve_camera(&s).unwrap();
        assert_eq!(i, None);
        assert_eq!((c.width, c.height), (100, 50));
        assert!(c.eye.z < 0.0 && (c.target - s.bounds().center()).length() < 1e-3);
    }
}
