//! glTF PBR metallic-roughness → [`MaterialModel::MetalRough`] (GGX lobes, glTF 2.0 appendix B).
//!
//! - `baseColorFactor` (linear) × `baseColorTexture` (sRGB) → albedo (the base colour).
//! - `metallicFactor`, `roughnessFactor` × `metallicRoughnessTexture` (linear; B metallic,
//!   G roughness) → metallic, roughness; `KHR_materials_ior` → ior (1.5: F0 = 0.04).
//! - `KHR_materials_transmission.transmissionFactor` × `transmissionTexture` (linear, R) →
//!   refractivity of the dielectric part only: `transmission × (1 - metallic)`; a rough
//!   dielectric (Walter et al. 2007) with the material's roughness, smooth at roughness 0,
//!   its transmission tinted by the base colour.
//! - `emissiveFactor × KHR_materials_emissive_strength` → emission, times `emissiveTexture`
//!   (sRGB) where there is one.
//! - `alphaMode: MASK` → alpha mask on the base colour texture's alpha, cutoff
//!   `alphaCutoff` (0.5) divided by the base colour factor's alpha (glTF multiplies the two).
//!   `BLEND` → stochastic opacity: a ray passes through with probability 1 − alpha (alpha =
//!   base colour factor alpha × texture alpha), unbiased for every integrator.
//! - `normalTexture` (linear, tangent space, `scale`) → normal map; tangents are generated
//!   from the UVs (`scene/tangents.rs`).
//! - `KHR_materials_volume` → absorption inside closed meshes (Beer-Lambert), sigma_a =
//!   −ln(attenuationColor) / attenuationDistance per channel, where the material transmits;
//!   `thicknessFactor` 0 (the default) means thin-walled (no volume: the extension's rule);
//!   otherwise the thickness and its texture are ignored (a path tracer measures the
//!   distance travelled).
//! - `KHR_materials_specular`: specularFactor → the dielectric coat's F90 and weight,
//!   specularColorFactor → its F0 colour (clamped to 1); the diffuse lobe keeps 1 − the
//!   largest channel of that Fresnel (the extension's `max_value`); specularTexture (linear,
//!   A) and specularColorTexture (sRGB, RGB) scale the factors. The glass fraction keeps the
//!   exact Fresnel of its ior.
//! - `KHR_materials_clearcoat` (read from the material's extension JSON, which the `gltf`
//!   crate keeps but does not parse): clearcoatFactor × clearcoatTexture (linear, R) and
//!   clearcoatRoughnessFactor × clearcoatRoughnessTexture (linear, G) → a dielectric coat of
//!   ior 1.5 over the continuous part (glsl/common/bsdf.glsl); clearcoatNormalTexture is not
//!   read (one warning): the coat shares the base's shading normal.
//! - Texture coordinate sets and KHR_texture_transform: `uv_map.rs`; occlusion is ignored silently (a path tracer computes occlusion).

use std::path::Path;

use ::gltf::material::AlphaMode;
use ::gltf::Document;
use glam::Vec3;

use super::files::{resolve, Uri};
use crate::scene::texture::{Request, Requests, Role, Source};
use crate::scene::warnings::Warnings;
use crate::scene::{AlphaMask, Material, MaterialModel, SceneError};

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
        let pbr = m.pbr_metallic_roughness();
        let [r, g, b, a] = pbr.base_color_factor();
        let albedo = Vec3::new(r, g, b);
        let albedo_texture = match pbr.base_color_texture() {
            Some(info) => image_request(file, buffers, base, info.texture().source(), Role::Colour, requests, w)?,
            None => None,
        };
        let metallic = pbr.metallic_factor();
        let roughness = pbr.roughness_factor();
        if !(0.0..=1.0).contains(&metallic) || !(0.0..=1.0).contains(&roughness) {
            return Err(SceneError::Gltf {
                file: file.to_path_buf(),
                element,
                msg: format!("metallicFactor {metallic} or roughnessFactor {roughness} outside [0, 1]"),
            });
        }
        let metal_rough_texture = match pbr.metallic_roughness_texture() {
            Some(info) => image_request(file, buffers, base, info.texture().source(), Role::Linear, requests, w)?,
            None => None,
        };
        let transmission = m.transmission();
        let transmission_texture = match transmission.as_ref().and_then(|t| t.transmission_texture()) {
            Some(info) => image_request(file, buffers, base, info.texture().source(), Role::Linear, requests, w)?,
            None => None,
        };
        let refractivity = transmission.map_or(0.0, |t| t.transmission_factor()).clamp(0.0, 1.0) * (1.0 - metallic);
        let emission = Vec3::from(m.emissive_factor()) * m.emissive_strength().unwrap_or(1.0);
        let emission_texture = match m.emissive_texture() {
            Some(info) if emission.max_element() > 0.0 => {
                image_request(file, buffers, base, info.texture().source(), Role::Colour, requests, w)?
            }
            _ => None,
        };
        let (normal_texture, normal_scale) = match m.normal_texture() {
            Some(info) => (image_request(file, buffers, base, info.texture().source(), Role::Linear, requests, w)?, info.scale()),
            None => (None, 1.0),
        };
        let alpha = match m.alpha_mode() {
            AlphaMode::Opaque => None,
            AlphaMode::Blend => None,
            AlphaMode::Mask => {
                let cutoff = m.alpha_cutoff().unwrap_or(0.5);
                match albedo_texture {
                    Some(t) if a > 0.0 => Some(AlphaMask { texture: t, cutoff: cutoff / a }),
                    _ => {
                        w.warn(format!("{}: {element}: alphaMode MASK without a base colour texture; treated as opaque", file.display()));
                        None
                    }
                }
            }
        };
        let absorption = match m.volume() {
            Some(v) if refractivity > 0.0 => volume_absorption(v.thickness_factor(), v.attenuation_color(), v.attenuation_distance())
                .map_err(|msg| SceneError::Gltf { file: file.to_path_buf(), element: element.clone(), msg })?,
            _ => Vec3::ZERO,
        };
        let (specular, specular_colour, specular_texture, specular_colour_texture) = match m.specular() {
            Some(s) => {
                let (f, c) = (s.specular_factor(), Vec3::from(s.specular_color_factor()));
                if !(0.0..=1.0).contains(&f) || !c.is_finite() || c.min_element() < 0.0 {
                    return Err(SceneError::Gltf {
                        file: file.to_path_buf(),
                        element,
                        msg: format!("KHR_materials_specular needs specularFactor in [0, 1] and specularColorFactor >= 0; got {f}, {c}"),
                    });
                }
                let texture = match s.specular_texture() {
                    Some(info) => image_request(file, buffers, base, info.texture().source(), Role::Linear, requests, w)?,
                    None => None,
                };
                let colour_texture = match s.specular_color_texture() {
                    Some(info) => image_request(file, buffers, base, info.texture().source(), Role::Colour, requests, w)?,
                    None => None,
                };
                (f, c, texture, colour_texture)
            }
            None => (1.0, Vec3::ONE, None, None),
        };
        let coat = match m.extension_value("KHR_materials_clearcoat") {
            Some(json) => clearcoat(file, doc, buffers, base, json, &element, requests, w)?,
            None => Clearcoat::default(),
        };
        let material = Material {
            name,
            albedo,
            albedo_texture,
            emission,
            emission_texture,
            reflectivity: 0.0,
            refractivity,
            ior: m.ior().unwrap_or(1.5),
            alpha,
            blend: (m.alpha_mode() == AlphaMode::Blend && (a < 1.0 || albedo_texture.is_some())).then_some(a),
            normal_texture,
            normal_scale,
            model: MaterialModel::MetalRough,
            metallic,
            roughness,
            roughness_texture: metal_rough_texture,
            metallic_texture: metal_rough_texture,
            transmission_texture: if refractivity > 0.0 { transmission_texture } else { None },
            absorption,
            specular,
            specular_colour,
            specular_texture,
            specular_colour_texture,
            clearcoat: coat.factor,
            clearcoat_roughness: coat.roughness,
            clearcoat_texture: coat.texture,
            clearcoat_roughness_texture: coat.roughness_texture,
        };
        let finite = material.albedo.is_finite() && material.emission.is_finite() && material.ior.is_finite();
        if !finite || material.albedo.min_element() < 0.0 || material.emission.min_element() < 0.0 || material.ior <= 0.0 {
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

/// A material's KHR_materials_clearcoat: its weight and roughness, and the textures that scale
/// them (requested only where the weight is above 0).
#[derive(Default)]
struct Clearcoat {
    factor: f32,
    roughness: f32,
    texture: Option<u32>,
    roughness_texture: Option<u32>,
}

/// Reads KHR_materials_clearcoat from the material's extension JSON (the `gltf` crate keeps it
/// but has no accessor for it): factors in [0, 1] (else an error naming `element`), texture
/// references to existing textures; clearcoatNormalTexture is warned about once.
#[allow(clippy::too_many_arguments)]
fn clearcoat<'a>(
    file: &Path,
    doc: &'a Document,
    buffers: &'a [Vec<u8>],
    base: &Path,
    json: &::gltf::json::Value,
    element: &str,
    requests: &mut Requests<'a>,
    w: &mut Warnings,
) -> Result<Clearcoat, SceneError> {
    let err = |msg: String| SceneError::Gltf { file: file.to_path_buf(), element: element.to_owned(), msg };
    let factor = |key: &str| json.get(key).map_or(Some(0.0), |v| v.as_f64().map(|f| f as f32));
    let (Some(factor), Some(roughness)) = (factor("clearcoatFactor"), factor("clearcoatRoughnessFactor")) else {
        return Err(err("KHR_materials_clearcoat's clearcoatFactor and clearcoatRoughnessFactor must be numbers".into()));
    };
    if !(0.0..=1.0).contains(&factor) || !(0.0..=1.0).contains(&roughness) {
        return Err(err(format!(
            "KHR_materials_clearcoat needs clearcoatFactor and clearcoatRoughnessFactor in [0, 1]; got {factor}, {roughness}"
        )));
    }
    if json.get("clearcoatNormalTexture").is_some() {
        w.warn_once("gltf-clearcoat-normal", || {
            format!("{}: {element}: clearcoatNormalTexture is not read; the clear coat uses the base's shading normal", file.display())
        });
    }
    if factor <= 0.0 {
        return Ok(Clearcoat::default());
    }
    let mut texture = |key: &str| -> Result<Option<u32>, SceneError> {
        let Some(info) = json.get(key) else { return Ok(None) };
        let found = info.get("index").and_then(|i| i.as_u64()).and_then(|i| doc.textures().nth(usize::try_from(i).ok()?));
        let Some(t) = found else {
            return Err(err(format!("KHR_materials_clearcoat's {key} has no valid texture index ({info})")));
        };
        image_request(file, buffers, base, t.source(), Role::Linear, requests, w)
    };
    Ok(Clearcoat { factor, roughness, texture: texture("clearcoatTexture")?, roughness_texture: texture("clearcoatRoughnessTexture")? })
}

/// KHR_materials_volume's absorption coefficient per unit length, −ln(colour) / distance per
/// channel (zero for a thin-walled material, thickness 0, or an infinite distance); colour
/// channels of 0 absorb completely (clamped to 1e-6).
pub(super) fn volume_absorption(thickness: f32, colour: [f32; 3], distance: f32) -> Result<Vec3, String> {
    let colour = Vec3::from(colour);
    if !thickness.is_finite()
        || thickness < 0.0
        || distance.is_nan()
        || distance <= 0.0
        || !colour.is_finite()
        || colour.min_element() < 0.0
        || colour.max_element() > 1.0
    {
        return Err(format!(
            "KHR_materials_volume needs thicknessFactor >= 0, attenuationDistance > 0 and attenuationColor in [0, 1]; got {thickness}, {distance}, {colour}"
        ));
    }
    if thickness == 0.0 || distance.is_infinite() {
        return Ok(Vec3::ZERO);
    }
    Ok(-colour.max(Vec3::splat(1e-6)).ln() / distance)
}

/// The provisional texture index of `image` decoded for `role` (sRGB colour or linear data).
fn image_request<'a>(
    file: &Path,
    buffers: &'a [Vec<u8>],
    base: &Path,
    image: ::gltf::Image<'a>,
    role: Role,
    requests: &mut Requests<'a>,
    w: &mut Warnings,
) -> Result<Option<u32>, SceneError> {
    let index = image.index();
    let label = image.name().map(str::to_owned);
    let at = format!(
        "{}: image {index}{}",
        crate::text::path(file),
        label.as_ref().map_or(String::new(), |n| format!(" \"{}\"", crate::text::quote(n)))
    );
    let source = match image.source() {
        ::gltf::image::Source::View { view, mime_type } => {
            let start = view.offset();
            let bytes = buffers.get(view.buffer().index()).and_then(|b| b.get(start..start.checked_add(view.length())?));
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
        (None, Source::File(p)) => p.file_name().map_or_else(|| format!("image {index}"), |f| f.to_string_lossy().into_owned()),
        _ => format!("image {index}"),
    };
    Ok(Some(requests.request(format!("image {index}"), role, || Request { name, source, role, at, file: file.to_path_buf(), line: None })))
}

#[cfg(test)]
mod tests {
    use super::volume_absorption;
    use glam::Vec3;

    #[test]
    fn volume_absorption_is_minus_ln_colour_over_distance() {
        let s = volume_absorption(1.0, [0.5, 1.0, 0.25], 2.0).unwrap();
        assert!((s - Vec3::new(2f32.ln() / 2.0, 0.0, 4f32.ln() / 2.0)).abs().max_element() < 1e-6, "{s}");
        // Thin-walled (thickness 0, the default) and an infinite distance: no volume.
        assert_eq!(volume_absorption(0.0, [0.5; 3], 2.0).unwrap(), Vec3::ZERO);
        assert_eq!(volume_absorption(1.0, [0.5; 3], f32::INFINITY).unwrap(), Vec3::ZERO);
        // A black channel absorbs completely (finite, large).
        assert!(volume_absorption(1.0, [0.0, 1.0, 1.0], 1.0).unwrap().x > 13.0);
        for (t, c, d) in
            [(1.0, [0.5; 3], 0.0), (1.0, [0.5; 3], -1.0), (1.0, [1.5, 0.5, 0.5], 1.0), (-1.0, [0.5; 3], 1.0), (1.0, [f32::NAN; 3], 1.0)]
        {
            let e = volume_absorption(t, c, d).unwrap_err();
            assert!(e.contains("KHR_materials_volume"), "{e}");
        }
    }
}
