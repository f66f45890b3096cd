//! The scene in GPU memory, modelling no more than the scene has: vertex normals, UVs and
//! textures are uploaded only when present (a 4-byte placeholder is bound otherwise) and the
//! kernels are specialised on [`SceneFeatures`] so they run no code for what is absent.

use super::env::{light_disk, EnvTable};
use super::lights::{luminance, LightTable};
use crate::bvh::Bvh;
use crate::gpu::abi::{self, GpuMaterial, GpuPunctual, GpuTexture};
use crate::gpu_data::{GpuBvh, SceneFeatures};
use crate::scene::{Material, MaterialModel, Scene, Texture};
use crate::vk::{Bind, Buffer, Context, Memory, Result};
use glam::UVec4;

/// Every buffer the integrators read.
pub struct GpuScene {
    pub bvh: GpuBvh,
    pub prim_info: Buffer,
    pub materials: Buffer,
    pub emitters: Buffer,
    pub alias: Buffer,
    pub emitter_uvs: Buffer,
    pub normals: Buffer,
    pub tangents: Buffer,
    pub uvs: Buffer,
    pub textures: Buffer,
    pub texels: Buffer,
    pub positions: Buffer,
    /// The environment (`GpuEnv`), its texels and alias table; placeholders without one.
    pub env: Buffer,
    pub env_texels: Buffer,
    pub env_alias: Buffer,
    pub punctual: Buffer,
    /// The code the kernels are specialised for: what the scene has, or everything under
    /// `RenderSettings::all_material_code`.
    pub features: SceneFeatures,
    /// What the scene has, never widened by `all_material_code`: the estimators' defaults (BDPT's
    /// MIS heuristic, light paths per pixel, connection candidates) follow it, so that compiling
    /// all the material code in measures the same estimator.
    pub estimator_features: SceneFeatures,
    pub emitter_count: u32,
    pub emitter_weight: f32,
    /// Total bytes uploaded.
    pub bytes: u64,
    /// Textures were halved this many times to fit the device's storage-buffer limit.
    pub texture_downsamples: u32,
}

impl GpuScene {
    pub fn upload(ctx: &Context, scene: &Scene, bvh: &Bvh) -> Result<GpuScene> {
        let mut features = SceneFeatures::of(scene);
        let materials: Vec<GpuMaterial> = scene.materials.iter().map(gpu_material).collect();
        // Triangles whose material can turn a hit away are marked for the alpha-tested
        // traversal, as traverse_alpha_hit (scene.glsl) decides: it keeps every hit on the rest.
        let may_reject = |t: u32| {
            let m = &materials[scene.material_ids[t as usize] as usize];
            let opaque = m.opacity >= 1.0 && m.alpha_texture == 0;
            m.alpha_cutoff > 0.0 || !opaque
        };
        let gbvh = GpuBvh::upload_with_tris(ctx, bvh, &bvh.alpha_marked_tris(may_reject))?;
        let prim_info: Vec<UVec4> = bvh
            .tri_ids
            .iter()
            .map(|&t| {
                let [a, b, c] = scene.triangles[t as usize];
                UVec4::new(a, b, c, scene.material_ids[t as usize])
            })
            .collect();
        let lights = LightTable::build(scene);
        let placeholder = |name: &str| ctx.create_buffer(name, 4, Memory::Device);
        let normals = match (&scene.normals, features.normals) {
            (Some(n), true) => ctx.upload_buffer("scene.normals", &n.iter().flat_map(|v| v.to_array()).collect::<Vec<f32>>())?,
            _ => placeholder("scene.normals (none)")?,
        };
        let tangents = match features.normal_maps.then(|| crate::scene::tangents::generate(scene)).flatten() {
            Some(t) => ctx.upload_buffer("scene.tangents", &t)?,
            None => placeholder("scene.tangents (none)")?,
        };
        let uvs = match (&scene.uvs, features.uvs) {
            (Some(uv), true) => ctx.upload_buffer("scene.uvs", uv)?,
            _ => placeholder("scene.uvs (none)")?,
        };
        let (table, texels, downsamples) = if features.textures {
            pack_textures(&scene.textures, ctx.info().max_storage_buffer_range as u64)
        } else {
            (Vec::new(), Vec::new(), 0)
        };
        if downsamples > 0 {
            log::warn!(
                "textures halved {downsamples} time(s) to fit {} MiB storage buffers on {}",
                ctx.info().max_storage_buffer_range >> 20,
                ctx.info().name
            );
        }
        let textures = if table.is_empty() { placeholder("scene.textures (none)")? } else { ctx.upload_buffer("scene.textures", &table)? };
        let texels = if texels.is_empty() { placeholder("scene.texels (none)")? } else { ctx.upload_buffer("scene.texels", &texels)? };
        let emitters = if lights.emitters.is_empty() {
            placeholder("scene.emitters (none)")?
        } else {
            ctx.upload_buffer("scene.emitters", &lights.emitters)?
        };
        let alias =
            if lights.alias.is_empty() { placeholder("scene.alias (none)")? } else { ctx.upload_buffer("scene.alias", &lights.alias)? };
        let emitter_uvs = match features.emission_textures && !lights.emitters.is_empty() {
            true => ctx.upload_buffer("scene.emitter_uvs", &lights.emitter_uvs(scene))?,
            false => placeholder("scene.emitter_uvs (none)")?,
        };
        // Light sampling splits evenly between the kinds of light the scene has.
        let bounds = scene.bounds();
        let has_env = scene.environment.as_ref().is_some_and(|e| !e.is_black());
        let punctual: Vec<GpuPunctual> = scene.punctual_lights.iter().map(gpu_punctual).collect();
        let kinds = [!lights.emitters.is_empty(), has_env, !punctual.is_empty()].iter().filter(|k| **k).count();
        let share = 1.0 / kinds.max(1) as f32;
        let env_table = scene.environment.as_ref().and_then(|e| EnvTable::build(e, &bounds, share));
        features.env = env_table.is_some();
        features.punctual = !punctual.is_empty();
        let mut header = env_table.as_ref().map_or_else(
            || {
                let (bounds, disk_area) = light_disk(&bounds);
                abi::GpuEnv { bounds, disk_area, sun_cos_max: 2.0, ..bytemuck::Zeroable::zeroed() }
            },
            |t| t.env,
        );
        header.punctual_count = punctual.len() as u32;
        header.punctual_pick = if punctual.is_empty() { 0.0 } else { share };
        let env = ctx.upload_buffer("scene.env", std::slice::from_ref(&header))?;
        let (env_texels, env_alias) = match &env_table {
            Some(t) => (ctx.upload_buffer("scene.env_texels", &t.texels)?, ctx.upload_buffer("scene.env_alias", &t.alias)?),
            None => (placeholder("scene.env_texels (none)")?, placeholder("scene.env_alias (none)")?),
        };
        let punctual =
            if punctual.is_empty() { placeholder("scene.punctual (none)")? } else { ctx.upload_buffer("scene.punctual", &punctual)? };
        let positions = ctx.upload_buffer("scene.positions", &scene.positions.iter().flat_map(|v| v.to_array()).collect::<Vec<f32>>())?;
        let prim_info = ctx.upload_buffer("scene.prim_info", &prim_info)?;
        let materials = ctx.upload_buffer("scene.materials", &materials)?;
        let bytes = [
            &prim_info,
            &materials,
            &emitters,
            &alias,
            &emitter_uvs,
            &normals,
            &tangents,
            &uvs,
            &textures,
            &texels,
            &positions,
            &env,
            &env_texels,
            &env_alias,
            &punctual,
        ]
        .iter()
        .map(|b| b.size())
        .sum::<u64>()
            + gbvh.bytes;
        Ok(GpuScene {
            bvh: gbvh,
            prim_info,
            materials,
            emitters,
            alias,
            emitter_uvs,
            normals,
            tangents,
            uvs,
            textures,
            texels,
            positions,
            env,
            env_texels,
            env_alias,
            punctual,
            features,
            estimator_features: features,
            emitter_count: lights.emitters.len() as u32,
            emitter_weight: lights.total_weight,
            bytes,
            texture_downsamples: downsamples,
        })
    }

    /// Bindings of every scene buffer (glsl/common/scene.glsl).
    pub fn binds(&self) -> Vec<Bind<'_>> {
        vec![
            Bind::buffer(abi::BIND_NODES, &self.bvh.nodes),
            Bind::buffer(abi::BIND_TRIS, &self.bvh.tris),
            Bind::buffer(abi::BIND_PRIM_INFO, &self.prim_info),
            Bind::buffer(abi::BIND_MATERIALS, &self.materials),
            Bind::buffer(abi::BIND_EMITTERS, &self.emitters),
            Bind::buffer(abi::BIND_ALIAS, &self.alias),
            Bind::buffer(abi::BIND_EMITTER_UVS, &self.emitter_uvs),
            Bind::buffer(abi::BIND_NORMALS, &self.normals),
            Bind::buffer(abi::BIND_TANGENTS, &self.tangents),
            Bind::buffer(abi::BIND_UVS, &self.uvs),
            Bind::buffer(abi::BIND_TEXTURES, &self.textures),
            Bind::buffer(abi::BIND_TEXELS, &self.texels),
            Bind::buffer(abi::BIND_POSITIONS, &self.positions),
            Bind::buffer(abi::BIND_ENV, &self.env),
            Bind::buffer(abi::BIND_ENV_TEXELS, &self.env_texels),
            Bind::buffer(abi::BIND_ENV_ALIAS, &self.env_alias),
            Bind::buffer(abi::BIND_PUNCTUAL, &self.punctual),
        ]
    }
}

/// A material as the kernels read it (`GpuMaterial` in src/gpu/abi.rs).
pub fn gpu_material(m: &Material) -> GpuMaterial {
    let index = |t: Option<u32>| t.map_or(0, |t| t + 1);
    // KHR_materials_specular: the coat's F0, coloured (the kernels clamp it after the texture).
    let specular_f0 = ((m.ior - 1.0) / (m.ior + 1.0)).powi(2) * m.specular_colour;
    GpuMaterial {
        albedo: m.albedo,
        // A MASK cutoff stays positive: 0 means "not MASK" to the kernels.
        alpha_cutoff: m.alpha.map_or(0.0, |a| a.cutoff.max(f32::MIN_POSITIVE)),
        emission: m.emission,
        emission_luminance: luminance(m.emission),
        reflectivity: m.reflectivity,
        refractivity: m.refractivity,
        ior: m.ior,
        transmission_texture: index(m.transmission_texture),
        albedo_texture: index(m.albedo_texture),
        alpha_texture: match (m.alpha, m.blend) {
            (Some(a), _) => a.texture + 1,
            (None, Some(_)) => index(m.albedo_texture),
            (None, None) => 0,
        },
        roughness_texture: index(m.roughness_texture),
        metallic_texture: index(m.metallic_texture),
        emission_texture: index(m.emission_texture),
        normal_texture: index(m.normal_texture),
        normal_scale: m.normal_scale,
        opacity: m.blend.unwrap_or(1.0),
        metallic: m.metallic,
        roughness: m.roughness,
        specular_texture: index(m.specular_texture),
        sigma_a: m.absorption,
        specular_colour_texture: index(m.specular_colour_texture),
        specular_f0,
        specular: m.specular,
        clearcoat: if m.has_clearcoat() { m.clearcoat } else { 0.0 },
        clearcoat_roughness: m.clearcoat_roughness,
        clearcoat_texture: index(m.clearcoat_texture),
        clearcoat_roughness_texture: index(m.clearcoat_roughness_texture),
        model: match m.model {
            MaterialModel::Thesis => abi::MATERIAL_THESIS,
            MaterialModel::MetalRough => abi::MATERIAL_METAL_ROUGH,
        },
    }
}

/// A punctual light as the kernels read it.
fn gpu_punctual(l: &crate::scene::PunctualLight) -> GpuPunctual {
    use crate::scene::PunctualKind;
    let (kind, cos_outer, cos_inner) = match l.kind {
        PunctualKind::Point => (abi::PUNCTUAL_POINT, -1.0, -1.0),
        PunctualKind::Spot { inner, outer } => (abi::PUNCTUAL_SPOT, outer.cos(), inner.cos()),
        PunctualKind::Directional => (abi::PUNCTUAL_DIRECTIONAL, 1.0, 1.0),
    };
    GpuPunctual {
        position: l.position.extend(0.0),
        direction: l.direction.normalize_or_zero().extend(0.0),
        intensity: l.intensity.extend(0.0),
        kind,
        cos_outer,
        cos_inner,
        pad0: 0,
    }
}

/// Concatenates textures as packed RGBA8 words, halving all of them until they fit `limit`
/// bytes. Returns the table, the texels and how many times they were halved.
fn pack_textures(textures: &[Texture], limit: u64) -> (Vec<GpuTexture>, Vec<u32>, u32) {
    let mut level: Vec<(u32, u32, Vec<u8>)> = textures.iter().map(|t| (t.width, t.height, t.rgba8.clone())).collect();
    let mut halvings = 0;
    while level.iter().map(|(w, h, _)| *w as u64 * *h as u64 * 4).sum::<u64>() > limit {
        level = level.into_iter().map(|(w, h, p)| halve(w, h, &p)).collect();
        halvings += 1;
    }
    let mut table = Vec::new();
    let mut texels = Vec::new();
    for (t, (w, h, p)) in textures.iter().zip(level) {
        table.push(GpuTexture { offset: texels.len() as u32, width: w, height: h, flags: if t.srgb { abi::TEXTURE_SRGB } else { 0 } });
        texels.extend(p.chunks_exact(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])));
    }
    (table, texels, halvings)
}

/// 2x2 box downsample of RGBA8 (averaging encoded values; good enough to fit memory).
fn halve(w: u32, h: u32, p: &[u8]) -> (u32, u32, Vec<u8>) {
    let (nw, nh) = ((w / 2).max(1), (h / 2).max(1));
    let mut out = vec![0u8; (nw * nh * 4) as usize];
    for y in 0..nh {
        for x in 0..nw {
            for c in 0..4 {
                let mut s = 0u32;
                for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                    let (sx, sy) = ((2 * x + dx).min(w - 1), (2 * y + dy).min(h - 1));
                    s += p[((sy * w + sx) * 4 + c) as usize] as u32;
                }
                out[((y * nw + x) * 4 + c) as usize] = ((s + 2) / 4) as u8;
            }
        }
    }
    (nw, nh, out)
}

#[cfg(test)]
mod tests {
    /// `Scene::gpu_bytes` (the size checks before upload) counts materials at the GPU size.
    #[test]
    fn material_bytes_match_the_gpu_struct() {
        assert_eq!(std::mem::size_of::<crate::gpu::abi::GpuMaterial>() as u64, crate::scene::GPU_MATERIAL_BYTES);
    }
}
