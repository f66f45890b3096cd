use crate::gpu::abi::GpuCamera;
use crate::scene::Camera;
use glam::UVec2;

/// The kernel form of a pinhole camera, with the conventions of
/// `shared/scenes/cornell-box/README.md`: right = forward x up, row 0 on top, vertical field
/// of view, square pixels.
pub fn gpu_camera(cam: &Camera) -> GpuCamera {
    let forward = (cam.target - cam.eye).normalize();
    let right = forward.cross(cam.up).normalize();
    let up = right.cross(forward);
    let tan_half = (cam.fov_y_deg.to_radians() * 0.5).tan();
    let aspect = cam.width as f32 / cam.height as f32;
    GpuCamera {
        eye: cam.eye,
        window_x: 0,
        forward,
        window_y: 0,
        right: (right * tan_half * aspect).extend(0.0),
        up: (up * tan_half).extend(0.0),
        size: UVec2::new(cam.width, cam.height),
        window_size: UVec2::new(cam.width, cam.height),
    }
}

/// `camera` restricted to the window `crop` of its image (the projection is unchanged).
pub fn gpu_camera_window(camera: &GpuCamera, crop: crate::imaging::Crop) -> GpuCamera {
    GpuCamera { window_x: crop.x0, window_y: crop.y0, window_size: UVec2::new(crop.width(), crop.height()), ..*camera }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cornell_camera_right_is_minus_x() {
        let cam = Camera::cornell_box();
        let g = gpu_camera(&cam);
        assert!(g.right.x < 0.0 && g.right.y.abs() < 1e-6, "right = forward x up = -x");
        assert!((g.up.y - (39.3077f32.to_radians() / 2.0).tan()).abs() < 1e-6);
    }
}
