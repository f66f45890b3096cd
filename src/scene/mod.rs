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
mod dim;
mod env;
mod error;
mod gltf;
mod mtl;
mod obj;
mod obj_check;
mod punctual;
mod quad_light;
mod sky;
mod stats;
pub mod tangents;
mod texture;
mod warnings;

pub use builtin::BUILTIN_SOURCE;
pub use camera::{fmt_vec, CORNELL_BOX_CAMERA_NAME, DEFAULT_IMAGE_SIZE};
pub use dim::DIM_EMISSION_RATIO;
pub use env::{EnvError, EnvSpec, Environment, Sun};
pub use error::SceneError;
pub use gltf::load_gltf;
pub use obj::{load_obj, load_obj_str};
pub use punctual::{PunctualKind, PunctualLight};
pub use quad_light::{parse_vec3, QuadLight, QuadLightError};
pub use sky::{Preetham, SkySpec};
pub use stats::{luminance, Aabb, Emitter, Features, GpuBytes, MaterialCounts, GPU_MATERIAL_BYTES};
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
    let loaded = match ext.as_deref() {
        Some("obj") => load_obj(path, opts),
        Some("gltf") | Some("glb") => load_gltf(path, opts),
        _ => Err(SceneError::UnknownFormat { file: path.to_path_buf() }),
    }?;
    loaded.scene.check_emission()?;
    Ok(loaded)
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
    /// Per-vertex tangents from the file (glTF TANGENT: xyz, w = handedness), only where
    /// every part has them; else tangents are generated from the UVs (`tangents.rs`).
    pub tangents: Option<Vec<glam::Vec4>>,
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

/// Which reflection model a material's non-delta part follows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MaterialModel {
    /// The thesis' lobes: Lambertian, mirror, smooth glass; with `roughness > 0` the mirror
    /// fraction is a rough (GGX) conductor with F = 1.
    #[default]
    Thesis,
    /// glTF 2.0 metallic-roughness (appendix B): GGX lobes, the metal with F0 = albedo, the
    /// dielectric coat (F0 from `ior`) over a Lambertian base, mixed by `metallic`.
    MetalRough,
}

/// The thesis' material model: diffuse albedo (colour or texture), emission, a fraction of
/// perfect mirror and a fraction of smooth dielectric; or the glTF metallic-roughness model
/// ([`MaterialModel`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub name: String,
    /// Linear RGB diffuse albedo (multiplied with the texture where there is one).
    pub albedo: Vec3,
    pub albedo_texture: Option<u32>,
    /// Emitted radiance, linear RGB, from the front face only (times the emission texture).
    pub emission: Vec3,
    /// sRGB texture scaling the emission (glTF emissiveTexture, `map_Ke`).
    pub emission_texture: Option<u32>,
    /// Fraction of perfect mirror reflection (0..1).
    pub reflectivity: f32,
    /// Fraction of smooth dielectric transmission/reflection (0..1).
    pub refractivity: f32,
    /// Index of refraction for the dielectric part.
    pub ior: f32,
    /// Alpha-tested cut-out: texels with alpha below the cutoff are holes.
    pub alpha: Option<AlphaMask>,
    /// glTF `BLEND`: stochastic opacity, alpha = `blend` × the base colour texture's alpha.
    pub blend: Option<f32>,
    /// Tangent-space normal map (linear; glTF normalTexture) and its scale of X and Y.
    pub normal_texture: Option<u32>,
    pub normal_scale: f32,
    pub model: MaterialModel,
    /// Metallic factor (MetalRough), times the metallic texture's blue channel.
    pub metallic: f32,
    /// GGX roughness (alpha = roughness²), times the roughness texture's green channel.
    pub roughness: f32,
    /// Linear texture whose green channel scales the roughness (glTF metallicRoughness, `map_Pr`).
    pub roughness_texture: Option<u32>,
    /// Linear texture whose blue channel scales the metallic factor (glTF metallicRoughness, `map_Pm`).
    pub metallic_texture: Option<u32>,
    /// Linear texture whose red channel scales `refractivity` (glTF transmissionTexture).
    pub transmission_texture: Option<u32>,
    /// Absorption coefficient sigma_a per unit length, per channel, inside a closed mesh of
    /// this material (glTF KHR_materials_volume: Beer-Lambert, docs/integrators.md); zero:
    /// no volume.
    pub absorption: Vec3,
    /// glTF KHR_materials_specular (MetalRough): specularFactor, the strength of the
    /// dielectric coat's reflection (its F90; 1 = plain glTF), and specularColorFactor,
    /// which scales the coat's F0 (linear RGB; 1 = plain glTF).
    pub specular: f32,
    pub specular_colour: Vec3,
    /// Linear texture whose alpha scales `specular` (glTF specularTexture).
    pub specular_texture: Option<u32>,
    /// sRGB texture whose RGB scales `specular_colour` (glTF specularColorTexture).
    pub specular_colour_texture: Option<u32>,
    /// glTF KHR_materials_clearcoat (MetalRough): the clear coat's weight (0: none) and GGX
    /// roughness, a dielectric layer of ior 1.5 over the continuous part (docs/integrators.md,
    /// "Clear coat").
    pub clearcoat: f32,
    pub clearcoat_roughness: f32,
    /// Linear textures whose red channel scales `clearcoat` (clearcoatTexture) and whose green
    /// channel scales `clearcoat_roughness` (clearcoatRoughnessTexture).
    pub clearcoat_texture: Option<u32>,
    pub clearcoat_roughness_texture: Option<u32>,
}

impl Default for Material {
    fn default() -> Self {
        Material {
            name: String::new(),
            albedo: Vec3::splat(0.8),
            albedo_texture: None,
            emission: Vec3::ZERO,
            emission_texture: None,
            reflectivity: 0.0,
            refractivity: 0.0,
            ior: 1.5,
            alpha: None,
            blend: None,
            normal_texture: None,
            normal_scale: 1.0,
            model: MaterialModel::Thesis,
            metallic: 0.0,
            roughness: 0.0,
            roughness_texture: None,
            metallic_texture: None,
            transmission_texture: None,
            absorption: Vec3::ZERO,
            specular: 1.0,
            specular_colour: Vec3::ONE,
            specular_texture: None,
            specular_colour_texture: None,
            clearcoat: 0.0,
            clearcoat_roughness: 0.0,
            clearcoat_texture: None,
            clearcoat_roughness_texture: None,
        }
    }
}

impl Material {
    pub fn is_emissive(&self) -> bool {
        self.emission.max_element() > 0.0
    }

    /// Whether the material has a clear coat (KHR_materials_clearcoat; glTF materials only).
    pub fn has_clearcoat(&self) -> bool {
        self.model == MaterialModel::MetalRough && self.clearcoat > 0.0
    }

    /// Whether the material has a GGX lobe (glTF metallic-roughness, or a rough mirror).
    pub fn is_glossy(&self) -> bool {
        match self.model {
            MaterialModel::MetalRough => true,
            MaterialModel::Thesis => self.reflectivity > 0.0 && self.roughness > 0.0,
        }
    }

    /// What the material is and uses, for `bidir info`: its model, then each lobe and map,
    /// e.g. `metal-rough: GGX, diffuse, base colour map, normal map, emission map`.
    pub fn describe(&self) -> String {
        let mut f: Vec<&str> = Vec::new();
        let kind = match self.model {
            MaterialModel::Thesis => "thesis",
            MaterialModel::MetalRough => "metal-rough",
        };
        let diffuse = match self.model {
            MaterialModel::Thesis => self.reflectivity + self.refractivity < 1.0,
            MaterialModel::MetalRough => self.metallic < 1.0 || self.metallic_texture.is_some(),
        };
        if self.is_glossy() {
            f.push(if self.model == MaterialModel::Thesis { "rough mirror (GGX, F = 1)" } else { "GGX" });
        }
        if diffuse && self.refractivity < 1.0 {
            f.push("diffuse");
        }
        if self.has_mirror() {
            f.push("mirror");
        }
        if self.has_rough_glass() {
            f.push("rough glass (GGX)");
        } else if self.refractivity > 0.0 {
            f.push("glass");
        }
        if self.model == MaterialModel::MetalRough
            && (self.specular != 1.0
                || self.specular_colour != Vec3::ONE
                || self.specular_texture.is_some()
                || self.specular_colour_texture.is_some())
        {
            f.push("specular (KHR_materials_specular)");
        }
        if self.has_clearcoat() {
            f.push("clear coat (KHR_materials_clearcoat)");
        }
        if self.has_volume() {
            f.push("volume (absorbing)");
        }
        if self.is_emissive() {
            f.push("emissive");
        }
        let maps = [
            (self.albedo_texture.is_some(), "base colour map"),
            (self.roughness_texture.is_some(), "roughness map"),
            (self.metallic_texture.is_some(), "metallic map"),
            (self.transmission_texture.is_some(), "transmission map"),
            (self.specular_texture.is_some(), "specular map"),
            (self.specular_colour_texture.is_some(), "specular colour map"),
            (self.normal_texture.is_some(), "normal map"),
            (self.has_clearcoat() && self.clearcoat_texture.is_some(), "clear coat map"),
            (self.has_clearcoat() && self.clearcoat_roughness_texture.is_some(), "clear coat roughness map"),
            (self.emission_texture.is_some() && self.is_emissive(), "emission map"),
            (self.alpha.is_some(), "alpha mask"),
            (self.blend.is_some(), "blend"),
        ];
        f.extend(maps.iter().filter(|(on, _)| *on).map(|(_, name)| *name));
        format!("{kind}: {}", f.join(", "))
    }

    /// Whether the lobe choice here (bsdf.glsl's choose_lobe) can take both a continuous lobe
    /// and a delta or rough-glass one: a mirror or glass fraction beside a continuous part
    /// (1 - reflectivity - refractivity > 0), or a glass fraction scaled by a transmission
    /// texture. Conservative: a rough mirror's fraction counts though its lobe is GGX.
    pub fn mixes_lobes(&self) -> bool {
        let delta = self.reflectivity + self.refractivity;
        delta > 0.0 && (delta < 1.0 || (self.refractivity > 0.0 && self.transmission_texture.is_some()))
    }

    /// Whether the glass fraction is a rough dielectric (roughness > 0; Walter et al. 2007).
    pub fn has_rough_glass(&self) -> bool {
        self.refractivity > 0.0 && self.roughness > 0.0
    }

    /// Whether a closed mesh of this material absorbs inside (KHR_materials_volume).
    pub fn has_volume(&self) -> bool {
        self.absorption.max_element() > 0.0
    }

    /// Whether the thesis' perfect mirror (a delta lobe) is used.
    pub fn has_mirror(&self) -> bool {
        self.reflectivity > 0.0 && !self.is_glossy()
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
