//! The viewer's fly camera, independent of the window system so it can be unit-tested.
//!
//! Looking keeps the camera's `up` as the world's up: the view direction is a horizontal
//! heading plus an elevation clamped short of straight up or down (where `up` and forward
//! would be parallel and the camera undefined).

use crate::scene::{Aabb, Camera};
use glam::{Quat, Vec3};

/// Steepest elevation of the view direction, in degrees.
const MAX_ELEVATION_DEG: f32 = 89.0;
/// Scroll steps multiply the speed by this.
const SPEED_STEP: f32 = 1.25;

/// Movement asked for by held keys: each component in -1..=1 (forward/back, right/left,
/// up/down).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Motion {
    pub forward: f32,
    pub right: f32,
    pub up: f32,
}

impl Motion {
    pub fn is_zero(&self) -> bool {
        self.forward == 0.0 && self.right == 0.0 && self.up == 0.0
    }
}

/// A camera flown with mouse and keys.
#[derive(Clone, Debug)]
pub struct FlyCamera {
    /// What is rendered now.
    pub camera: Camera,
    /// World units per second.
    pub speed: f32,
    initial: Camera,
    initial_speed: f32,
    bounds: Aabb,
}

impl FlyCamera {
    /// Starts at `camera`, moving across `bounds`' diagonal in about four seconds.
    pub fn new(camera: Camera, bounds: Aabb) -> FlyCamera {
        let diagonal = bounds.diagonal().length();
        let speed = if diagonal.is_finite() && diagonal > 0.0 { 0.25 * diagonal } else { 1.0 };
        FlyCamera { camera: camera.clone(), speed, initial: camera, initial_speed: speed, bounds }
    }

    fn up(&self) -> Vec3 {
        self.camera.up.normalize_or(Vec3::Y)
    }

    /// Unit view direction.
    pub fn forward(&self) -> Vec3 {
        (self.camera.target - self.camera.eye).normalize_or(Vec3::Z)
    }

    fn set_forward(&mut self, forward: Vec3) {
        self.camera.target = self.camera.eye + forward;
    }

    /// Turns by a mouse drag of (`dx`, `dy`) pixels: right turns right, down looks down; one
    /// pixel is one pixel's share of the vertical field of view, so the scene follows the
    /// cursor. Returns whether the camera changed.
    pub fn look(&mut self, dx: f32, dy: f32) -> bool {
        if (dx == 0.0 && dy == 0.0) || !(dx.is_finite() && dy.is_finite()) {
            return false;
        }
        let per_pixel = self.camera.fov_y_deg.to_radians() / self.camera.height.max(1) as f32;
        let up = self.up();
        let f = self.forward();
        let mut heading = (f - f.dot(up) * up).normalize_or_zero();
        if heading == Vec3::ZERO {
            heading = up.any_orthonormal_vector();
        }
        let elevation = f.dot(up).clamp(-1.0, 1.0).asin();
        // Rotating about `up` by +a turns toward -right (right = forward x up).
        let heading = Quat::from_axis_angle(up, -dx * per_pixel) * heading;
        let max = MAX_ELEVATION_DEG.to_radians();
        let elevation = (elevation - dy * per_pixel).clamp(-max, max);
        self.set_forward(elevation.cos() * heading + elevation.sin() * up);
        true
    }

    /// Moves for `dt` seconds at the current speed. Returns whether the camera changed.
    pub fn fly(&mut self, m: Motion, dt: f32) -> bool {
        if m.is_zero() || dt.is_nan() || dt <= 0.0 {
            return false;
        }
        let (f, r, _) = self.camera.basis();
        let step = (m.forward * f + m.right * r + m.up * self.up()) * self.speed * dt;
        self.camera.eye += step;
        self.camera.target += step;
        true
    }

    /// Scales the speed by 1.25 per scroll line (negative lines slow down).
    pub fn scroll(&mut self, lines: f32) {
        if lines.is_finite() {
            self.speed = (self.speed * SPEED_STEP.powf(lines)).clamp(1e-6 * self.initial_speed, 1e6 * self.initial_speed);
        }
    }

    /// Keeps the view direction and backs off from the scene's centre until its bounding
    /// sphere fits the field of view both ways.
    pub fn frame_scene(&mut self) {
        let center = self.bounds.center();
        let radius = (0.5 * self.bounds.diagonal().length()).max(f32::MIN_POSITIVE);
        let half_y = 0.5 * self.camera.fov_y_deg.to_radians();
        let half_x = (half_y.tan() * self.camera.aspect()).atan();
        let distance = radius / half_y.min(half_x).sin();
        let f = self.forward();
        self.camera.eye = center - f * distance;
        self.camera.target = center;
    }

    /// Back to the starting camera and speed (at the current image size).
    pub fn reset(&mut self) {
        let (w, h) = (self.camera.width, self.camera.height);
        self.camera = Camera { width: w, height: h, ..self.initial.clone() };
        self.speed = self.initial_speed;
    }

    /// The image size follows the window.
    pub fn resize(&mut self, width: u32, height: u32) {
        self.camera.width = width;
        self.camera.height = height;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fly() -> FlyCamera {
        let s = crate::scene::Scene::builtin_cornell_box();
        FlyCamera::new(s.cameras[0].clone(), s.bounds())
    }

    #[test]
    fn dragging_right_turns_right_and_down_looks_down() {
        let mut c = fly();
        let (f0, r0, u0) = c.camera.basis();
        assert!(c.look(10.0, 0.0));
        assert!(c.forward().dot(r0) > 0.0, "turned toward the old right");
        assert!(c.forward().dot(u0).abs() < 1e-5, "a horizontal drag keeps the elevation");
        let mut c = fly();
        c.look(0.0, 10.0);
        assert!(c.forward().dot(u0) < 0.0, "looked down");
        // One pixel is one pixel's share of the vertical field of view.
        let mut c = fly();
        c.look(c.camera.height as f32 / 2.0, 0.0);
        let angle = c.forward().dot(f0).acos().to_degrees();
        assert!((angle - c.camera.fov_y_deg / 2.0).abs() < 1e-3, "{angle}");
        c.camera.validate().unwrap();
    }

    #[test]
    fn elevation_stops_short_of_the_poles() {
        let mut c = fly();
        for _ in 0..100 {
            c.look(0.0, -1000.0);
        }
        let elevation = c.forward().dot(c.up()).asin().to_degrees();
        assert!((elevation - MAX_ELEVATION_DEG).abs() < 1e-3, "{elevation}");
        c.camera.validate().unwrap();
    }

    #[test]
    fn keys_move_along_the_view_and_speed_scrolls() {
        let mut c = fly();
        let eye = c.camera.eye;
        let (f, r, _) = c.camera.basis();
        assert!(!c.fly(Motion::default(), 1.0));
        c.fly(Motion { forward: 1.0, ..Default::default() }, 0.5);
        assert!((c.camera.eye - (eye + f * c.speed * 0.5)).length() < 1e-3);
        let before = c.camera.eye;
        c.fly(Motion { right: -1.0, up: 1.0, ..Default::default() }, 1.0);
        let d = c.camera.eye - before;
        assert!(d.dot(r) < 0.0 && d.dot(Vec3::Y) > 0.0);
        let s = c.speed;
        c.scroll(2.0);
        assert!((c.speed - s * 1.5625).abs() < 1e-3 * s);
        c.reset();
        assert_eq!(c.camera.eye, Camera::cornell_box().eye);
        assert_eq!(c.speed, s);
    }

    #[test]
    fn framing_keeps_direction_and_sees_every_corner() {
        let mut c = fly();
        c.look(200.0, 50.0);
        c.resize(400, 100);
        let f = c.forward();
        c.frame_scene();
        assert!((c.forward() - f).length() < 1e-4);
        let b = c.bounds;
        for i in 0..8 {
            let p = Vec3::new(
                if i & 1 == 0 { b.min.x } else { b.max.x },
                if i & 2 == 0 { b.min.y } else { b.max.y },
                if i & 4 == 0 { b.min.z } else { b.max.z },
            );
            let q = c.camera.project(p).expect("in front of the camera");
            assert!(q.x >= 0.0 && q.x <= 400.0 && q.y >= 0.0 && q.y <= 100.0, "corner {p} at {q}");
        }
    }
}
