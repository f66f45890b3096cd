//! The GPU ABI: every binding index, workgroup size, specialisation-constant id and struct
//! that host and shaders share. Defined here once; build.rs compiles this same file and
//! writes `bidir_abi.glsl` (the `#define`s and `struct`s below) into the include path of
//! every kernel. Never write one of these numbers or structs by hand in GLSL.
//!
//! Layout rule: structs are used in std430 storage buffers. A `Vec3` must be followed by a
//! 4-byte scalar (std430 aligns vec3 to 16 bytes); the `abi` test compares every offset
//! here with the `Offset` decorations the GLSL compiler assigned, so a drift fails the build's
//! tests rather than the image.

include!("abi_macros.rs");

use glam::{IVec4, UVec4, Vec4};

gpu_consts! {
    // ---- Workgroup sizes -------------------------------------------------------------
    /// Invocations per workgroup of the reduction and scan kernels.
    pub const SCAN_WG_SIZE: u32 = 256;
    /// Workgroup edge of 2D image kernels (WG x WG).
    pub const IMAGE_WG_SIZE: u32 = 8;

    // ---- Bindings: reduce_sum.comp -----------------------------------------------------
    pub const REDUCE_BIND_INPUT: u32 = 0;
    pub const REDUCE_BIND_OUTPUT: u32 = 1;

    // ---- Bindings: scan_block.comp / scan_add.comp ---------------------------------------
    pub const SCAN_BIND_DATA: u32 = 0;
    pub const SCAN_BIND_BLOCK_SUMS: u32 = 1;

    // ---- Bindings: image_affine.comp --------------------------------------------------
    pub const IMAGE_AFFINE_BIND_SRC: u32 = 0;
    pub const IMAGE_AFFINE_BIND_DST: u32 = 1;

    // ---- Bindings: subgroup_probe.comp -------------------------------------------------
    pub const PROBE_BIND_OUT: u32 = 0;

    // ---- BVH and traversal (glsl/common/traverse.glsl) -----------------------------------
    /// Invocations per workgroup of the ray kernels.
    pub const TRACE_WG_SIZE: u32 = 64;
    /// Traversal stack entries per ray; BVHs deeper than this are rejected at build time.
    pub const TRAVERSAL_STACK_SIZE: u32 = 64;
    /// Stack bottom marker (never a node index).
    pub const TRAVERSAL_SENTINEL: u32 = 0x7fff_ffff;
    /// A leaf child pointer has bit 31 set; bits 0..27 hold its first triangle and bits 27..31
    /// its triangle count minus one.
    pub const LEAF_FIRST_BITS: u32 = 27;
    pub const LEAF_MAX_TRIS: u32 = 16;
    /// `BvhNode`-triangle encodings (specialisation constant `SPEC_TRI_TEST`).
    pub const TRI_TEST_WATERTIGHT: u32 = 0;
    pub const TRI_TEST_WOOP: u32 = 1;
    /// `GpuHit::tri` of a ray that hit nothing.
    pub const NO_HIT: u32 = 0xffff_ffff;
    pub const BIND_NODES: u32 = 0;
    pub const BIND_TRIS: u32 = 1;
    pub const BIND_TRI_IDS: u32 = 2;
    pub const BIND_RAYS: u32 = 3;
    pub const BIND_HITS: u32 = 4;
    pub const BIND_STATS: u32 = 5;
    pub const BIND_RAYS_OUT: u32 = 6;
    pub const BIND_FLAGS: u32 = 7;

    // ---- Specialisation-constant ids ----------------------------------------------------
    /// Triangle test: TRI_TEST_WATERTIGHT or TRI_TEST_WOOP.
    pub const SPEC_TRI_TEST: u32 = 0;
    /// 1: count node and triangle tests per ray into the stats buffer.
    pub const SPEC_STATS: u32 = 1;
    /// 1: any-hit (shadow) query, stop at the first hit; 0: closest hit.
    pub const SPEC_ANY_HIT: u32 = 2;
    /// Secondary ray kind for gen_secondary.comp: 0 shadow, 1 diffuse.
    pub const SPEC_SECONDARY_KIND: u32 = 3;
}

gpu_structs! {
    /// Push constants of the reduction and scan kernels.
    pub struct ScanPush (16 bytes) {
        /// Number of valid elements.
        pub count: u32,
        pub pad0: u32,
        pub pad1: u32,
        pub pad2: u32,
    }

    /// Push constants of `image_affine.comp`: dst = src * scale + offset.
    pub struct ImageAffinePush (48 bytes) {
        pub scale: Vec4,
        pub offset: Vec4,
        pub size: UVec4,
    }

    /// An inner BVH node in the Aila–Laine layout: both children's boxes, so one 64-byte
    /// fetch tests both. `children.xy` are child pointers (>= 0: inner node index; < 0: a leaf,
    /// see LEAF_FIRST_BITS); `children.zw` are unused.
    pub struct BvhNode (64 bytes) {
        /// (c0.min.x, c0.max.x, c0.min.y, c0.max.y)
        pub c0_xy: Vec4,
        /// (c1.min.x, c1.max.x, c1.min.y, c1.max.y)
        pub c1_xy: Vec4,
        /// (c0.min.z, c0.max.z, c1.min.z, c1.max.z)
        pub c01_z: Vec4,
        pub children: IVec4,
    }

    /// A triangle in leaf order, encoded for the chosen test: watertight stores the three
    /// vertices (xyz); Woop stores the rows of the world-to-unit-triangle affine map
    /// (xyz = row, w = translation), thesis eq. 2.29–2.32.
    pub struct GpuTri (48 bytes) {
        pub a: Vec4,
        pub b: Vec4,
        pub c: Vec4,
    }

    /// A ray: origin with tmin in w, direction with tmax in w (tmax < 0: no ray).
    pub struct GpuRay (32 bytes) {
        pub origin: Vec4,
        pub dir: Vec4,
    }

    /// Closest hit: distance, original triangle index (NO_HIT if none), barycentrics of
    /// vertices 1 and 2 (`u`, `v`); for any-hit queries `tri` is 0 on a hit.
    pub struct GpuHit (16 bytes) {
        pub t: f32,
        pub tri: u32,
        pub u: f32,
        pub v: f32,
    }

    /// Push constants of the ray kernels.
    pub struct TracePush (16 bytes) {
        pub count: u32,
        pub seed: u32,
        pub pad0: u32,
        pub pad1: u32,
    }

    /// A pinhole camera as kernels use it: `dir = forward + x * right + y * up` for
    /// x, y in [-1, 1] (right and up are pre-scaled by the field of view and aspect).
    pub struct GpuCamera (80 bytes) {
        pub eye: Vec4,
        pub forward: Vec4,
        pub right: Vec4,
        pub up: Vec4,
        /// (width, height, 0, 0)
        pub size: UVec4,
    }

    /// Push constants of gen_secondary.comp.
    pub struct SecondaryPush (32 bytes) {
        /// Point light position (shadow rays), w unused.
        pub light: Vec4,
        pub count: u32,
        pub seed: u32,
        pub pad0: u32,
        pub pad1: u32,
    }

    /// What one invocation of `subgroup_probe.comp` saw.
    pub struct SubgroupProbe (16 bytes) {
        pub subgroup_size: u32,
        pub subgroup_id: u32,
        pub invocation_id: u32,
        pub num_subgroups: u32,
    }
}

/// The whole generated header, as build.rs writes it.
pub fn header_glsl() -> String {
    format!(
        "// Generated by build.rs from src/gpu/abi.rs. Do not edit.\n#ifndef BIDIR_ABI_GLSL\n#define BIDIR_ABI_GLSL\n\n{}\n{}#endif\n",
        consts_glsl(),
        structs_glsl()
    )
}
