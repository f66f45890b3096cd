//! Data derived from a [`Scene`]: emitters and their power (for light sampling), bounds,
//! material kinds, byte counts, and the features kernels can skip.

use glam::Vec3;

use super::{Material, Scene, SceneError};

/// Rec. 709 / sRGB-primaries luminance of a linear RGB value.
pub fn luminance(rgb: Vec3) -> f32 {
    rgb.dot(Vec3::new(0.2126, 0.7152, 0.0722))
}

/// An axis-aligned box; empty when `min > max` (the default).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min: Vec3,
    pub max: Vec3,
}

impl Default for Aabb {
    fn default() -> Self {
        Aabb { min: Vec3::splat(f32::INFINITY), max: Vec3::splat(f32::NEG_INFINITY) }
    }
}

impl Aabb {
    pub fn is_empty(&self) -> bool {
        !(self.min.cmple(self.max).all())
    }
    pub fn grow(&mut self, p: Vec3) {
        self.min = self.min.min(p);
        self.max = self.max.max(p);
    }
    pub fn center(&self) -> Vec3 {
        0.5 * (self.min + self.max)
    }
    pub fn diagonal(&self) -> Vec3 {
        self.max - self.min
    }
}

/// One emissive triangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Emitter {
    pub triangle: u32,
    pub area: f32,
    /// Emitted power per channel, `π · area · Le`: a one-sided Lambertian emitter of radiance
    /// Le sends Le·cosθ over the hemisphere, whose integral is π.
    pub power: Vec3,
    /// `luminance(power)`: the scalar weight for choosing among emitters.
    pub luminance_power: f32,
}

/// How many materials have each component. Components overlap: a material with
/// reflectivity 0.3 counts as both diffuse (its remaining 0.7) and mirror; an emitter usually
/// has a diffuse part too.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MaterialCounts {
    pub total: usize,
    /// `reflectivity + refractivity < 1`: some diffuse reflection.
    pub diffuse: usize,
    pub mirror: usize,
    pub glass: usize,
    /// With a GGX lobe: glTF metallic-roughness, or a rough thesis mirror.
    pub glossy: usize,
    pub emissive: usize,
    pub alpha_masked: usize,
    /// glTF BLEND: stochastic opacity.
    pub blended: usize,
    pub textured: usize,
}

/// Estimated GPU memory, by buffer. The layout assumed is the std430 one the kernels will use:
/// positions and normals as `vec4` (std430 pads a `vec3` array to 16 bytes), UVs as `vec2`,
/// triangles as three `uint`, one `uint` material id per triangle, 128 bytes per material
/// (`GpuMaterial`), textures as RGBA8
/// without mipmaps. The BVH is not included: the bvh module adds its own nodes and
/// reordered triangle indices.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GpuBytes {
    pub positions: u64,
    pub normals: u64,
    pub uvs: u64,
    pub triangles: u64,
    pub material_ids: u64,
    pub materials: u64,
    pub textures: u64,
}

impl GpuBytes {
    pub fn total(&self) -> u64 {
        self.positions + self.normals + self.uvs + self.triangles + self.material_ids + self.materials + self.textures
    }
}

/// What the kernels need to handle for this scene.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Features {
    pub normals: bool,
    pub uvs: bool,
    pub textures: bool,
    pub alpha_mask: bool,
    pub mirror: bool,
    pub glass: bool,
    pub glossy: bool,
}

/// Bytes of one material on the GPU (`gpu::abi::GpuMaterial`; a test in `render::gpu_scene` keeps them equal).
pub const GPU_MATERIAL_BYTES: u64 = 144;

fn has_diffuse(m: &Material) -> bool {
    match m.model {
        crate::scene::MaterialModel::Thesis => m.reflectivity + m.refractivity < 1.0,
        crate::scene::MaterialModel::MetalRough => (m.metallic < 1.0 || m.metallic_texture.is_some()) && m.refractivity < 1.0,
    }
}

impl Scene {
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    pub fn triangle_vertices(&self, t: usize) -> [Vec3; 3] {
        self.triangles[t].map(|i| self.positions[i as usize])
    }

    pub fn triangle_area(&self, t: usize) -> f32 {
        let [a, b, c] = self.triangle_vertices(t);
        0.5 * (b - a).cross(c - a).length()
    }

    pub fn material_of(&self, t: usize) -> &Material {
        &self.materials[self.material_ids[t] as usize]
    }

    /// Every triangle whose material emits, with its power.
    pub fn emitters(&self) -> Vec<Emitter> {
        (0..self.triangles.len())
            .filter(|&t| self.material_of(t).is_emissive())
            .map(|t| {
                let area = self.triangle_area(t);
                let power = std::f32::consts::PI * area * self.material_of(t).emission;
                Emitter { triangle: t as u32, area, power, luminance_power: luminance(power) }
            })
            .collect()
    }

    /// Total emitted power: per channel, and its luminance.
    pub fn total_emitted_power(&self) -> (Vec3, f32) {
        let power = self.emitters().iter().fold(Vec3::ZERO, |acc, e| acc + e.power);
        (power, luminance(power))
    }

    /// Emission a float32 renderer can handle: every emissive material's radiance at most
    /// [`MAX_RADIANCE`](crate::limits::MAX_RADIANCE) per channel, and the total emitted power
    /// finite (else light sampling's power sums overflow and the image is black or garbage).
    pub fn check_emission(&self) -> Result<(), SceneError> {
        let err = |msg: String| Err(SceneError::Parse { file: self.source.clone().into(), msg });
        let max = crate::limits::MAX_RADIANCE;
        if let Some(m) = self.materials.iter().find(|m| !m.emission.is_finite() || m.emission.max_element() > max) {
            return err(format!(
                "material '{}': emitted radiance {:e} is too large (limit {max:e} per channel)",
                crate::text::quote(&m.name),
                m.emission.max_element()
            ));
        }
        let (power, _) = self.total_emitted_power();
        if !power.is_finite() || !luminance(power).is_finite() {
            return err(format!(
                "the emitted power (pi x area x radiance, summed) overflows float32 ({:e}); make the emitters smaller or dimmer",
                power.max_element()
            ));
        }
        Ok(())
    }

    /// Bounds of the vertices the triangles use (empty for a scene without triangles).
    pub fn bounds(&self) -> Aabb {
        let mut used = vec![false; self.positions.len()];
        for t in &self.triangles {
            for &i in t {
                used[i as usize] = true;
            }
        }
        let mut b = Aabb::default();
        for (p, _) in self.positions.iter().zip(&used).filter(|(_, u)| **u) {
            b.grow(*p);
        }
        b
    }

    pub fn material_counts(&self) -> MaterialCounts {
        let mut c = MaterialCounts { total: self.materials.len(), ..Default::default() };
        for m in &self.materials {
            c.diffuse += has_diffuse(m) as usize;
            c.mirror += m.has_mirror() as usize;
            c.glass += (m.refractivity > 0.0) as usize;
            c.glossy += m.is_glossy() as usize;
            c.emissive += m.is_emissive() as usize;
            c.alpha_masked += m.alpha.is_some() as usize;
            c.blended += m.blend.is_some() as usize;
            c.textured += (m.albedo_texture.is_some()
                || m.roughness_texture.is_some()
                || m.metallic_texture.is_some()
                || m.transmission_texture.is_some()
                || m.specular_texture.is_some()
                || m.specular_colour_texture.is_some()
                || m.emission_texture.is_some()
                || m.normal_texture.is_some()) as usize;
        }
        c
    }

    /// Bytes of decoded texels.
    pub fn texture_bytes(&self) -> u64 {
        self.textures.iter().map(|t| t.rgba8.len() as u64).sum()
    }

    /// See [`GpuBytes`] for the layout assumed.
    pub fn gpu_bytes_estimate(&self) -> GpuBytes {
        let v = self.positions.len() as u64;
        let t = self.triangles.len() as u64;
        GpuBytes {
            positions: 16 * v,
            normals: if self.normals.is_some() { 16 * v } else { 0 },
            uvs: if self.uvs.is_some() { 8 * v } else { 0 },
            triangles: 12 * t,
            material_ids: 4 * t,
            materials: GPU_MATERIAL_BYTES * self.materials.len() as u64,
            textures: self.texture_bytes(),
        }
    }

    pub fn features(&self) -> Features {
        Features {
            normals: self.normals.is_some(),
            uvs: self.uvs.is_some(),
            textures: !self.textures.is_empty(),
            alpha_mask: self.materials.iter().any(|m| m.alpha.is_some()),
            mirror: self.materials.iter().any(Material::has_mirror),
            glass: self.materials.iter().any(|m| m.refractivity > 0.0),
            glossy: self.materials.iter().any(Material::is_glossy),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Material;

    fn two_triangle_scene() -> Scene {
        Scene {
            positions: vec![Vec3::ZERO, Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 3.0, 0.0), Vec3::new(9.0, 9.0, 9.0), Vec3::splat(-50.0)],
            triangles: vec![[0, 1, 2], [0, 2, 1]],
            material_ids: vec![0, 1],
            materials: vec![
                Material::default(),
                Material { emission: Vec3::new(1.0, 2.0, 0.0), reflectivity: 0.25, refractivity: 0.75, ..Default::default() },
            ],
            ..Default::default()
        }
    }

    #[test]
    fn emitter_power_is_pi_area_radiance() {
        let s = two_triangle_scene();
        let e = s.emitters();
        assert_eq!(e.len(), 1);
        assert_eq!(e[0].triangle, 1);
        assert!((e[0].area - 3.0).abs() < 1e-6);
        let want = std::f32::consts::PI * 3.0 * Vec3::new(1.0, 2.0, 0.0);
        assert!((e[0].power - want).length() < 1e-4);
        assert!((e[0].luminance_power - (0.2126 * want.x + 0.7152 * want.y)).abs() < 1e-3);
    }

    #[test]
    fn bounds_ignore_unused_vertices() {
        let b = two_triangle_scene().bounds();
        assert_eq!(b, Aabb { min: Vec3::ZERO, max: Vec3::new(2.0, 3.0, 0.0) });
        assert!(Scene::default().bounds().is_empty());
    }

    #[test]
    fn counts_components_and_bytes() {
        let s = two_triangle_scene();
        let c = s.material_counts();
        assert_eq!(
            c,
            MaterialCounts { total: 2, diffuse: 1, mirror: 1, glass: 1, glossy: 0, emissive: 1, alpha_masked: 0, blended: 0, textured: 0 }
        );
        let g = s.gpu_bytes_estimate();
        assert_eq!((g.positions, g.normals, g.uvs, g.triangles, g.material_ids, g.materials), (80, 0, 0, 24, 8, 288));
        assert_eq!(g.total(), 400);
    }
}
