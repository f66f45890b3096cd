//! What a scene uses, as specialisation constants: kernels run no code for what is absent.

use crate::gpu::abi;
use crate::scene::{Material, Scene};
use crate::vk::Spec;

/// What a scene uses; each is a specialisation constant of the integrator kernels.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SceneFeatures {
    pub normals: bool,
    pub uvs: bool,
    pub textures: bool,
    pub mirror: bool,
    pub glass: bool,
    pub alpha: bool,
    /// GGX lobes (glTF metallic-roughness, rough mirrors).
    pub glossy: bool,
    /// Emission textures on emitters.
    pub emission_textures: bool,
    /// Tangent-space normal maps (needs normals and UVs).
    pub normal_maps: bool,
    /// An environment light (that is not black).
    pub env: bool,
    /// Punctual lights.
    pub punctual: bool,
    /// Rough glass (a glass fraction with roughness > 0).
    pub rough_glass: bool,
    /// Absorbing volumes inside closed meshes (KHR_materials_volume).
    pub volume: bool,
    /// Clear coats (KHR_materials_clearcoat): a second GGX lobe.
    pub clearcoat: bool,
    /// Some material's lobe choice can take a continuous lobe or a delta (or rough-glass)
    /// one ([`Material::mixes_lobes`]); not a kernel specialisation of its own: VCM merges in
    /// the camera pass then (`VcmMode::merges_apart`).
    pub mixed_lobes: bool,
}

impl SceneFeatures {
    pub fn of(scene: &Scene) -> SceneFeatures {
        let m = &scene.materials;
        let textures = scene.uvs.is_some()
            && !scene.textures.is_empty()
            && m.iter().any(|m| {
                m.albedo_texture.is_some()
                    || m.alpha.is_some()
                    || m.roughness_texture.is_some()
                    || m.metallic_texture.is_some()
                    || m.transmission_texture.is_some()
                    || m.specular_texture.is_some()
                    || m.specular_colour_texture.is_some()
                    || m.emission_texture.is_some()
                    || m.normal_texture.is_some()
                    || m.clearcoat_texture.is_some()
                    || m.clearcoat_roughness_texture.is_some()
            });
        SceneFeatures {
            normals: scene.normals.is_some(),
            // Texture coordinates are interpolated only where a texture reads them.
            uvs: textures,
            textures,
            mirror: m.iter().any(|m| m.reflectivity > 0.0),
            glass: m.iter().any(|m| m.refractivity > 0.0),
            alpha: (scene.uvs.is_some() && m.iter().any(|m| m.alpha.is_some())) || m.iter().any(|m| m.blend.is_some()),
            glossy: m.iter().any(Material::is_glossy),
            emission_textures: scene.uvs.is_some()
                && !scene.textures.is_empty()
                && m.iter().any(|m| m.is_emissive() && m.emission_texture.is_some()),
            normal_maps: scene.normals.is_some()
                && scene.uvs.is_some()
                && !scene.textures.is_empty()
                && m.iter().any(|m| m.normal_texture.is_some()),
            env: scene.environment.as_ref().is_some_and(|e| !e.is_black()),
            punctual: !scene.punctual_lights.is_empty(),
            rough_glass: m.iter().any(Material::has_rough_glass),
            volume: m.iter().any(Material::has_volume),
            clearcoat: m.iter().any(Material::has_clearcoat),
            mixed_lobes: m.iter().any(Material::mixes_lobes),
        }
    }

    /// The same scene with the code for mirrors, glass, textures and alpha compiled in even
    /// where it has none (only to measure what specialisation buys; vertex attributes stay as
    /// they are, since their buffers are only uploaded when present).
    pub fn with_all_material_code(self) -> SceneFeatures {
        SceneFeatures {
            textures: true,
            mirror: true,
            glass: true,
            alpha: true,
            glossy: true,
            emission_textures: true,
            normal_maps: true,
            rough_glass: true,
            volume: true,
            clearcoat: true,
            mixed_lobes: true,
            ..self
        }
    }

    /// Smooth mirrors, glass or rough glass: delta or transmissive lobes, whose code makes the
    /// kernels larger (the BVH-layout and one-trace defaults in `render` turn on it).
    pub fn has_specular(&self) -> bool {
        self.mirror || self.glass || self.rough_glass
    }

    /// Only diffuse surfaces: no specular lobe and no GGX one.
    pub fn only_diffuse(&self) -> bool {
        !self.has_specular() && !self.glossy
    }

    pub fn specs(&self) -> Vec<Spec> {
        vec![
            Spec { id: abi::SPEC_HAS_NORMALS, value: self.normals as u32 },
            Spec { id: abi::SPEC_HAS_UVS, value: self.uvs as u32 },
            Spec { id: abi::SPEC_HAS_TEXTURES, value: self.textures as u32 },
            Spec { id: abi::SPEC_HAS_MIRROR, value: self.mirror as u32 },
            Spec { id: abi::SPEC_HAS_GLASS, value: self.glass as u32 },
            Spec { id: abi::SPEC_HAS_ALPHA, value: self.alpha as u32 },
            Spec { id: abi::SPEC_HAS_GLOSSY, value: self.glossy as u32 },
            Spec { id: abi::SPEC_HAS_EMISSION_TEXTURES, value: self.emission_textures as u32 },
            Spec { id: abi::SPEC_HAS_NORMAL_MAPS, value: self.normal_maps as u32 },
            Spec { id: abi::SPEC_HAS_ENV, value: self.env as u32 },
            Spec { id: abi::SPEC_HAS_PUNCTUAL, value: self.punctual as u32 },
            Spec { id: abi::SPEC_HAS_ROUGH_GLASS, value: self.rough_glass as u32 },
            Spec { id: abi::SPEC_HAS_VOLUME, value: self.volume as u32 },
            Spec { id: abi::SPEC_HAS_CLEARCOAT, value: self.clearcoat as u32 },
        ]
    }
}

#[cfg(test)]
mod tests {
    use crate::scene::Material;

    /// `mixed_lobes` decides whether VCM may merge apart from the camera pass (at most one
    /// merge per camera sample): it must hold wherever the lobe choice can take both kinds.
    #[test]
    fn mixed_lobes_where_the_lobe_choice_can_take_both_kinds() {
        let m = |reflectivity: f32, refractivity: f32, transmission_texture: Option<u32>| Material {
            reflectivity,
            refractivity,
            transmission_texture,
            ..Material::default()
        };
        assert!(!m(0.0, 0.0, None).mixes_lobes(), "diffuse only");
        assert!(!m(1.0, 0.0, None).mixes_lobes(), "a perfect mirror");
        assert!(!m(0.0, 1.0, None).mixes_lobes(), "smooth glass");
        assert!(!m(0.4, 0.6, None).mixes_lobes(), "mirror and glass, no continuous part");
        assert!(m(0.3, 0.0, None).mixes_lobes(), "a mirror fraction beside diffuse");
        assert!(m(0.0, 0.5, None).mixes_lobes(), "a glass fraction beside diffuse");
        assert!(m(0.0, 1.0, Some(0)).mixes_lobes(), "glass scaled by a transmission texture");
    }
}
