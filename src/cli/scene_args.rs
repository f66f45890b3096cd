//! The scene and camera arguments shared by every subcommand that needs a scene (`info`
//! now; `render`, `view` and `bench` later): `#[command(flatten)] scene: SceneArgs`.

use std::path::PathBuf;
use std::time::{Duration, Instant};

use anyhow::bail;
use bidir::scene::{self, Camera, EnvSpec, Environment, LoadOptions, QuadLight, Scene, Sun, DEFAULT_IMAGE_SIZE};
use glam::Vec3;

/// Texels of the `--sky` map: 0.7 degrees each, fine against the sky's smooth gradients (the
/// sun itself is `--sun`'s disk, not a texel).
const SKY_MAP_SIZE: (u32, u32) = (512, 256);

#[derive(clap::Args, Debug, Clone, Default)]
pub struct SceneArgs {
    /// Scene file: .obj (with its .mtl), .gltf or .glb [default: the built-in Cornell box]
    #[arg(value_name = "SCENE")]
    pub scene: Option<PathBuf>,
    /// Scene camera to use, by name or index [default: the first; a scene without cameras is
    /// framed from -Z (OBJ) or from +Z, the front of a glTF asset]
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
    #[arg(long, value_name = "DEG", allow_hyphen_values = true)]
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
    /// Add an emissive parallelogram (repeatable; quote it, ';' ends a shell command):
    /// corner C, edges E1 and E2, radiance R,G,B. Its corners are C, C+E1, C+E1+E2, C+E2; it
    /// emits from its front face only, the side from which C, C+E1, C+E1+E2 run
    /// counter-clockwise (normal E1 x E2). Each quad gets its own black emissive material.
    /// Example: --quad-light "-1,10,-1;2,0,0;0,0,2;50,50,50" (2x2, facing down)
    #[arg(long = "quad-light", value_name = "C;E1;E2;R,G,B", allow_hyphen_values = true)]
    pub quad_lights: Vec<QuadLight>,
    /// Add the modified Sponza's lights (thesis 5.2.2): a small, very bright sun shining
    /// down through the atrium's open roof at 24 degrees from the zenith and a large, dim blue
    /// sky above it. Placed for ../shared/scenes/sponza/Sponza.gltf; `bidir info SCENE
    /// --sponza-sun-sky` prints them as --quad-light values
    #[arg(long)]
    pub sponza_sun_sky: bool,
    /// Environment light: R,G,B (uniform radiance), an equirectangular FILE.hdr or FILE.exr
    /// (linear; +Y up, the map's middle seen looking along -Z), or none [default: none, or a
    /// uniform white environment of radiance 1, with a warning, for a scene with no light]
    #[arg(long, value_name = "R,G,B|FILE|none")]
    pub env: Option<EnvSpec>,
    /// Multiply the environment's radiance
    #[arg(long, value_name = "S", default_value_t = 1.0)]
    pub env_scale: f32,
    /// Turn the environment about the up axis (+Y), in degrees
    #[arg(long, value_name = "DEG", default_value_t = 0.0, allow_hyphen_values = true)]
    pub env_rotate: f32,
    /// A sun, added to the environment (quote it): the direction toward it, the irradiance
    /// it gives a surface facing it, and its apparent diameter in degrees [default: 0.53],
    /// e.g. --sun "0.3,1,0.2;800,760,700"
    #[arg(long, value_name = "DIR;R,G,B;ANGLE", allow_hyphen_values = true)]
    pub sun: Option<Sun>,
    /// A clear sky (Preetham et al. 1999) as the environment, toward --sun's direction (or
    /// sun=X,Y,Z), quoted: e.g. --sky "turbidity=3;albedo=0.3" [defaults: turbidity 3 (2:
    /// very clear, 6: hazy), ground albedo 0.3, scale 1 (radiance = luminance / 683 lm/W)]
    #[arg(long, value_name = "turbidity=T;albedo=A;scale=S;sun=X,Y,Z", num_args = 0..=1, default_missing_value = "")]
    pub sky: Option<bidir::scene::SkySpec>,
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

    /// The emissive quads the flags add, each with its material name.
    pub fn added_lights(&self) -> Vec<(QuadLight, String)> {
        let mut lights: Vec<(QuadLight, String)> = Vec::new();
        if self.sponza_sun_sky {
            let [sun, sky] = QuadLight::sponza_sun_sky();
            lights.extend([(sun, "sponza-sun".to_owned()), (sky, "sponza-sky".to_owned())]);
        }
        lights.extend(self.quad_lights.iter().enumerate().map(|(i, q)| (*q, format!("quad-light-{i}"))));
        lights
    }

    /// Loads the scene file (or the built-in Cornell box), resolves the camera, then adds the
    /// lights of `--quad-light` / `--sponza-sun-sky` (after the camera, so a scene without
    /// cameras is framed on its own geometry, not on lights far above it).
    pub fn load(&self) -> anyhow::Result<LoadedScene> {
        let start = Instant::now();
        let (mut scene, warnings) = match &self.scene {
            Some(path) => {
                let loaded = scene::load(path, &LoadOptions { strict: self.strict })?;
                (loaded.scene, loaded.warnings)
            }
            None => (Scene::builtin_cornell_box(), Vec::new()),
        };
        let load_time = start.elapsed();
        let (camera, camera_index) = self.resolve_camera(&scene)?;
        for (quad, name) in self.added_lights() {
            scene.add_quad_light(&quad, &name);
        }
        scene.check_emission()?;
        let mut warnings = warnings;
        scene.environment = self.environment(&scene, &mut warnings)?;
        Ok(LoadedScene { scene, warnings, camera, camera_index, load_time })
    }

    /// The environment `--env` asks for; without `--env`, a scene that has no emitter, or only
    /// emitters too weak to light it, gets a uniform white one of radiance 1 and a warning, so it
    /// never renders silently black.
    fn environment(&self, scene: &Scene, warnings: &mut Vec<String>) -> anyhow::Result<Option<Environment>> {
        if !(self.env_scale.is_finite() && self.env_scale >= 0.0) {
            bail!("--env-scale {}: must be a finite number >= 0", self.env_scale);
        }
        if !self.env_rotate.is_finite() {
            bail!("--env-rotate {}: must be a finite number of degrees", self.env_rotate);
        }
        let env = match (&self.env, &self.sky) {
            (Some(_), Some(_)) => bail!("--sky and --env both give the environment: choose one"),
            (None, Some(sky)) => Some(self.sky_environment(sky)?),
            (Some(spec), None) => Environment::from_spec(spec)?,
            (None, None) if scene.emitters().is_empty() && scene.punctual_lights.is_empty() && self.sun.is_none() => {
                let w = format!("{}: no emitter, no punctual light and no --env: lit by a uniform white environment of radiance 1 (--env none keeps it dark)", scene.source);
                log::warn!("{w}");
                warnings.push(w);
                Some(Environment::uniform(Vec3::ONE))
            }
            (None, None) => self.dim_emitters_environment(scene, warnings),
        };
        // A sun alone shines from an otherwise black sky.
        let env = match self.sun {
            Some(sun) => Some(Environment { sun: Some(sun), ..env.unwrap_or_else(|| Environment::uniform(Vec3::ZERO)) }),
            None => env,
        };
        Ok(env.map(|e| Environment { scale: self.env_scale, rotate_deg: self.env_rotate, ..e }))
    }

    /// A scene lit only by emitters too weak for its size (DamagedHelmet's glowing visor:
    /// 0.15 % of the light the default environment would give) renders nearly black, where a
    /// glTF viewer shows the model under an environment: it gets the default white environment
    /// as well as its own light, and one line says so and how to keep only its own.
    fn dim_emitters_environment(&self, scene: &Scene, warnings: &mut Vec<String>) -> Option<Environment> {
        if !scene.punctual_lights.is_empty() || self.sun.is_some() {
            return None;
        }
        let ratio = scene.emitted_light_ratio().filter(|r| *r < bidir::scene::DIM_EMISSION_RATIO)?;
        let w = format!(
            "{}: its emitters are weak for its size (they give it {:.2} % of the light a uniform environment of radiance 1 would), no punctual light and no --env: lit by a uniform white environment of radiance 1 as well (--env none keeps only its own light)",
            scene.source,
            100.0 * ratio
        );
        log::warn!("{w}");
        warnings.push(w);
        Some(Environment::uniform(Vec3::ONE))
    }

    /// `--sky`'s map, its sun where `--sun` is (its irradiance lights the ground too).
    fn sky_environment(&self, sky: &bidir::scene::SkySpec) -> anyhow::Result<Environment> {
        let sun = match (sky.sun, self.sun) {
            (Some(a), Some(b)) if a.dot(b.direction) < 0.9999 => bail!(
                "--sky sun={} and --sun {} differ: give the direction once",
                bidir::scene::fmt_vec(a),
                bidir::scene::fmt_vec(b.direction)
            ),
            (_, Some(s)) => s.direction,
            (Some(d), None) => d,
            (None, None) => bail!("--sky needs the sun's direction: give --sun \"DIR;R,G,B\" or --sky \"sun=X,Y,Z\""),
        };
        if sun.y <= 0.0 {
            bail!("--sky: the sun ({}) is below the horizon, where Preetham's clear-sky model does not hold", bidir::scene::fmt_vec(sun));
        }
        let irradiance = self.sun.map_or(Vec3::ZERO, |s| s.irradiance);
        Ok(Environment::preetham_sky(sky, sun, irradiance, self.env_rotate, SKY_MAP_SIZE.0, SKY_MAP_SIZE.1))
    }

    /// The camera: `--camera` (or the scene's first, or a framing of its bounds), then each
    /// flag given overrides its field. Fails if the result cannot form an image.
    pub fn resolve_camera(&self, scene: &Scene) -> anyhow::Result<(Camera, Option<usize>)> {
        if let Some(v) = self.fov {
            if !(v > 0.0 && v < 180.0) {
                bail!("--fov {v}: must be in (0, 180)");
            }
        }
        for (flag, v) in [("--width", self.width), ("--height", self.height)] {
            if v == Some(0) {
                bail!("{flag} 0: must be at least 1");
            }
        }
        let (mut cam, index) = match &self.camera {
            Some(sel) => {
                let i = find_camera(scene, sel)?;
                (scene.cameras[i].clone(), Some(i))
            }
            None => match scene.cameras.first() {
                Some(c) => (c.clone(), Some(0)),
                None => {
                    let (w, h) = DEFAULT_IMAGE_SIZE;
                    let (w, h) = (self.width.unwrap_or(w), self.height.unwrap_or(h));
                    // glTF assets face +Z: look at their front, toward -Z.
                    let gltf = self
                        .scene
                        .as_ref()
                        .and_then(|p| p.extension())
                        .and_then(|e| e.to_str())
                        .is_some_and(|e| e.eq_ignore_ascii_case("gltf") || e.eq_ignore_ascii_case("glb"));
                    let look = if gltf { -Vec3::Z } else { Vec3::Z };
                    (Camera::framing_along(&scene.bounds(), w, h, look), None)
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
        // A scene's camera is named with its file (the flags were checked above).
        cam.validate().map_err(|e| match index {
            Some(_) => anyhow::anyhow!("{}: {e}", scene.source),
            None => e.into(),
        })?;
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

/// `x,y,z`, e.g. `278,273,-800` (shared with `--quad-light`, hence in the library).
pub use bidir::scene::parse_vec3;

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

    #[test]
    fn light_flags_parse_and_add_emitters() {
        let a = args(&["--quad-light", "-100,500,-100;0,0,50;40,0,0;5,5,5", "--quad-light", "0,0,0;1,0,0;0,1,0;0,0,2"]).unwrap();
        assert_eq!(a.quad_lights.len(), 2);
        assert_eq!(a.quad_lights[0].corner, Vec3::new(-100.0, 500.0, -100.0));
        let base = Scene::builtin_cornell_box();
        let l = a.load().unwrap();
        assert_eq!(l.scene.triangle_count(), base.triangle_count() + 4);
        assert_eq!(l.scene.emitters().len(), base.emitters().len() + 4);
        let names: Vec<&str> = l.scene.materials.iter().rev().take(2).map(|m| m.name.as_str()).collect();
        assert_eq!(names, ["quad-light-1", "quad-light-0"]);

        // A scene without cameras is framed on its geometry, not on lights added above it.
        let obj = std::env::temp_dir().join(format!("bidir-scene-args-{}.obj", std::process::id()));
        std::fs::write(&obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
        let path = obj.to_str().unwrap();
        let plain = args(&[path]).unwrap().load().unwrap();
        let lit = args(&[path, "--quad-light", "0,100,0;1,0,0;0,0,1;1,1,1"]).unwrap().load().unwrap();
        std::fs::remove_file(&obj).unwrap();
        assert_eq!(plain.camera_index, None);
        assert_eq!(lit.camera, plain.camera);
        assert_eq!(lit.scene.emitters().len(), 2);

        let l = args(&["--sponza-sun-sky"]).unwrap().load().unwrap();
        assert_eq!(l.scene.emitters().len(), base.emitters().len() + 4);
        let sun = l.scene.materials.iter().find(|m| m.name == "sponza-sun").expect("a sun material");
        assert!(sun.emission.min_element() > 1000.0);
        assert!(l.scene.materials.iter().any(|m| m.name == "sponza-sky"));
    }

    #[test]
    fn bad_light_flags_are_refused_with_the_reason() {
        let err = |a: &[&str]| args(a).expect_err("refused").to_string();
        let e = err(&["--quad-light", "0,0,0;1,0,0;0,1,0"]);
        assert!(e.contains("--quad-light") && e.contains("CORNER;EDGE1;EDGE2;R,G,B"), "{e}");
        let e = err(&["--quad-light", "0,0,0;1,0,0;2,0,0;1,1,1"]);
        assert!(e.contains("parallel or zero"), "{e}");
        let e = err(&["--quad-light", "0,0,0;1,0,0;0,1,0;1,1,-1"]);
        assert!(e.contains("radiance 1,1,-1 must be >= 0"), "{e}");
        let e = err(&["--quad-light", "0,0,0;1,0,0;0,1,z;1,1,1"]);
        assert!(e.contains("edge2: 'z' in '0,1,z' is not a finite number"), "{e}");
    }
}
