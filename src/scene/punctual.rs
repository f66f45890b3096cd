//! Punctual lights (glTF's KHR_lights_punctual): point, spot and directional. They are delta
//! lights: no ray can hit them, so only light sampling, BDPT connections and light tracing
//! see them. Units follow the extension with one watt per lumen: point and spot intensity
//! (candela) is radiant intensity, directional intensity (lux) is irradiance.

use glam::Vec3;

/// What kind of punctual light, with its shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PunctualKind {
    Point,
    /// Intensity falls off smoothly from the inner to the outer cone half-angle (radians), as
    /// the extension defines: t = clamp((cos - cos_outer) / (cos_inner - cos_outer)), t^2.
    Spot {
        inner: f32,
        outer: f32,
    },
    Directional,
}

/// A punctual light in world space.
#[derive(Clone, Debug, PartialEq)]
pub struct PunctualLight {
    pub name: String,
    pub kind: PunctualKind,
    /// Point and spot lights.
    pub position: Vec3,
    /// Spot and directional lights: the unit direction the light travels.
    pub direction: Vec3,
    /// Colour times intensity, linear RGB.
    pub intensity: Vec3,
}

impl PunctualLight {
    /// Radiant intensity toward unit direction `w` leaving the light (point, spot).
    pub fn intensity_toward(&self, w: Vec3) -> Vec3 {
        match self.kind {
            PunctualKind::Point | PunctualKind::Directional => self.intensity,
            PunctualKind::Spot { inner, outer } => {
                let scale = 1.0 / (inner.cos() - outer.cos()).max(1e-3);
                let t = ((self.direction.dot(w) - outer.cos()) * scale).clamp(0.0, 1.0);
                self.intensity * t * t
            }
        }
    }
}
