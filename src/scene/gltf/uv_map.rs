//! Texture coordinates per material: the set (`texCoord`, `TEXCOORD_0` or `_1`) and the
//! `KHR_texture_transform` of its texture slots, baked into the UVs of the primitives that use
//! the material when the mesh is read (one UV set per vertex on the GPU).
//!
//! The transform (KHR_texture_transform): uv' = T(offset) R(rotation) S(scale) uv with
//! R = [[cos, sin], [-sin, cos]]; its `texCoord` overrides the slot's. Slots of one material
//! that disagree (another set or transform) are warned about once, and the first slot's (in the
//! order base colour, metallic-roughness, emission, transmission, specular, clear coat,
//! normal map) is used for all.

use std::path::Path;

use ::gltf::Document;
use glam::{Mat3, Vec2};

use crate::scene::warnings::Warnings;

/// How a material's primitives get their UVs: from set `tex_coord`, through `transform`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct UvMap {
    pub tex_coord: u32,
    pub transform: Mat3,
}

impl Default for UvMap {
    fn default() -> Self {
        UvMap { tex_coord: 0, transform: Mat3::IDENTITY }
    }
}

impl UvMap {
    pub fn apply(&self, uv: Vec2) -> Vec2 {
        self.transform.transform_point2(uv)
    }
}

/// T(offset) R(rotation) S(scale) of KHR_texture_transform, as a 2D affine matrix.
fn transform_matrix(offset: [f32; 2], rotation: f32, scale: [f32; 2]) -> Mat3 {
    let (s, c) = rotation.sin_cos();
    let r = Mat3::from_cols(glam::Vec3::new(c, -s, 0.0), glam::Vec3::new(s, c, 0.0), glam::Vec3::Z);
    Mat3::from_translation(Vec2::from(offset)) * r * Mat3::from_scale(Vec2::from(scale))
}

/// A slot whose KHR_texture_transform the `gltf` crate does not parse, from the extension's
/// JSON `t` (if any) and the slot's own set `tex_coord`: the extension's defaults where a field
/// is absent; a field of the wrong shape is taken as absent.
fn of_transform_json(t: Option<&::gltf::json::Value>, tex_coord: u32) -> UvMap {
    let Some(t) = t else {
        return UvMap { tex_coord, transform: Mat3::IDENTITY };
    };
    let pair = |key: &str, default: [f32; 2]| match t.get(key).and_then(|v| v.as_array()).map(Vec::as_slice) {
        Some([x, y]) => match (x.as_f64(), y.as_f64()) {
            (Some(x), Some(y)) => [x as f32, y as f32],
            _ => default,
        },
        _ => default,
    };
    let rotation = t.get("rotation").and_then(|v| v.as_f64()).unwrap_or(0.0) as f32;
    let tex_coord = t.get("texCoord").and_then(|v| v.as_u64()).map_or(tex_coord, |c| c.min(u32::MAX as u64) as u32);
    UvMap { tex_coord, transform: transform_matrix(pair("offset", [0.0, 0.0]), rotation, pair("scale", [1.0, 1.0])) }
}

/// The normal map's slot (the `gltf` crate has no accessor for its transform).
fn of_normal(n: &::gltf::material::NormalTexture) -> UvMap {
    of_transform_json(n.extension_value("KHR_texture_transform"), n.tex_coord())
}

/// KHR_materials_clearcoat's texture slots (material.rs reads that extension from its JSON):
/// the textureInfo objects under `key`s that are present.
fn of_clearcoat(m: &::gltf::Material, key: &str) -> Option<UvMap> {
    let info = m.extension_value("KHR_materials_clearcoat")?.get(key)?;
    let tex_coord = info.get("texCoord").and_then(|v| v.as_u64()).map_or(0, |c| c.min(u32::MAX as u64) as u32);
    Some(of_transform_json(info.get("extensions").and_then(|e| e.get("KHR_texture_transform")), tex_coord))
}

fn of_info(info: &::gltf::texture::Info) -> UvMap {
    match info.texture_transform() {
        Some(t) => {
            UvMap { tex_coord: t.tex_coord().unwrap_or(info.tex_coord()), transform: transform_matrix(t.offset(), t.rotation(), t.scale()) }
        }
        None => UvMap { tex_coord: info.tex_coord(), transform: Mat3::IDENTITY },
    }
}

/// The UV map of each material of `doc`, in order.
pub(super) fn uv_maps(file: &Path, doc: &Document, w: &mut Warnings) -> Vec<UvMap> {
    doc.materials()
        .map(|m| {
            let pbr = m.pbr_metallic_roughness();
            let slots: Vec<UvMap> = [
                pbr.base_color_texture().map(|i| of_info(&i)),
                pbr.metallic_roughness_texture().map(|i| of_info(&i)),
                m.emissive_texture().map(|i| of_info(&i)),
                m.transmission().and_then(|t| t.transmission_texture()).map(|i| of_info(&i)),
                m.specular().and_then(|s| s.specular_texture()).map(|i| of_info(&i)),
                m.specular().and_then(|s| s.specular_color_texture()).map(|i| of_info(&i)),
                of_clearcoat(&m, "clearcoatTexture"),
                of_clearcoat(&m, "clearcoatRoughnessTexture"),
                m.normal_texture().map(|n| of_normal(&n)),
            ]
            .into_iter()
            .flatten()
            .collect();
            let mut first = slots.first().copied().unwrap_or_default();
            if !first.transform.is_finite() {
                w.warn(format!(
                    "{}: material {}: a KHR_texture_transform is not finite; ignored",
                    file.display(),
                    m.index().unwrap_or(0)
                ));
                first.transform = Mat3::IDENTITY;
            }
            if slots.iter().any(|s| *s != first) {
                w.warn_once("gltf-uv-maps", || {
                    format!(
                        "{}: material {}: texture slots use different texture coordinate sets or transforms; the first's is used for all (further uses not reported)",
                        file.display(),
                        m.index().unwrap_or(0)
                    )
                });
            }
            first
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn transform_is_offset_rotation_scale() {
        // The extension's example: rotate a quarter turn, then scale, then offset.
        let m = transform_matrix([0.5, 0.25], std::f32::consts::FRAC_PI_2, [2.0, 3.0]);
        // S (1, 0) = (2, 0); R (2, 0) = (cos 2, -sin 2) = (0, -2); + offset.
        let p = m.transform_point2(Vec2::new(1.0, 0.0));
        assert!((p - Vec2::new(0.5, -1.75)).length() < 1e-6, "{p}");
        // S (0, 1) = (0, 3); R (0, 3) = (sin 3, cos 3) = (3, 0); + offset.
        let p = m.transform_point2(Vec2::new(0.0, 1.0));
        assert!((p - Vec2::new(3.5, 0.25)).length() < 1e-6, "{p}");
        let identity = transform_matrix([0.0, 0.0], 0.0, [1.0, 1.0]);
        assert_eq!(identity, Mat3::IDENTITY);
    }

    /// The UV maps of a document whose materials are `materials` (JSON), and its warnings.
    fn maps_of(materials: &str) -> (Vec<UvMap>, Vec<String>) {
        let json = format!(
            r#"{{"asset": {{"version": "2.0"}}, "extensionsUsed": ["KHR_texture_transform"], "images": [{{"uri": "a.png"}}],
                "textures": [{{"source": 0}}], "materials": {materials}}}"#
        );
        let doc = ::gltf::Gltf::from_slice(json.as_bytes()).unwrap().document;
        let mut w = Warnings::default();
        let maps = uv_maps(Path::new("t.gltf"), &doc, &mut w);
        (maps, w.into_vec())
    }

    /// The normal map's KHR_texture_transform is read like the other slots' (the `gltf` crate
    /// gives it no accessor): gltfpack puts its dequantizing transform on every slot, which
    /// then agree, so no warning; a normal map alone gets its own transform and set.
    #[test]
    fn the_normal_maps_transform_is_read() {
        let t = r#"{"KHR_texture_transform": {"offset": [0.25, 1.0], "scale": [16.0, 8.0]}}"#;
        let (maps, warnings) = maps_of(&format!(
            r#"[{{"pbrMetallicRoughness": {{"baseColorTexture": {{"index": 0, "extensions": {t}}}}}, "normalTexture": {{"index": 0, "extensions": {t}}}}},
               {{"normalTexture": {{"index": 0, "texCoord": 1, "extensions": {{"KHR_texture_transform": {{"rotation": 0.5, "texCoord": 0}}}}}}}},
               {{"normalTexture": {{"index": 0, "texCoord": 1}}}}]"#
        ));
        assert!(warnings.is_empty(), "{warnings:?}");
        assert_eq!(maps[0], UvMap { tex_coord: 0, transform: transform_matrix([0.25, 1.0], 0.0, [16.0, 8.0]) });
        assert_eq!(maps[1], UvMap { tex_coord: 0, transform: transform_matrix([0.0, 0.0], 0.5, [1.0, 1.0]) });
        assert_eq!(maps[2], UvMap { tex_coord: 1, transform: Mat3::IDENTITY });
        // The clear coat's texture slots are read the same way: alone they give the map, and
        // beside a base colour texture of the same transform they agree with it.
        let (maps, warnings) = maps_of(&format!(
            r#"[{{"extensions": {{"KHR_materials_clearcoat": {{"clearcoatFactor": 1, "clearcoatTexture": {{"index": 0, "texCoord": 1, "extensions": {t}}}}}}}}},
               {{"pbrMetallicRoughness": {{"baseColorTexture": {{"index": 0, "extensions": {t}}}}},
                 "extensions": {{"KHR_materials_clearcoat": {{"clearcoatRoughnessTexture": {{"index": 0, "extensions": {t}}}}}}}}}]"#
        ));
        assert!(warnings.is_empty(), "{warnings:?}");
        assert_eq!(maps[0], UvMap { tex_coord: 1, transform: transform_matrix([0.25, 1.0], 0.0, [16.0, 8.0]) });
        assert_eq!(maps[1], UvMap { tex_coord: 0, transform: transform_matrix([0.25, 1.0], 0.0, [16.0, 8.0]) });
        // A normal map whose transform differs from the base colour's is still warned about.
        let (_, warnings) = maps_of(&format!(
            r#"[{{"pbrMetallicRoughness": {{"baseColorTexture": {{"index": 0, "extensions": {t}}}}}, "normalTexture": {{"index": 0}}}}]"#
        ));
        assert_eq!(warnings.len(), 1, "{warnings:?}");
    }
}
