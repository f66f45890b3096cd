//! The scene model: only what the renderer reads. Loaders (OBJ+MTL, glTF 2.0) and the
//! built-in Cornell box produce a [`Scene`]; the BVH and the GPU upload consume it.
//!
//! "Model no more than a scene needs": normals, UVs and textures are `None`/empty when the
//! file has none, and [`Scene::features`] tells kernels what they can skip.
//!
//! Files, one job each: [`load`] picks the loader by extension; `obj.rs` (+ `obj_check.rs`, the
//! line-numbered validation tobj lacks, and `mtl.rs`, the material library with the thesis'
//! keys) and `gltf/` read files; `builder.rs` assembles the one compact vertex/triangle list
//! both loaders share (normal/UV filling, degenerate triangles); `texture.rs` decodes images
//! in parallel; `camera.rs` holds the pinhole conventions; `stats.rs` the derived data
//! (emitters and their power, bounds, byte counts); `builtin.rs` the embedded Cornell box;
//! `quad_light.rs` emissive quads added from the command line (`--quad-light`, the modified
//! Sponza's sun and sky).

mod builder;
mod builtin;
mod camera;
mod env;
mod error;
mod gltf;
mod mtl;
mod obj;
mod obj_check;
mod punctual;
mod quad_light;
mod stats;
mod texture;
mod warnings;

pub use builtin::BUILTIN_SOURCE;
pub use camera::{fmt_vec, CORNELL_BOX_CAMERA_NAME, DEFAULT_IMAGE_SIZE};
pub use env::{EnvError, EnvSpec, Environment, Sun};
pub use error::SceneError;
pub use gltf::load_gltf;
pub use obj::{load_obj, load_obj_str};
pub use punctual::{PunctualKind, PunctualLight};
pub use quad_light::{parse_vec3, QuadLight, QuadLightError};
pub use stats::{luminance, Aabb, Emitter, Features, GpuBytes, MaterialCounts};
pub use texture::srgb_to_linear;

use std::path::Path;

use glam::{Vec2, Vec3};

/// How forgiving a loader is.
#[derive(Clone, Copy, Debug, Default)]
pub struct LoadOptions {
    /// Missing or undecodable material libraries and textures, and unknown material names,
    /// are errors instead of warnings with a fallback (default grey material / no texture).
    pub strict: bool,
}

/// What a loader returns: the scene and the warnings met on the way (each also went to
/// `log::warn!`), for the CLI to print.
#[derive(Clone, Debug)]
pub struct Loaded {
    pub scene: Scene,
    pub warnings: Vec<String>,
}

/// Loads a scene file, choosing the loader by extension: `.obj` (with its `.mtl`),
/// `.gltf` or `.glb`.
pub fn load(path: &Path, opts: &LoadOptions) -> Result<Loaded, SceneError> {
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("obj") => load_obj(path, opts),
        Some("gltf") | Some("glb") => load_gltf(path, opts),
        _ => Err(SceneError::UnknownFormat { file: path.to_path_buf() }),
    }
}

/// Indexed triangles with a material per triangle.
#[derive(Clone, Debug, Default)]
pub struct Scene {
    /// Where it came from (file path, or `builtin:cornell-box`), for messages.
    pub source: String,
    pub positions: Vec<Vec3>,
    /// Per-vertex unit shading normals, only where the file has them. When only part of a
    /// scene has normals, the rest gets its flat face normal (on unshared vertices), so a
    /// kernel never mixes "has normals" and "has none". A zero-length normal in a file stays
    /// zero: kernels fall back to the geometric normal when the interpolated one degenerates.
    pub normals: Option<Vec<Vec3>>,
    /// Per-vertex texture coordinates, only where the file has them. (0, 0) is the top-left
    /// corner of a texture (glTF's convention; OBJ's `v` is flipped on load).
    pub uvs: Option<Vec<Vec2>>,
    /// Vertex indices, counter-clockwise seen from the front.
    pub triangles: Vec<[u32; 3]>,
    /// Index into `materials`, one per triangle.
    pub material_ids: Vec<u32>,
    pub materials: Vec<Material>,
    pub textures: Vec<Texture>,
    pub cameras: Vec<Camera>,
    /// Degenerate (zero-area or non-finite) triangles dropped while loading.
    pub dropped_degenerate: usize,
    /// Light from infinitely far away (`--env`, or the default for a scene without lights);
    /// loaders leave it `None`.
    pub environment: Option<Environment>,
    /// Point, spot and directional lights (glTF KHR_lights_punctual).
    pub punctual_lights: Vec<PunctualLight>,
}

/// The thesis' material model: diffuse albedo (colour or texture), emission, a fraction of
/// perfect mirror and a fraction of smooth dielectric.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub name: String,
    /// Linear RGB diffuse albedo (multiplied with the texture where there is one).
    pub albedo: Vec3,
    pub albedo_texture: Option<u32>,
    /// Emitted radiance, linear RGB, from the front face only.
    pub emission: Vec3,
    /// Fraction of perfect mirror reflection (0..1).
    pub reflectivity: f32,
    /// Fraction of smooth dielectric transmission/reflection (0..1).
    pub refractivity: f32,
    /// Index of refraction for the dielectric part.
    pub ior: f32,
    /// Alpha-tested cut-out: texels with alpha below the cutoff are holes.
    pub alpha: Option<AlphaMask>,
}

impl Default for Material {
    fn default() -> Self {
        Material {
            name: String::new(),
            albedo: Vec3::splat(0.8),
            albedo_texture: None,
            emission: Vec3::ZERO,
            reflectivity: 0.0,
            refractivity: 0.0,
            ior: 1.5,
            alpha: None,
        }
    }
}

impl Material {
    pub fn is_emissive(&self) -> bool {
        self.emission.max_element() > 0.0
    }
}

/// Where an alpha-tested material reads its alpha.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AlphaMask {
    pub texture: u32,
    pub cutoff: f32,
}

/// A decoded texture: RGBA8, rows top to bottom.
#[derive(Clone, Debug)]
pub struct Texture {
    pub name: String,
    pub width: u32,
    pub height: u32,
    /// RGBA8 texels, `width * height * 4` bytes.
    pub rgba8: Vec<u8>,
    /// Colour data is sRGB-encoded and must be linearised when sampled.
    pub srgb: bool,
}

/// A pinhole camera, with the conventions of `scenes/cornell-box/README.md`: image row 0 at
/// the top, camera right = forward × up (so forward (0,0,1), up (0,1,0) gives right (-1,0,0)).
/// See `camera.rs` for ray generation and projection.
#[derive(Clone, Debug, PartialEq)]
pub struct Camera {
    pub name: String,
    pub eye: Vec3,
    pub target: Vec3,
    pub up: Vec3,
    /// Vertical field of view in degrees.
    pub fov_y_deg: f32,
    pub width: u32,
    pub height: u32,
}
