//! What every GPU user of a scene shares, below both the integrators (`render`) and the ray
//! queries of the tests and benchmark (`trace`): the BVH in GPU memory, the kernel form of the
//! camera, the order in which kernels visit pixels, and the scene's feature set that
//! specialises the kernels.

mod bvh;
mod camera;
mod features;
mod tiles;

pub use bvh::GpuBvh;
pub use camera::{gpu_camera, gpu_camera_window};
pub use features::SceneFeatures;
pub use tiles::tiled_invocations;
