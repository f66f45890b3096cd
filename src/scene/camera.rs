//! The pinhole camera's conventions, in one place (`scenes/cornell-box/README.md`):
//! - forward = normalize(target - eye); right = normalize(forward × up); the image's up is
//!   right × forward. With forward (0,0,1) and up (0,1,0), right is (-1,0,0).
//! - `fov_y_deg` is the full vertical field of view; pixels are square, so the horizontal
//!   extent is `aspect = width / height` times the vertical one.
//! - Pixel (i, j) covers [i, i+1) × [j, j+1); row 0 is the top of the image.

use glam::{Mat4, Vec2, Vec3};

use super::{Aabb, Camera, SceneError};
use crate::limits::{thousands, MAX_FILM_PIXELS};

/// Name of the camera attached to the built-in Cornell box.
pub const CORNELL_BOX_CAMERA_NAME: &str = "cornell-box";

/// Image size of a camera the file does not size: glTF cameras without an aspect ratio, and
/// the framing camera of a scene without cameras. glTF cameras with an aspect ratio keep the
/// 1080 rows.
pub const DEFAULT_IMAGE_SIZE: (u32, u32) = (1920, 1080);
const GLTF_ROWS: u32 = DEFAULT_IMAGE_SIZE.1;
const GLTF_DEFAULT_WIDTH: u32 = DEFAULT_IMAGE_SIZE.0;

/// Vertical field of view used to frame a scene that has no camera.
const FRAMING_FOV_Y_DEG: f32 = 40.0;

impl Camera {
    /// The camera of the Cornell box reference (README table).
    pub fn cornell_box() -> Camera {
        Camera {
            name: CORNELL_BOX_CAMERA_NAME.to_owned(),
            eye: Vec3::new(278.0, 273.0, -800.0),
            target: Vec3::new(278.0, 273.0, -799.0),
            up: Vec3::Y,
            fov_y_deg: 39.3077,
            width: 256,
            height: 256,
        }
    }

    /// A glTF perspective camera on a node with world transform `world`: glTF cameras look
    /// down their local -Z with +Y up. `aspect` (width / height), when the file gives one,
    /// sets the width of a 1080-row image; without it the image is 1920 × 1080.
    pub fn from_gltf(name: String, world: Mat4, yfov_rad: f32, aspect: Option<f32>) -> Camera {
        let eye = world.transform_point3(Vec3::ZERO);
        let forward = world.transform_vector3(Vec3::NEG_Z).normalize_or_zero();
        let up = world.transform_vector3(Vec3::Y).normalize_or_zero();
        let width = match aspect {
            Some(a) if a.is_finite() && a > 0.0 => ((GLTF_ROWS as f32 * a).round() as u32).max(1),
            _ => GLTF_DEFAULT_WIDTH,
        };
        Camera { name, eye, target: eye + forward, up, fov_y_deg: yfov_rad.to_degrees(), width, height: GLTF_ROWS }
    }

    /// A camera for a scene without one: it looks along +Z (as the Cornell box camera does)
    /// at the centre of `bounds`, with +Y up and a 40° vertical field of view, from just far
    /// enough that the bounding sphere fits in both the vertical and horizontal field of view.
    pub fn framing(bounds: &Aabb, width: u32, height: u32) -> Camera {
        Camera::framing_along(bounds, width, height, Vec3::Z)
    }

    /// As [`Camera::framing`], looking along the unit direction `look` (not parallel to +Y):
    /// glTF assets face +Z, so their front view looks along -Z.
    pub fn framing_along(bounds: &Aabb, width: u32, height: u32, look: Vec3) -> Camera {
        let center = bounds.center();
        let radius = (0.5 * bounds.diagonal().length()).max(f32::MIN_POSITIVE);
        let half_y = (0.5 * FRAMING_FOV_Y_DEG).to_radians();
        let aspect = width.max(1) as f32 / height.max(1) as f32;
        let half_x = (half_y.tan() * aspect).atan();
        let distance = radius / half_y.min(half_x).sin();
        Camera {
            name: "framing".to_owned(),
            eye: center - look * distance,
            target: center,
            up: Vec3::Y,
            fov_y_deg: FRAMING_FOV_Y_DEG,
            width,
            height,
        }
    }

    pub fn aspect(&self) -> f32 {
        self.width as f32 / self.height as f32
    }

    /// Unit forward, right and image-up vectors.
    pub fn basis(&self) -> (Vec3, Vec3, Vec3) {
        let forward = (self.target - self.eye).normalize();
        let right = forward.cross(self.up).normalize();
        (forward, right, right.cross(forward))
    }

    /// The (unnormalised) direction through the image point (x, y), in pixels from the
    /// top-left corner: pixel (i, j)'s centre is (i + 0.5, j + 0.5).
    pub fn ray_direction(&self, x: f32, y: f32) -> Vec3 {
        let (forward, right, up) = self.basis();
        let t = (0.5 * self.fov_y_deg).to_radians().tan();
        let sx = (2.0 * x / self.width as f32 - 1.0) * t * self.aspect();
        let sy = (1.0 - 2.0 * y / self.height as f32) * t;
        forward + sx * right + sy * up
    }

    /// The image point (pixels from the top-left corner) where `p` appears, or `None` behind
    /// the camera. Inverse of [`Camera::ray_direction`].
    pub fn project(&self, p: Vec3) -> Option<Vec2> {
        let (forward, right, up) = self.basis();
        let d = p - self.eye;
        let z = d.dot(forward);
        if z <= 0.0 {
            return None;
        }
        let t = (0.5 * self.fov_y_deg).to_radians().tan();
        let sx = d.dot(right) / z / (t * self.aspect());
        let sy = d.dot(up) / z / t;
        Some(Vec2::new((sx + 1.0) * 0.5 * self.width as f32, (1.0 - sy) * 0.5 * self.height as f32))
    }

    /// Can this camera form an image?
    pub fn validate(&self) -> Result<(), SceneError> {
        let bad = |msg: String| Err(SceneError::Camera { name: crate::text::quote(&self.name), msg });
        if !(self.eye.is_finite() && self.target.is_finite() && self.up.is_finite()) {
            return bad("eye, target and up must be finite".into());
        }
        let forward = self.target - self.eye;
        if forward.length_squared() == 0.0 {
            return bad(format!("eye and target are the same point {}", fmt_vec(self.eye)));
        }
        if forward.normalize().cross(self.up).length_squared() < 1e-12 {
            return bad(format!("up {} is parallel to the view direction {}", fmt_vec(self.up), fmt_vec(forward)));
        }
        if !(self.fov_y_deg > 0.0 && self.fov_y_deg < 180.0) {
            return bad(format!("vertical field of view {}° is not in (0, 180) (override it with --fov)", self.fov_y_deg));
        }
        if self.width == 0 || self.height == 0 {
            return bad(format!("image size {}x{} is empty", self.width, self.height));
        }
        if self.width as u64 * self.height as u64 > MAX_FILM_PIXELS {
            return bad(format!(
                "image size {}x{} is over the limit of {} pixels (choose the size with --width/--height)",
                self.width,
                self.height,
                thousands(MAX_FILM_PIXELS)
            ));
        }
        Ok(())
    }
}

/// `(x, y, z)` with up to 4 significant decimals, for messages and `bidir info`.
pub fn fmt_vec(v: Vec3) -> String {
    let f = |x: f32| {
        let s = format!("{x:.4}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        if s == "-0" {
            "0".to_owned()
        } else {
            s.to_owned()
        }
    };
    format!("({}, {}, {})", f(v.x), f(v.y), f(v.z))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cornell_camera_right_is_minus_x_and_red_wall_left() {
        let c = Camera::cornell_box();
        let (f, r, u) = c.basis();
        assert!((f - Vec3::Z).length() < 1e-6);
        assert!((r - Vec3::NEG_X).length() < 1e-6);
        assert!((u - Vec3::Y).length() < 1e-6);
        // The red wall is at x ≈ 555: left half of the image.
        let p = c.project(Vec3::new(550.0, 273.0, 300.0)).unwrap();
        assert!(p.x < 128.0, "{p}");
        // The floor (y = 0) is in the bottom half (row 0 on top).
        let p = c.project(Vec3::new(278.0, 0.0, 300.0)).unwrap();
        assert!(p.y > 128.0, "{p}");
    }

    #[test]
    fn project_inverts_ray_direction() {
        let c = Camera { width: 320, height: 200, ..Camera::cornell_box() };
        for (x, y) in [(0.5, 0.5), (160.0, 100.0), (319.5, 10.25), (3.0, 199.0)] {
            let p = c.eye + c.ray_direction(x, y) * 37.0;
            let back = c.project(p).unwrap();
            assert!((back - Vec2::new(x, y)).length() < 1e-3, "({x}, {y}) -> {back}");
        }
        // Half the vertical fov: the top edge of the image.
        let top = c.ray_direction(160.0, 0.0).normalize();
        let angle = top.angle_between(Vec3::Z).to_degrees();
        assert!((angle - 0.5 * 39.3077).abs() < 1e-3, "{angle}");
    }

    #[test]
    fn gltf_camera_looks_down_minus_z_and_keeps_1080_rows() {
        let world = Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0)) * Mat4::from_rotation_y(std::f32::consts::FRAC_PI_2);
        let c = Camera::from_gltf("c".into(), world, 0.5, Some(2.0));
        assert!((c.eye - Vec3::new(1.0, 2.0, 3.0)).length() < 1e-6);
        // -Z rotated 90° about +Y is -X.
        assert!((c.target - c.eye - Vec3::NEG_X).length() < 1e-6, "{}", c.target - c.eye);
        assert!((c.fov_y_deg - 0.5f32.to_degrees()).abs() < 1e-4);
        assert_eq!((c.width, c.height), (2160, 1080));
        // glTF's camera +X must be our right.
        let (_, right, _) = c.basis();
        assert!((right - world.transform_vector3(Vec3::X)).length() < 1e-6);
        let c = Camera::from_gltf("c".into(), Mat4::IDENTITY, 0.5, None);
        assert_eq!((c.width, c.height), (1920, 1080));
    }

    #[test]
    fn framing_sees_every_corner() {
        let b = Aabb { min: Vec3::new(-3.0, 0.0, 10.0), max: Vec3::new(5.0, 2.0, 30.0) };
        for (w, h) in [(1920, 1080), (200, 800)] {
            let c = Camera::framing(&b, w, h);
            c.validate().unwrap();
            assert!(c.eye.z < b.min.z);
            for i in 0..8 {
                let p = Vec3::new(
                    if i & 1 == 0 { b.min.x } else { b.max.x },
                    if i & 2 == 0 { b.min.y } else { b.max.y },
                    if i & 4 == 0 { b.min.z } else { b.max.z },
                );
                let q = c.project(p).unwrap();
                assert!(q.x >= 0.0 && q.x <= w as f32 && q.y >= 0.0 && q.y <= h as f32, "{p} -> {q} ({w}x{h})");
            }
        }
    }

    #[test]
    fn validate_rejects_unusable_cameras() {
        let ok = Camera::cornell_box();
        ok.validate().unwrap();
        for bad in [
            Camera { target: ok.eye, ..ok.clone() },
            Camera { up: Vec3::Z, ..ok.clone() },
            Camera { fov_y_deg: 180.0, ..ok.clone() },
            Camera { fov_y_deg: 0.0, ..ok.clone() },
            Camera { width: 0, ..ok.clone() },
            Camera { eye: Vec3::new(f32::NAN, 0.0, 0.0), ..ok.clone() },
        ] {
            let e = bad.validate().unwrap_err().to_string();
            assert!(e.starts_with("camera 'cornell-box'"), "{e}");
        }
    }

    #[test]
    fn fmt_vec_is_compact() {
        assert_eq!(fmt_vec(Vec3::new(278.0, -0.0, 548.8)), "(278, 0, 548.8)");
        assert_eq!(fmt_vec(Vec3::new(0.123456, 1e-6, -2.5)), "(0.1235, 0, -2.5)");
    }
}
