//! glTF PBR metallic-roughness → the thesis' material model.
//!
//! - `baseColorFactor` (linear) × `baseColorTexture` (sRGB) → albedo.
//! - `metallicFactor == 1` and `roughnessFactor <= 0.05` → perfect mirror (reflectivity 1);
//!   anything rougher is diffuse (the model has no glossy lobe).
//! - `KHR_materials_transmission.transmissionFactor` → refractivity (0 on a mirror, as glTF's
//!   transmission only applies to the dielectric part), `KHR_materials_ior` → ior (1.5).
//! - `emissiveFactor × KHR_materials_emissive_strength` → emission.
//! - `alphaMode: MASK` → alpha mask on the base colour texture's alpha, cutoff
//!   `alphaCutoff` (0.5) divided by the base colour factor's alpha (glTF multiplies the two).
//!   `BLEND` is treated as opaque.
//! - Textures the model cannot use (normal, occlusion, emissive, metallic-roughness,
//!   transmission) are ignored with one warning each.

use std::path::Path;

use ::gltf::material::AlphaMode;
use ::gltf::Document;
use glam::Vec3;

use super::files::{resolve, Uri};
use crate::scene::texture::{Request, Requests, Role, Source};
use crate::scene::warnings::Warnings;
use crate::scene::{AlphaMask, Material, SceneError};

/// Roughness at or below which a fully metallic material is a perfect mirror.
const MIRROR_ROUGHNESS: f32 = 0.05;

pub(super) fn convert<'a>(
    file: &Path,
    doc: &'a Document,
    buffers: &'a [Vec<u8>],
    base: &Path,
    requests: &mut Requests<'a>,
    w: &mut Warnings,
) -> Result<Vec<Material>, SceneError> {
    let mut out = Vec::new();
    for m in doc.materials() {
        let index = m.index().unwrap_or(out.len());
        let name = m.name().map_or_else(|| format!("material {index}"), str::to_owned);
        let element = format!("material {index} \"{name}\"");
        let unsupported = |w: &mut Warnings, what: &str| {
            w.warn_once(&format!("gltf-{what}"), || {
                format!("{}: {element}: {what} is not supported; ignored (further uses not reported)", file.display())
            })
        };
        let pbr = m.pbr_metallic_roughness();
        let [r, g, b, a] = pbr.base_color_factor();
        let albedo = Vec3::new(r, g, b);
        let albedo_texture = match pbr.base_color_texture() {
            Some(info) => {
                if info.tex_coord() != 0 {
                    unsupported(w, "a texture on TEXCOORD_1 or higher (TEXCOORD_0 is used)");
                }
                image_request(file, buffers, base, info.texture().source(), requests, w)?
            }
            None => None,
        };
        let reflectivity =
            if pbr.metallic_factor() >= 1.0 && pbr.roughness_factor() <= MIRROR_ROUGHNESS { 1.0 } else { 0.0 };
        if pbr.metallic_roughness_texture().is_some() {
            unsupported(w, "metallicRoughnessTexture");
        }
        let transmission = m.transmission();
        if transmission.as_ref().is_some_and(|t| t.transmission_texture().is_some()) {
            unsupported(w, "transmissionTexture");
        }
        let refractivity = if reflectivity > 0.0 {
            0.0
        } else {
            transmission.map_or(0.0, |t| t.transmission_factor()).clamp(0.0, 1.0)
        };
        let emission = Vec3::from(m.emissive_factor()) * m.emissive_strength().unwrap_or(1.0);
        if m.emissive_texture().is_some() {
            unsupported(w, "emissiveTexture (emissiveFactor alone is used)");
        }
        if m.normal_texture().is_some() {
            unsupported(w, "normalTexture");
        }
        if m.occlusion_texture().is_some() {
            unsupported(w, "occlusionTexture");
        }
        let alpha = match m.alpha_mode() {
            AlphaMode::Opaque => None,
            AlphaMode::Blend => {
                unsupported(w, "alphaMode BLEND (treated as opaque)");
                None
            }
            AlphaMode::Mask => {
                let cutoff = m.alpha_cutoff().unwrap_or(0.5);
                match albedo_texture {
                    Some(t) if a > 0.0 => Some(AlphaMask { texture: t, cutoff: cutoff / a }),
                    _ => {
                        w.warn(format!(
                            "{}: {element}: alphaMode MASK without a base colour texture; treated as opaque",
                            file.display()
                        ));
                        None
                    }
                }
            }
        };
        let material = Material {
            name,
            albedo,
            albedo_texture,
            emission,
            reflectivity,
            refractivity,
            ior: m.ior().unwrap_or(1.5),
            alpha,
        };
        let finite = material.albedo.is_finite() && material.emission.is_finite() && material.ior.is_finite();
        if !finite
            || material.albedo.min_element() < 0.0
            || material.emission.min_element() < 0.0
            || material.ior <= 0.0
        {
            return Err(SceneError::Gltf {
                file: file.to_path_buf(),
                element,
                msg: "colour, emission or ior is negative or not finite".into(),
            });
        }
        out.push(material);
    }
    Ok(out)
}

/// The provisional texture index of `image` as an sRGB colour texture.
fn image_request<'a>(
    file: &Path,
    buffers: &'a [Vec<u8>],
    base: &Path,
    image: ::gltf::Image<'a>,
    requests: &mut Requests<'a>,
    w: &mut Warnings,
) -> Result<Option<u32>, SceneError> {
    let index = image.index();
    let label = image.name().map(str::to_owned);
    let at =
        format!("{}: image {index}{}", file.display(), label.as_ref().map_or(String::new(), |n| format!(" \"{n}\"")));
    let source = match image.source() {
        ::gltf::image::Source::View { view, mime_type } => {
            let start = view.offset();
            let bytes =
                buffers.get(view.buffer().index()).and_then(|b| b.get(start..start.checked_add(view.length())?));
            match bytes {
                Some(bytes) => Source::Memory { bytes, mime: Some(mime_type.to_owned()) },
                None => {
                    return Err(SceneError::Gltf {
                        file: file.to_path_buf(),
                        element: format!("image {index}"),
                        msg: format!("bufferView {} runs past the end of its buffer", view.index()),
                    })
                }
            }
        }
        ::gltf::image::Source::Uri { uri, mime_type } => match resolve(uri, base) {
            Ok(Uri::File(path)) => Source::File(path),
            Ok(Uri::Data(bytes)) => Source::Owned { bytes, mime: mime_type.map(str::to_owned) },
            Err(msg) => {
                w.warn(format!("{at}: {msg}; using no texture"));
                return Ok(None);
            }
        },
    };
    let name = match (&label, &source) {
        (Some(n), _) => n.clone(),
        (None, Source::File(p)) => {
            p.file_name().map_or_else(|| format!("image {index}"), |f| f.to_string_lossy().into_owned())
        }
        _ => format!("image {index}"),
    };
    Ok(Some(requests.request(format!("image {index}"), Role::Colour, || Request {
        name,
        source,
        role: Role::Colour,
        at,
        file: file.to_path_buf(),
        line: None,
    })))
}
