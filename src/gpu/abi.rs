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

use glam::{IVec4, UVec2, UVec4, Vec2, Vec3, Vec4};

gpu_consts! {
    // ---- Workgroup sizes -------------------------------------------------------------
    /// Invocations per workgroup of the reduction and scan kernels.
    pub const SCAN_WG_SIZE: u32 = 256;
    /// Workgroup edge of 2D image kernels (WG x WG).
    pub const IMAGE_WG_SIZE: u32 = 8;
    /// Edge of the pixel tiles in which the ray and integrator kernels visit an image
    /// (`tiled_pixel` in glsl/common/ray.glsl, `gpu_data::tiled_invocations`): with 8, a
    /// subgroup of 32 covers an 8x4 block, so neighbouring lanes trace neighbouring rays.
    pub const TILE_SIZE: u32 = 8;

    // ---- Bindings: reduce_sum.comp -----------------------------------------------------
    pub const REDUCE_BIND_INPUT: u32 = 0;
    pub const REDUCE_BIND_OUTPUT: u32 = 1;

    // ---- Bindings: scan_block.comp / scan_add.comp ---------------------------------------
    pub const SCAN_BIND_DATA: u32 = 0;
    pub const SCAN_BIND_BLOCK_SUMS: u32 = 1;

    // ---- Bindings: image_affine.comp --------------------------------------------------
    pub const IMAGE_AFFINE_BIND_SRC: u32 = 0;
    pub const IMAGE_AFFINE_BIND_DST: u32 = 1;

    // ---- Bindings: tonemap.comp (film -> display bytes) ------------------------------------
    /// The film's accumulation buffer (vec4 per pixel: rgb sum, sample count).
    pub const TONEMAP_BIND_ACCUM: u32 = 0;
    /// The film's light-tracing splats (rgb floats per pixel), read when `has_splat` is 1.
    pub const TONEMAP_BIND_SPLAT: u32 = 1;
    /// The RGBA8 storage image written.
    pub const TONEMAP_BIND_OUT: u32 = 2;

    // ---- Bindings: subgroup_probe.comp -------------------------------------------------
    pub const PROBE_BIND_OUT: u32 = 0;

    // ---- BVH and traversal (glsl/common/traverse.glsl) -----------------------------------
    /// Invocations per workgroup of the ray kernels.
    pub const TRACE_WG_SIZE: u32 = 64;
    /// Traversal stack entries per ray; BVHs deeper than this are rejected at build time.
    pub const TRAVERSAL_STACK_SIZE: u32 = 64;
    /// Entries of the compressed-wide-BVH traversal stack (node groups and postponed triangle
    /// groups, at most one of each per level); trees deeper than half of it are rejected at
    /// build time.
    pub const CWBVH_STACK_SIZE: u32 = 32;
    /// `TraceOptions::layout` / `BuildOptions::layout`: the binary Aila–Laine layout
    /// (`BvhNode`) or the compressed 8-wide BVH (`CwbvhNode`).
    pub const BVH_LAYOUT_BVH2: u32 = 0;
    pub const BVH_LAYOUT_CWBVH: u32 = 1;
    /// The binary layout with 32-byte quantised nodes (`QuantNode`).
    pub const BVH_LAYOUT_BVH2Q: u32 = 2;
    /// The 4-wide layout with full-precision boxes (`Bvh4Node`).
    pub const BVH_LAYOUT_BVH4: u32 = 3;
    /// `QuantNode::exps_left` bits 24..32: 0 when child 0 is the inner node after this one,
    /// else child 0 is a leaf of that many triangles ending where child 1's leaf begins.
    pub const QUANT_LEFT_SHIFT: u32 = 24;
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
    /// Persistent trace kernels: the next ray to fetch and the launch's finished workgroups
    /// (two u32, left at 0 by each launch's last workgroup).
    pub const BIND_RAY_COUNTER: u32 = 26;

    // ---- Bindings: the driver's ray-tracing pipeline (glsl/rt/, vk::DriverTracer) ----------
    /// The top-level acceleration structure the driver built over the scene's triangles;
    /// the rays and hits use BIND_RAYS / BIND_HITS as the trace kernels do.
    pub const RT_BIND_TLAS: u32 = 0;

    // ---- Bindings: ray_sort_keys.comp / ray_sort_scatter.comp (trace::RaySorter) -----------
    /// Rays to sort (`GpuRay`).
    pub const RAY_SORT_BIND_RAYS: u32 = 0;
    /// Per ray: (key, rank among the rays of its key) (uvec2).
    pub const RAY_SORT_BIND_KEYS: u32 = 1;
    /// Per key: its ray count, then (scanned) its first slot in the sorted order.
    pub const RAY_SORT_BIND_BINS: u32 = 2;
    /// The sorted rays.
    pub const RAY_SORT_BIND_OUT: u32 = 3;
    /// Per sorted slot: the index of its ray in the input.
    pub const RAY_SORT_BIND_ORDER: u32 = 4;
    /// Origin cells per axis of the sort key's grid over the scene bounds are
    /// 2^RAY_SORT_CELL_BITS; the key is the direction octant (3 high bits) above the cell's
    /// Morton code (3 x RAY_SORT_CELL_BITS bits).
    pub const RAY_SORT_CELL_BITS: u32 = 4;
    pub const RAY_SORT_KEYS: u32 = 32768;
    /// The local sort (`ray_sort_local.comp`): invocations per workgroup (one workgroup sorts
    /// one block of consecutive rays), the largest block, and the largest octahedral grid of
    /// direction cells (per side).
    pub const RAY_SORT_LOCAL_WG: u32 = 256;
    pub const RAY_SORT_LOCAL_MAX_BLOCK: u32 = 4096;
    pub const RAY_SORT_LOCAL_MAX_GRID: u32 = 16;

    // ---- Scene and integrator bindings (glsl/common/scene.glsl) ----------------------------
    pub const BIND_PRIM_INFO: u32 = 8;
    pub const BIND_MATERIALS: u32 = 9;
    pub const BIND_EMITTERS: u32 = 10;
    pub const BIND_ALIAS: u32 = 11;
    pub const BIND_NORMALS: u32 = 12;
    pub const BIND_UVS: u32 = 13;
    pub const BIND_TEXTURES: u32 = 14;
    pub const BIND_TEXELS: u32 = 15;
    /// Vertex positions (xyz triples), for exact hit points when triangles are Woop-encoded.
    pub const BIND_POSITIONS: u32 = 21;
    pub const BIND_ACCUM: u32 = 16;
    pub const BIND_RENDER_STATS: u32 = 17;
    pub const BIND_LIGHT_VERTICES: u32 = 18;
    pub const BIND_LIGHT_COUNTS: u32 = 19;
    pub const BIND_SPLAT: u32 = 20;
    /// Light vertex cache (bdpt:lvc): per light path its stored-vertex count, scanned in
    /// place into offsets; the dense list of stored-vertex slots; and its length.
    pub const BIND_LVC_OFFSETS: u32 = 22;
    pub const BIND_LVC_INDEX: u32 = 23;
    pub const BIND_LVC_TOTAL: u32 = 24;
    /// Per emitter: its vertices' texture coordinates and emission texture (GpuEmitterUv),
    /// read where SPEC_HAS_EMISSION_TEXTURES.
    pub const BIND_EMITTER_UVS: u32 = 27;
    /// Per-vertex tangents (vec4: xyz, handedness w), read where SPEC_HAS_NORMAL_MAPS.
    pub const BIND_TANGENTS: u32 = 28;
    /// Sample slices (vec4 per slice and pixel: rgb sum, count) that film_slices.comp adds
    /// into the film in a fixed order, when a pass runs several samples of a pixel at once.
    pub const BIND_SLICES: u32 = 25;
    /// The environment light (glsl/common/env.glsl): one `GpuEnv`, its texels (`GpuEnvTexel`,
    /// rows top to bottom) and Walker's alias table over them (`GpuAlias`).
    pub const BIND_ENV: u32 = 29;
    pub const BIND_ENV_TEXELS: u32 = 30;
    pub const BIND_ENV_ALIAS: u32 = 31;
    /// Punctual (delta) lights, `GpuPunctual` each (glsl/common/punctual.glsl).
    pub const BIND_PUNCTUAL: u32 = 32;
    /// The first-hit pass (glsl/kernels/first_hit.comp: EXR alpha and `--aov`): per window
    /// pixel one `FirstHitSums`, added to by every pass that asks for them.
    pub const BIND_FIRST_HIT: u32 = 40;
    /// Most specular bounces the first-hit pass follows to the first non-specular surface.
    pub const FIRST_HIT_SPECULAR_DEPTH: u32 = 16;
    /// `GpuPunctual::kind`.
    pub const PUNCTUAL_POINT: u32 = 0;
    pub const PUNCTUAL_SPOT: u32 = 1;
    pub const PUNCTUAL_DIRECTIONAL: u32 = 2;
    /// BDPT joins (BdptPush::join).
    pub const JOIN_FULL: u32 = 0;
    pub const JOIN_K: u32 = 1;
    /// Light vertex cache (Davidovic et al. 2014): `join_k` vertices (0: the mean stored per
    /// light path) drawn uniformly from every light path's stored vertices.
    pub const JOIN_LVC: u32 = 2;
    /// 16-byte words of a light vertex cache entry (BIND_LVC_INDEX, glsl/common/lvc_entry.glsl):
    /// the slot and its path's seen / stored; with a preview of the vertex where connections
    /// are resampled from several candidates (SPEC_LVC_CANDIDATES > 1).
    pub const LVC_ENTRY_WORDS_UNIFORM: u32 = 1;
    pub const LVC_ENTRY_WORDS_RESAMPLED: u32 = 2;
    /// Invocations per workgroup of the integrator kernels (PT_WG_SIZE x 1).
    pub const PT_WG_SIZE: u32 = 64;
    /// `GpuTexture::flags` bit: texels are sRGB-encoded.
    pub const TEXTURE_SRGB: u32 = 1;
    /// Counters in the render stats buffer.
    pub const STAT_NAN_SAMPLES: u32 = 0;
    /// With SPEC_STATS set in an integrator kernel (`RenderSettings::count_traversal`): rays
    /// traced, inner nodes visited and triangles tested (32-bit: count a few million samples).
    pub const STAT_RAYS: u32 = 1;
    pub const STAT_NODES: u32 = 2;
    pub const STAT_TRIS: u32 = 3;
    pub const STAT_COUNT: u32 = 4;

    // ---- Specialisation-constant ids ----------------------------------------------------
    /// Triangle test: TRI_TEST_WATERTIGHT or TRI_TEST_WOOP.
    pub const SPEC_TRI_TEST: u32 = 0;
    /// 1: count node and triangle tests per ray into the stats buffer.
    pub const SPEC_STATS: u32 = 1;
    /// 1: any-hit (shadow) query, stop at the first hit; 0: closest hit.
    pub const SPEC_ANY_HIT: u32 = 2;
    /// Secondary ray kind for gen_secondary.comp: 0 shadow, 1 diffuse.
    pub const SPEC_SECONDARY_KIND: u32 = 3;
    /// 1: next-event estimation with MIS (pt-nee); 0: plain path tracing.
    pub const SPEC_NEE: u32 = 4;
    /// What the scene has: 1 if it carries per-vertex normals / UVs / textures / mirrors /
    /// glass; kernels skip the code of what it lacks.
    pub const SPEC_HAS_NORMALS: u32 = 5;
    pub const SPEC_HAS_UVS: u32 = 6;
    pub const SPEC_HAS_TEXTURES: u32 = 7;
    pub const SPEC_HAS_MIRROR: u32 = 8;
    pub const SPEC_HAS_GLASS: u32 = 9;
    pub const SPEC_HAS_ALPHA: u32 = 10;
    /// Random numbers: how many leading dimensions of each sample come from Owen-scrambled
    /// Sobol' (glsl/common/rng.glsl); the rest come from a hash chain. SAMPLER_INDEPENDENT
    /// (0): all from the hash; SOBOL_ALL_DIMS: all from Sobol'; SOBOL_FIRST_VERTEX: those of
    /// the pixel and of the path's first vertex, however many its decisions take.
    pub const SPEC_SAMPLER: u32 = 11;
    pub const SAMPLER_INDEPENDENT: u32 = 0;
    pub const SOBOL_ALL_DIMS: u32 = 0xffff_ffff;
    pub const SOBOL_FIRST_VERTEX: u32 = 0xffff_fffe;

    // ---- Bindings and modes: glsl/tests/sampling.comp (tests/sampling.rs) -----------------
    /// Results, vec4 per sample (two per sample for SAMPLING_EMITTER).
    pub const SAMPLING_BIND_OUT: u32 = 0;
    /// Input directions (vec4) for SAMPLING_COSINE_PDF.
    pub const SAMPLING_BIND_IN: u32 = 1;
    pub const SAMPLING_COSINE: u32 = 0;
    pub const SAMPLING_COSINE_PDF: u32 = 1;
    pub const SAMPLING_EMITTER: u32 = 2;
    pub const SAMPLING_DIELECTRIC: u32 = 3;
    /// continuous_sample for the BSDF in the push (`a`: wo, `b`: shading normal, `c`..`e`:
    /// its parameters): `out[2i]` = (wi, 1 if sampled else 0), `out[2i + 1]` = (f cos / pdf_fwd_w
    /// (rgb), pdf_fwd_w).
    pub const SAMPLING_GLOSSY: u32 = 4;
    /// continuous_eval of direction pairs `in[2i]` = wo, `in[2i + 1]` = wi: `out[2i]` =
    /// (f(wo, wi), pdf_fwd_w), `out[2i + 1]` = (f(wi, wo), pdf_rev_w).
    pub const SAMPLING_GLOSSY_EVAL: u32 = 5;
    /// Environment sampling: (direction, pdf_w) per sample, then the pdf looked up again.
    pub const SAMPLING_ENV: u32 = 6;
    /// rough_dielectric_sample_world for wo `a.xyz`, shading normal `b.xyz`, eta `c.x`, alpha
    /// `c.y`, radiance if `c.z` > 0: `out[2i]` = (wi, 1 if sampled else 0), `out[2i + 1]` =
    /// (weight f |cos| / pdf_fwd_w, pdf_fwd_w, pdf_rev_w, 1 if refracted).
    pub const SAMPLING_ROUGH_GLASS: u32 = 7;
    /// The rough dielectric of direction pairs `in[2i]` = wo, `in[2i + 1]` = wi (parameters as
    /// SAMPLING_ROUGH_GLASS, local frame of `b.xyz`): `out[2i]` = (f radiance, f importance,
    /// pdf_fwd_w, pdf_rev_w), `out[2i + 1]` = the same for the pair swapped.
    pub const SAMPLING_ROUGH_GLASS_EVAL: u32 = 8;
    /// rng.glsl itself, under the kernel's SPEC_SAMPLER: invocation i draws the first 16
    /// numbers (rng_next_uint) of pixel i / 8 and sample index `in[i].x` (as bits),
    /// starting a group of Sobol' dimensions (rng_start_group) before number n where bit n
    /// of `SAMPLING_RNG_GROUP_STARTS` is set and a path vertex where that of
    /// `SAMPLING_RNG_VERTEX_STARTS` is; `out[4i .. 4i + 3]` holds them as bits.
    pub const SAMPLING_RNG: u32 = 9;
    /// index_below(u, n) (rng.glsl) for `in[i].x`, `in[i].y` as bits: `out[i]` = (the index
    /// as bits, what is left of u within it).
    pub const SAMPLING_INDEX: u32 = 10;
    /// The device's arithmetic under `precise` for `in[i].xyz` = (a, b, c): `out[i]` =
    /// (fma(a, b, c), a b + c), the first one rounding, the second two, as the CPU twins of
    /// intersect.glsl assume.
    pub const SAMPLING_FMA: u32 = 11;
    /// glsl/common/ballot.glsl's cursor on the ballot `in[i]` (its four words as bits) from
    /// lane s = 37 i mod 129, `ballot_take_lowest` until `ballot_from(b, s)` is empty: `out[i]`
    /// = (the first and second lanes taken, or 128, the lanes taken, their order folded as h 31
    /// + lane + 1), as bits.
    pub const SAMPLING_BALLOT_CURSOR: u32 = 12;
    /// glsl/common/packed_contrib.glsl on `in[i].xyz`: `out[3i]` = (contrib_round, 0),
    /// `out[3i + 1]` = (contrib_unpack of contrib_pack, 0), `out[3i + 2]` = (the two packed
    /// words as bits, contrib_round of the rounded value's first two channels).
    pub const SAMPLING_CONTRIB_PACK: u32 = 13;
    /// The numbers of SAMPLING_RNG before which a group starts: the 3rd, 6th, 7th and 12th
    /// (under Sobol' everywhere dimension 2 to 4, 7 to 8, 9 to 12 and 17 to 20; with ten
    /// Sobol' dimensions 9 to 10, where the hash chain starts).
    pub const SAMPLING_RNG_GROUP_STARTS: u32 = (1 << 2) | (1 << 5) | (1 << 6) | (1 << 11);
    /// The numbers of SAMPLING_RNG before which the path reaches its next vertex
    /// (rng_start_vertex; before a group starts there): vertex 1 before the 1st number, vertex
    /// 2 before the 10th.
    pub const SAMPLING_RNG_VERTEX_STARTS: u32 = 1 | (1 << 9);

    /// 1: persistent trace kernel (Aila & Laine 2009, section 3): a fixed number of workgroups
    /// whose subgroups fetch batches of rays from BIND_RAY_COUNTER until none are left.
    pub const SPEC_PERSISTENT: u32 = 12;
    /// Binary BVH traversal: 1 (default) speculative — a lane holding a leaf keeps descending
    /// until every active lane of its subgroup holds one; 0: each lane tests its leaf at once
    /// (Aila & Laine 2009's plain while-while).
    pub const SPEC_SPECULATIVE: u32 = 13;
    /// Compressed wide BVH traversal: 1 postpones triangle tests while fewer than a fifth of
    /// the subgroup's lanes have any (Ylitie et al. 2017, section 4); 0 (default) tests them
    /// at once.
    pub const SPEC_CWBVH_POSTPONE: u32 = 14;
    /// 1: some material has a GGX lobe (glTF metallic-roughness, or a rough thesis mirror);
    /// 0 compiles the microfacet code out.
    pub const SPEC_HAS_GLOSSY: u32 = 15;
    /// 1: some emitter's radiance is scaled by an emission texture.
    pub const SPEC_HAS_EMISSION_TEXTURES: u32 = 16;
    /// 1: some material has a tangent-space normal map.
    pub const SPEC_HAS_NORMAL_MAPS: u32 = 17;

    /// `GpuMaterial::model`: the thesis' lobes (a rough reflectivity is a GGX conductor with
    /// F = 1), or the glTF metallic-roughness model.
    pub const MATERIAL_THESIS: u32 = 0;
    pub const MATERIAL_METAL_ROUGH: u32 = 1;

    /// 1: the scene has an environment light (escaped rays see it, light sampling and BDPT's
    /// light paths include it); 0 compiles none of it in.
    pub const SPEC_HAS_ENV: u32 = 18;
    /// 1: the scene has punctual lights (point, spot, directional).
    pub const SPEC_HAS_PUNCTUAL: u32 = 19;
    /// 1: some material's glass fraction is rough (roughness > 0): the rough dielectric of
    /// glsl/common/rough_dielectric.glsl; 0 compiles it out (smooth glass only).
    pub const SPEC_HAS_ROUGH_GLASS: u32 = 20;
    /// 1: some material has a volume (KHR_materials_volume): path segments inside closed
    /// meshes of it are attenuated (glsl/common/volume.glsl); 0 compiles it out.
    pub const SPEC_HAS_VOLUME: u32 = 21;
    /// 1: some material has a clear coat (KHR_materials_clearcoat): a second GGX lobe over the
    /// continuous part (glsl/common/bsdf.glsl); 0 compiles it out.
    pub const SPEC_HAS_CLEARCOAT: u32 = 22;

    // ---- Vertex connection and merging (docs/integrators.md, src/render/vcm.rs) ------------
    /// 0: BDPT; else the VCM strategies in use, VCM_MERGE | VCM_CONNECT, and where merging
    /// runs (VCM_MERGE_ALL: at every continuous camera vertex; without it at the first one
    /// only), and VCM_MERGE_APART. The BDPT kernels carry dVM and merge only with VCM_MERGE.
    pub const SPEC_VCM: u32 = 40;
    /// First iteration's merge radius r_1 (f32 bits, scene units).
    pub const SPEC_VCM_RADIUS: u32 = 41;
    /// Radius reduction exponent alpha (f32 bits): r_i = r_1 i^((alpha - 1) / 2).
    pub const SPEC_VCM_ALPHA: u32 = 42;
    /// log2 of the merge grid's hash-table size (cells).
    pub const SPEC_MERGE_GRID_BITS: u32 = 43;
    pub const VCM_MERGE: u32 = 1;
    pub const VCM_CONNECT: u32 = 2;
    pub const VCM_MERGE_ALL: u32 = 4;
    /// Merging runs in its own pass after the camera pass (vcm_merge.comp; set by the host,
    /// `VcmMode::merges_apart`, where a camera sample merges at most once).
    pub const VCM_MERGE_APART: u32 = 8;
    /// Merge grid: per hash cell, after the scatter, the end of its entries in
    /// BIND_MERGE_ITEMS (its start is the previous cell's end).
    pub const BIND_MERGE_CELLS: u32 = 33;
    /// Merge grid: the cached light vertices sorted by hash cell (`MergeItem`s).
    pub const BIND_MERGE_ITEMS: u32 = 34;
    /// VCM merging at the first continuous camera vertex: per camera sample (slice x pixels
    /// + pixel) the vertex the camera pass left for vcm_merge.comp (`MergeQuery`).
    pub const BIND_MERGE_QUERIES: u32 = 35;
    /// Trace kernels (not persistent): rays each invocation traces, strided by the launch's
    /// invocation count (default 1). Numbered apart from the scene features' ids.
    pub const SPEC_RAYS_PER_INVOCATION: u32 = 32;
    /// BVH traversal: 1 (default) takes the slab tests' minima and maxima on the distances'
    /// bits as signed integers (glsl/common/traverse.glsl, traverse_cwbvh.glsl), 0 as floats.
    pub const SPEC_INT_SLABS: u32 = 33;
    /// First-hit pass: 1 when an AOV (albedo, normal, depth) is asked for; 0 when only the
    /// EXR's alpha is, so the pass traces each camera ray as an any-hit ray and stops there.
    pub const SPEC_FIRST_HIT_AOVS: u32 = 50;
    // 51 was SPEC_PATH_REGENERATION: path regeneration or not is now a module each (pt.comp,
    // pt_loop.comp), so a pipeline compiles only the loop it runs.
    /// pt-nee: 1 traces the light sample's shadow ray in the step after the one that drew it,
    /// through the same trace_ray call as the extension ray; 0 where it is drawn (a second call).
    pub const SPEC_ONE_TRACE: u32 = 52;
    /// pt-nee: shadow-ray slots per invocation in BIND_SHADOW_QUEUE (0: no queue). The
    /// megakernel queues its light samples' shadow rays there and `shadow_queue.comp` traces
    /// them after it (docs/integrators.md, "Shadow-ray queue").
    pub const SPEC_SHADOW_QUEUE: u32 = 53;
    /// The queued shadow rays (`QueuedShadow`), slot j of invocation i at j x invocations + i.
    pub const BIND_SHADOW_QUEUE: u32 = 36;
    /// Per invocation of the megakernel, the shadow rays it queued (uint).
    pub const BIND_SHADOW_COUNTS: u32 = 37;
    /// pt-nee with the queue: 1 makes the megakernel stop where its invocation's queue slots
    /// are full, leaving its path in BIND_PT_SUSPENDED for the next launch to resume (no
    /// shadow ray is traced in it); 0 (the pass's last launch) finishes every path, tracing a
    /// shadow ray itself where the slots are full.
    pub const SPEC_SHADOW_SUSPEND: u32 = 54;
    /// BDPT and VCM: 1 keeps light tracing (t = 1) as a strategy for direct lighting, the paths light
    /// -> surface -> eye; 0 leaves those to the camera path's light samples and emitter hits
    /// (`RenderSettings::direct_light_tracing`; glsl/common/bdpt.glsl).
    pub const SPEC_DIRECT_LIGHT_TRACING: u32 = 55;
    /// BDPT and VCM: 16-byte words per slot of BIND_LIGHT_VERTICES: 6 (a `LightVertex`) or 4
    /// (the compact form without the glossy, volume and merging fields; glsl/common/bdpt.glsl).
    pub const SPEC_LIGHT_VERTEX_WORDS: u32 = 56;
    /// Binary and 4-wide speculative traversal: 1 runs its loops in lockstep over the
    /// subgroup (a lane whose ray is done idles until every lane's is, so the speculative vote
    /// sits in uniform control flow; the trace kernels' default), 0 lets each lane leave them
    /// on its own (the integrators, where lockstep loops are slower; glsl/common/traverse.glsl).
    pub const SPEC_LOCKSTEP: u32 = 57;
    /// 4-wide persistent trace kernels: 0 fetches a batch of rays when every lane of a
    /// subgroup is done; N > 0 refills the done lanes with new rays as soon as N of them are
    /// (dynamic fetch, Aila & Laine 2009; glsl/common/trace_kernel.glsl).
    pub const SPEC_REFILL_LANES: u32 = 58;
    /// Trace kernels with alpha testing (trace_alpha*.comp): 1 reads each ray's tmin slot
    /// (`GpuRay::origin.w`) as the bits of its path's stochastic-opacity seed (BLEND) and traces
    /// from 0, as the wavefront path tracer's rays carry it; 0: tmin, seed 0.
    pub const SPEC_RAY_SEED: u32 = 59;
    /// Trace kernels: 1 takes the ray count from BIND_RAY_COUNTS[`TracePush::count_index`]
    /// (at most `TracePush::count`), where a kernel before it queued the rays; 0: `count`.
    pub const SPEC_RAY_COUNT_BUFFER: u32 = 60;
    /// BDPT's wavefront path kernels (wf_active.glsl): the most workgroups each of a launch's
    /// trace kernels starts, `Tracer::queued_groups` of the pass's slots (a persistent kernel's
    /// resident workgroups); the default, u32::MAX, bounds nothing.
    pub const SPEC_WF_TRACE_GROUPS: u32 = 61;
    /// BDPT and VCM: 1 weighs their strategies by the balance heuristic (`mis(x) = x`), 0 by
    /// the power heuristic with exponent 2 (`RenderSettings::mis`; glsl/common/bdpt.glsl).
    pub const SPEC_MIS_BALANCE: u32 = 62;
    /// BDPT and VCM with the light vertex cache: N > 1 resamples each connection's light vertex
    /// from N uniform draws (per block of pixels, their reads shared within the subgroup), by its
    /// unshadowed contribution
    /// (`RenderSettings::connection_candidates`; glsl/common/bdpt_camera_path.glsl); 1 draws it
    /// uniformly.
    pub const SPEC_LVC_CANDIDATES: u32 = 63;
    /// Any-hit trace kernels: 1 writes one word per ray into BIND_HITS, word i of the buffer for
    /// ray i (`GpuHit::tri`'s: NO_HIT where the segment is clear, 0 where it is blocked), instead
    /// of a whole `GpuHit`; the wavefront passes' shadow rays, which read nothing else
    /// (`TraceOptions::any_hit_words`).
    pub const SPEC_HIT_WORDS: u32 = 64;
    /// The light vertex cache's listing (lvc_compact.comp): 1 runs an invocation per slot of the
    /// store, 0 one per light path looping over its stored slots
    /// (`render::default_lvc_listing_per_slot`).
    pub const SPEC_LVC_LIST_PER_SLOT: u32 = 65;
    /// Trace kernels: the form of the rays in BIND_RAYS (glsl/common/ray_words.glsl), as
    /// 32-bit words per ray: RAY_WORDS_FULL (`GpuRay`s, the default), RAY_WORDS_SEGMENT
    /// (closest-hit rays from 0 to unbounded) or RAY_WORDS_BOUNDED (any-hit rays from 0 to their
    /// tmax) in the compact structure-of-arrays forms the wavefront passes queue where rays carry
    /// no opacity seed (`TraceOptions::ray_words`).
    pub const SPEC_RAY_WORDS: u32 = 66;
    /// Wavefront path kernels: the forms (RAY_WORDS_*) of the segments and of the shadow rays
    /// they queue for the trace kernels (glsl/common/wf_ray.glsl; `wavefront_queues::ray_words`).
    pub const SPEC_WF_SEGMENT_WORDS: u32 = 67;
    pub const SPEC_WF_SHADOW_WORDS: u32 = 68;
    pub const RAY_WORDS_FULL: u32 = 8;
    pub const RAY_WORDS_SEGMENT: u32 = 6;
    pub const RAY_WORDS_BOUNDED: u32 = 7;
    /// Per invocation of the megakernel, its path between the launches of a pass (`PtSuspended`);
    /// per slot of a wavefront form, its path between launches in up to WF_STATE_WORDS 16-byte
    /// words (the path tracer's: pt_wavefront.glsl; BDPT's camera and light passes:
    /// `BdptCameraState`, `BdptLightState`, with the queue places in the random numbers' word and
    /// no origin).
    pub const BIND_PT_SUSPENDED: u32 = 38;
    /// `PtSuspended::rng_status.w`: the invocation has not started this pass (a cleared
    /// buffer: its first sample is next), has a path suspended, or starts sample
    /// `sample_index` next.
    pub const PT_FRESH: u32 = 0;
    pub const PT_SUSPENDED: u32 = 1;
    pub const PT_NEXT: u32 = 2;
    /// The wavefront path tracer (`pt_wavefront.comp`; `--wavefront`), one slot per megakernel
    /// invocation: the segment each slot's path traces next (`GpuRay`, tmax < 0: none) and what
    /// the closest-hit trace kernel found (`GpuHit`); the light sample's shadow ray and what the
    /// any-hit kernel found (one word, SPEC_HIT_WORDS); the contribution that shadow ray carries
    /// (rgb, at the ray's place in the half of the buffer of the launch's parity; BDPT's light
    /// pass: its join's film pixel in w).
    pub const BIND_WF_RAYS: u32 = 41;
    pub const BIND_WF_HITS: u32 = 42;
    pub const BIND_WF_SHADOW_RAYS: u32 = 43;
    pub const BIND_WF_SHADOW_HITS: u32 = 44;
    pub const BIND_WF_CONTRIB: u32 = 45;
    /// Per launch l of `pt_wavefront.comp` in a batch (`PtWavefrontPush::launch`): the
    /// segments (2 l) and shadow rays (2 l + 1) it queued, packed at the front of BIND_WF_RAYS
    /// and BIND_WF_SHADOW_RAYS; the trace kernels read their count there (BIND_RAY_COUNTS) and
    /// the host stops when a launch queues none.
    pub const BIND_WF_COUNTS: u32 = 46;
    // 47 was BIND_WF_INDEX (each wavefront slot's places in the queues), kept in the paths'
    // state since session 44 (BDPT's passes) and 45 (the path tracer).
    /// Trace kernels with SPEC_RAY_COUNT_BUFFER: ray counts, `TracePush::count_index` selects.
    pub const BIND_RAY_COUNTS: u32 = 48;
    /// A wavefront slot's status (pt_wavefront.glsl's queue word; BDPT's passes: their vertex
    /// counts' sentinels): the slot's samples of the pass are all done (its rays have none).
    pub const PT_DONE: u32 = 3;
    /// Shadow rays a slot of the wavefront camera pass (`bdpt_camera_wavefront.comp`) may queue
    /// per launch: the light sample and up to three connections (`--join lvc=N`, N <= 3).
    pub const BDPT_WF_SHADOW_RAYS: u32 = 4;
    /// BDPT's wavefront passes keep their queue places in two words of a path's state
    /// (`BdptCameraState::rng_status`'s z and w, `BdptLightState`'s): the slot's segment's place
    /// in its ray queue, then its first shadow ray's place with the count of its shadow rays
    /// (at most BDPT_WF_SHADOW_RAYS) in the bits from this one up. A shadow queue's 32-byte rays
    /// within one binding's 4 GiB are fewer than 2^27, so the place fits below.
    pub const WF_SHADOW_COUNT_SHIFT: u32 = 28;
    /// Most 16-byte words a slot's path takes between launches in the wavefront forms (the path
    /// tracer's and BDPT's two passes, BIND_PT_SUSPENDED): four, and a fifth for the medium and
    /// the opacity seed in scenes with either (wf_ray.glsl, `WF_STATE_STRIDE`).
    pub const WF_STATE_WORDS: u32 = 5;
    /// Most launches of `pt_wavefront.comp` one submission records (half BIND_WF_COUNTS's length).
    pub const WF_MAX_BATCH: u32 = 256;
    /// BDPT's wavefront passes (bdpt_light_wavefront.comp, bdpt_camera_wavefront.comp): which
    /// slots each launch runs. First the indirect dispatches of a batch's launches, `uvec4`
    /// (groups, 1, 1, slots) for launch l at entry l (WF_DISPATCH_ENTRIES of them; the last
    /// launch's successor is copied to entry 0 for the next batch), then the launches' traces'
    /// (WF_TRACE_DISPATCH_ENTRIES; both sized by each launch's last workgroup), then two halves of slot
    /// lists: a launch of parity p runs the slots listed in half p and lists in half 1 - p those
    /// that queued a ray, which run next (stream compaction: a launch costs what its live paths
    /// do, not what the pass's slots do).
    pub const BIND_WF_ACTIVE: u32 = 39;
    /// Entries of BIND_WF_ACTIVE's indirect dispatches: one per launch of a batch and one more.
    pub const WF_DISPATCH_ENTRIES: u32 = WF_MAX_BATCH + 1;
    /// Entries of BIND_WF_ACTIVE's indirect dispatches of the trace kernels, after the path
    /// kernel's: per launch l of a batch, its segments' closest-hit trace at 2 l and its shadow
    /// rays' any-hit trace at 2 l + 1, sized by the launch's last workgroup from the rays it
    /// queued, so that a launch of a pass's tail does not start a full persistent launch.
    pub const WF_TRACE_DISPATCH_ENTRIES: u32 = 2 * WF_MAX_BATCH;
    /// Set in `BdptWavefrontPush::launch`: the pass's first launch, which runs every slot (from
    /// a direct dispatch) and starts its path; the launch in the batch is in the other bits.
    pub const WF_ALL_SLOTS: u32 = 0x8000_0000;
    /// Set in `BdptWavefrontPush::launch` for the launch after a pass's first: the pass's first
    /// launch queues each slot's segment at the slot's own place and stores no state, and this
    /// one starts each listed path again from its random numbers (the same values) and takes
    /// up its segment's hit there (wf_active.glsl, `wf_first_hits`).
    pub const WF_FIRST_HITS: u32 = 0x4000_0000;
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

    /// A compressed 8-wide BVH node (Ylitie, Karras & Laine 2017, "Efficient Incoherent Ray
    /// Traversal on GPUs Through Compressed Wide BVHs", section 3.1), byte for byte obvhs'
    /// `CwBvhNode`: child boxes quantised to 8 bits on a grid of origin `p` and power-of-two
    /// cell size 2^(e - 127) per axis.
    pub struct CwbvhNode (80 bytes) {
        /// (p.x, p.y, p.z as f32 bits, e.x | e.y << 8 | e.z << 16 | imask << 24); imask bit i:
        /// child slot i is an inner node.
        pub p_e: UVec4,
        /// (first child node, first triangle, child_meta bytes 0..4, 4..8). A leaf's meta byte:
        /// triangle offset (bits 0..5) and count in unary (bits 5..8); an inner child's:
        /// 0b001 << 5 | (24 + slot).
        pub meta: UVec4,
        /// Quantised child bounds, one byte per child: (min x 0..4, 4..8, max x 0..4, 4..8).
        pub qx: UVec4,
        pub qy: UVec4,
        pub qz: UVec4,
    }

    /// A binary BVH node quantised to 32 bytes (half a `BvhNode`): both children's boxes on
    /// a grid of origin `origin` (the node's own box, lower corner) and power-of-two cell size
    /// 2^(e - 127) per axis, 8 bits per plane, rounded outwards when built so that the
    /// decoded planes `origin + q 2^(e - 127)` (exact product, one rounding) always enclose
    /// the child (`bvh::layout::quantize`). Inner nodes are in depth-first order: child 0, if
    /// inner, is the next node; child 1 is a pointer like `BvhNode::children` (the builder
    /// puts a lone leaf child there).
    pub struct QuantNode (32 bytes) {
        pub origin: Vec3,
        /// e.x | e.y << 8 | e.z << 16 (biased exponents of the cell sizes) | child 0's leaf
        /// triangle count << QUANT_LEFT_SHIFT (0: child 0 is the inner node index + 1).
        pub exps_left: u32,
        /// Per axis, one byte each: (child 0 lo, child 0 hi, child 1 lo, child 1 hi).
        pub qx: u32,
        pub qy: u32,
        pub qz: u32,
        /// Child 1: >= 0 an inner node index, < 0 a leaf pointer (see LEAF_FIRST_BITS).
        pub child1: i32,
    }

    /// A 4-wide BVH node with full-precision child boxes (the binary tree collapsed, see
    /// `bvh::wide4`), in 128 bytes: one cache line. `planes[2 a]` holds the four children's
    /// lower bounds on axis a (x, y, z), `planes[2 a + 1]` their upper bounds, so a ray reads
    /// its near planes at `2 a + (d[a] < 0)` and its far ones at `2 a + 1 - (d[a] < 0)`.
    /// An empty slot has lower bounds +inf and upper bounds -inf, so every ray misses it.
    pub struct Bvh4Node (128 bytes) {
        pub planes: [Vec4; 6],
        /// Child pointers like `BvhNode::children` (>= 0 inner node, < 0 leaf); 0 in empty
        /// slots (never followed).
        pub children: IVec4,
        /// Node 0's `x`: the root of any-hit rays' copy of the nodes
        /// (`Bvh::bvh4_any_nodes`), 0 without one; otherwise unused.
        pub reserved: UVec4,
    }

    /// Push constants of the ray sort kernels: the grid of origin cells over the scene bounds.
    pub struct RaySortPush (32 bytes) {
        pub bounds_lo: Vec3,
        pub count: u32,
        /// Cells per unit length on each axis (2^RAY_SORT_CELL_BITS / extent).
        pub cells_per_unit: Vec3,
        pub pad0: u32,
    }

    /// Push constants of the local ray sort (`ray_sort_local.comp`): the rays, the block of
    /// consecutive rays a workgroup sorts, and the side of the octahedral grid of direction
    /// cells they are sorted by.
    pub struct RaySortLocalPush (16 bytes) {
        pub count: u32,
        pub block: u32,
        pub grid: u32,
        pub pad0: u32,
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
        /// Rays (with SPEC_RAY_COUNT_BUFFER: at most; the count is in BIND_RAY_COUNTS).
        pub count: u32,
        pub seed: u32,
        /// Persistent trace kernels: most ray batches one subgroup fetches.
        pub max_batches: u32,
        /// With SPEC_RAY_COUNT_BUFFER: the index of the ray count in BIND_RAY_COUNTS.
        pub count_index: u32,
    }

    /// Push constants of the driver's ray-generation shader (glsl/rt/trace.rgen).
    pub struct RtTracePush (16 bytes) {
        pub count: u32,
        /// 1: shadow rays (any hit ends the query, no closest-hit shader runs).
        pub any_hit: u32,
        pub pad0: u32,
        pub pad1: u32,
    }

    /// A pinhole camera as kernels use it: `dir = forward + x * right + y * up` for
    /// x, y in [-1, 1] (right and up are pre-scaled by the field of view and aspect).
    /// Kernels render the window of `window_size` pixels at (`window_x`, `window_y`) of the
    /// full image (a crop; the whole image without one): projection and per-pixel random
    /// numbers use full-image pixels, the film holds the window's.
    pub struct GpuCamera (80 bytes) {
        pub eye: Vec3,
        /// The window's left column in the full image.
        pub window_x: u32,
        pub forward: Vec3,
        /// The window's top row in the full image.
        pub window_y: u32,
        pub right: Vec4,
        pub up: Vec4,
        /// Full image (width, height) in pixels.
        pub size: UVec2,
        /// The window's (width, height): the film's size.
        pub window_size: UVec2,
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

    /// A material: diffuse albedo (glTF: base colour), emission, mirror and glass fractions,
    /// and the GGX parameters (glsl/common/scene.glsl, `continuous_at`).
    pub struct GpuMaterial (144 bytes) {
        /// Linear albedo (base colour).
        pub albedo: Vec3,
        /// MASK: the alpha cutoff (> 0); 0 if not alpha-tested (BLEND: see `opacity`).
        pub alpha_cutoff: f32,
        /// Emitted radiance, front face only.
        pub emission: Vec3,
        /// Luminance of `emission` (light sampling's weight; 0: not an emitter).
        pub emission_luminance: f32,
        /// The thesis' mirror fraction.
        pub reflectivity: f32,
        /// The thesis' glass fraction (glTF: transmission).
        pub refractivity: f32,
        /// Index of refraction of the glass fraction.
        pub ior: f32,
        /// Transmission texture + 1 (linear; its red channel scales the refractivity), 0 = none.
        pub transmission_texture: u32,
        /// Albedo texture + 1 (sRGB), 0 = none.
        pub albedo_texture: u32,
        /// Texture whose alpha is the coverage (MASK, BLEND) + 1, 0 = none.
        pub alpha_texture: u32,
        /// Texture whose G channel scales the roughness + 1 (linear), 0 = none.
        pub roughness_texture: u32,
        /// Texture whose B channel scales the metallic factor + 1 (linear), 0 = none.
        pub metallic_texture: u32,
        /// glTF metallic factor (MATERIAL_METAL_ROUGH).
        pub metallic: f32,
        /// GGX roughness (alpha = roughness^2); for MATERIAL_THESIS, > 0 makes the
        /// reflectivity a rough conductor and the refractivity a rough dielectric.
        pub roughness: f32,
        /// KHR_materials_specular's specularTexture + 1 (linear; its alpha scales
        /// `specular`), 0 = none.
        pub specular_texture: u32,
        /// MATERIAL_THESIS or MATERIAL_METAL_ROUGH.
        pub model: u32,
        /// Emission texture + 1 (sRGB; scales `emission`), 0 = none.
        pub emission_texture: u32,
        /// Normal map + 1 (linear, tangent space), 0 = none.
        pub normal_texture: u32,
        /// Scale of the normal map's X and Y.
        pub normal_scale: f32,
        /// glTF BLEND: the base opacity (times the alpha texture's alpha); a hit is kept with
        /// that probability. 1 for other materials.
        pub opacity: f32,
        /// KHR_materials_volume: absorption coefficient sigma_a per unit length inside a
        /// closed mesh of this material (SPEC_HAS_VOLUME; zero: none).
        pub sigma_a: Vec3,
        /// KHR_materials_specular's specularColorTexture + 1 (sRGB; its RGB scales
        /// `specular_f0` before the clamp), 0 = none.
        pub specular_colour_texture: u32,
        /// Schlick F0 of the dielectric coat's reflection before the clamp to 1,
        /// ((ior - 1) / (ior + 1))^2 x specularColorFactor (KHR_materials_specular; 0.04 at
        /// ior 1.5 without); the diffuse lobe's coat weight uses its largest clamped channel.
        pub specular_f0: Vec3,
        /// KHR_materials_specular's specularFactor: the coat's F90 and weight (1 without).
        pub specular: f32,
        /// KHR_materials_clearcoat's clearcoatFactor (0: no clear coat; SPEC_HAS_CLEARCOAT).
        pub clearcoat: f32,
        /// Its clearcoatRoughnessFactor (the coat's GGX alpha = roughness^2).
        pub clearcoat_roughness: f32,
        /// Texture whose R channel scales `clearcoat` + 1 (linear), 0 = none.
        pub clearcoat_texture: u32,
        /// Texture whose G channel scales `clearcoat_roughness` + 1 (linear), 0 = none.
        pub clearcoat_roughness_texture: u32,
    }

    /// An emissive triangle for light sampling.
    pub struct GpuEmitter (64 bytes) {
        /// The triangle's first vertex.
        pub v0: Vec3,
        pub area: f32,
        /// v1 - v0.
        pub e1: Vec3,
        pub pad0: f32,
        /// v2 - v0.
        pub e2: Vec3,
        pub pad1: f32,
        /// Emitted radiance (the emission factor; a texture scales it at the point).
        pub radiance: Vec3,
        /// Probability that light sampling chooses this emitter: its weight over the total.
        pub pick: f32,
    }

    /// Where an emitter's emission texture is read (one per GpuEmitter, same order).
    pub struct GpuEmitterUv (32 bytes) {
        pub uv0: Vec2,
        pub uv1: Vec2,
        pub uv2: Vec2,
        /// Emission texture + 1, 0 = none.
        pub texture: u32,
        pub pad0: u32,
    }

    /// The environment light: an equirectangular map, conventions in `src/scene/env.rs`.
    pub struct GpuEnv (96 bytes) {
        /// Scene bounding sphere, centre (xyz) and radius (w): a light path from the
        /// environment starts on a disk of this radius, outside the sphere, facing its way.
        pub bounds: Vec4,
        pub width: u32,
        pub height: u32,
        /// Turn of the map about +Y (radians).
        pub rotate: f32,
        /// Probability that light sampling (and a BDPT light path) picks the environment
        /// rather than an emissive triangle.
        pub pick: f32,
        /// Area of the light-path disk, pi r^2 (also where directional lights' paths start).
        pub disk_area: f32,
        /// Punctual lights in BIND_PUNCTUAL (bound with this buffer even without an
        /// environment: it holds how light sampling splits between kinds of light).
        pub punctual_count: u32,
        /// Probability that light sampling picks a punctual light (then one uniformly).
        pub punctual_pick: f32,
        /// Cosine of the sun's angular radius (2: no sun).
        pub sun_cos_max: f32,
        /// Unit direction toward the sun (xyz), w unused.
        pub sun_direction: Vec4,
        /// The sun disk's radiance (rgb), w unused.
        pub sun_radiance: Vec4,
        /// Solid-angle pdf of env_sample inside the sun disk from its own alias cell (the
        /// last one, after the texels'): p_sun / sun solid angle.
        pub sun_pdf_w: f32,
        /// Alias-table cells: texels, plus one for the sun.
        pub cells: u32,
        pub pad0: u32,
        pub pad1: u32,
    }

    /// A punctual light (KHR_lights_punctual): a delta light, never hit by a ray.
    pub struct GpuPunctual (64 bytes) {
        /// Point and spot lights: position (xyz), w unused.
        pub position: Vec4,
        /// Spot and directional lights: unit direction of the emitted light (xyz), w unused.
        pub direction: Vec4,
        /// Point and spot: radiant intensity (W/sr, rgb); directional: irradiance on a surface
        /// facing it (rgb); w unused.
        pub intensity: Vec4,
        /// PUNCTUAL_POINT, PUNCTUAL_SPOT or PUNCTUAL_DIRECTIONAL.
        pub kind: u32,
        /// Spot: cosines of the outer and inner cone half-angles.
        pub cos_outer: f32,
        pub cos_inner: f32,
        pub pad0: u32,
    }

    /// One environment texel: its radiance (scale included) and the solid-angle pdf of
    /// sampling a direction inside it (p_alias / texel solid angle).
    pub struct GpuEnvTexel (16 bytes) {
        pub r: f32,
        pub g: f32,
        pub b: f32,
        pub pdf_w: f32,
    }

    /// One cell of Walker's alias table over emitters (Vose's construction).
    pub struct GpuAlias (8 bytes) {
        pub prob: f32,
        pub alias: u32,
    }

    /// A texture inside the texel buffer (RGBA8 packed in u32, rows top to bottom).
    pub struct GpuTexture (16 bytes) {
        pub offset: u32,
        pub width: u32,
        pub height: u32,
        pub flags: u32,
    }

    /// Push constants of the path-tracing kernels.
    pub struct PtPush (112 bytes) {
        pub camera: GpuCamera,
        /// Index of the first sample of this pass (per pixel).
        pub sample_base: u32,
        /// Samples per pixel in this pass.
        pub spp: u32,
        pub seed: u32,
        pub emitter_count: u32,
        /// Sum over emitters of luminance(Le) * area: pdf_a of light sampling at an emitter
        /// point is luminance(Le) / this.
        pub emitter_weight: f32,
        /// 0: unbounded (Russian roulette ends paths).
        pub max_depth: u32,
        /// First bounce at which Russian roulette applies.
        pub rr_depth: u32,
        /// Sample slices: invocations per pixel, each taking every slices-th sample of the
        /// pass into its own slice of BIND_SLICES (1: one invocation adds into the film).
        pub slices: u32,
    }

    /// Push constants of `pt_wavefront.comp`: the path tracer's, and which launch of the
    /// submission this is (its counters in BIND_WF_COUNTS).
    pub struct PtWavefrontPush (128 bytes) {
        pub pt: PtPush,
        pub launch: u32,
        pub pad0: u32,
        pub pad1: u32,
        pub pad2: u32,
    }

    /// A shadow ray pt-nee's megakernel queued for `shadow_queue.comp`: from `origin_tmax.xyz`
    /// along `dir.xyz` up to `origin_tmax.w`; `dir.w` holds the path's stochastic-opacity seed
    /// (its bits), `contrib.rgb` what the sample gains if nothing is in the way.
    pub struct QueuedShadow (48 bytes) {
        pub origin_tmax: Vec4,
        pub dir: Vec4,
        pub contrib: Vec4,
    }

    /// Push constants of `shadow_queue.comp`: the film (the camera's window) and the sample
    /// slices of the megakernel launch whose queue it traces (the same invocations). Of
    /// `shadow_queue_splat.comp`: `width` is the light pass's count of light paths (one per
    /// invocation), the rest unused.
    pub struct ShadowQueuePush (16 bytes) {
        pub width: u32,
        pub height: u32,
        pub slices: u32,
        pub pad: u32,
    }

    /// pt-nee's path of one invocation between the launches of a pass (the shadow-ray queue):
    /// pt_path.glsl's `PathState` (pt_queue.comp) without a pending shadow ray, the sample it belongs to and the
    /// random-number state.
    pub struct PtSuspended (96 bytes) {
        /// Origin of the next segment (its floats' bits), then the vertex count.
        pub o_depth: UVec4,
        /// Direction, then the solid-angle pdf of the last non-delta bounce.
        pub d_pdf: Vec4,
        /// Throughput, then 1 if the last bounce was a delta lobe.
        pub throughput_specular: Vec4,
        /// The estimate so far (its floats' bits), then the stochastic-opacity seed.
        pub radiance_seed: UVec4,
        /// sigma_a where the next segment leaves its surface (its floats' bits), then the sample
        /// index: the suspended path's, or the next one to start.
        ///
        /// Integers live in integer words (kept in a float's bits, a value risks a float move
        /// that flushes it, which lavapipe did to one in session 20), and every member is a
        /// 16-byte vector: NVIDIA's driver loads and stores those whole, where `vec3` + `uint`
        /// members cost pt-nee 6 % on DamagedHelmet (session 22, docs/results.md).
        pub sigma_sample: UVec4,
        /// The random-number state (state, index, dim), then PT_FRESH / PT_SUSPENDED / PT_NEXT.
        pub rng_status: UVec4,
    }

    /// A camera subpath of the wavefront camera pass between its launches (BIND_PT_SUSPENDED;
    /// glsl/common/bdpt_camera_path.glsl's `CameraPath` without VCM's terms). The kernel stores
    /// it as 16-byte words, `sigma_seed` last and only in scenes with a medium or alpha: 64 bytes
    /// a slot, two 32-byte sectors, in the others (bdpt_camera_wavefront.glsl, `camera_state_load`;
    /// 10 % of the camera kernel's time on the Cornell box, session 43). Stored, `rng_status`
    /// holds the random numbers' state and dimension, then the slot's queue places (the
    /// segment's, the first shadow ray's with their count above WF_SHADOW_COUNT_SHIFT): the
    /// sample index is recomputed, the status follows from `sum_depth.w` (all ones once the path
    /// has ended), and a launch reads its queue places with its path (session 44). It keeps no
    /// origin (a launch's step needs only the direction and the hit) but the sample's sum, which
    /// goes to the film once (session 44).
    pub struct BdptCameraState (80 bytes) {
        /// The sample's sum so far (its floats' bits: what the film gets once the sample has
        /// nothing left to add), then the vertex count (all ones once the path has ended).
        pub sum_depth: UVec4,
        /// Its direction, then dVCM.
        pub d_dvcm: Vec4,
        /// Throughput, then dVC.
        pub beta_dvc: Vec4,
        /// sigma_a where the next segment leaves its surface (its floats' bits), then the
        /// stochastic-opacity seed (integers in integer words, as in `PtSuspended`).
        pub sigma_seed: UVec4,
        /// The random-number state (state, index, dim), then PT_FRESH / PT_SUSPENDED / PT_DONE.
        pub rng_status: UVec4,
    }

    /// A light subpath of the wavefront light pass between its launches (BIND_PT_SUSPENDED;
    /// bdpt_light_wavefront.comp; the light megakernel's loop state without VCM's dVM). The
    /// kernel stores it as 16-byte words without the origin (no launch reads it back), `sigma`
    /// and the opacity seed last and only in scenes with a medium or alpha: 64 bytes a slot,
    /// two 32-byte sectors, in the others (`light_state_load`). Stored, `rng_status` holds the
    /// random numbers' state and dimension, then the slot's queue places (its segment's, its
    /// join's shadow ray's with their count above WF_SHADOW_COUNT_SHIFT): the sample index is
    /// recomputed, the status follows from `counts.x` (all ones once the path has ended), and
    /// the join's film pixel waits in BIND_WF_CONTRIB's w (session 44).
    pub struct BdptLightState (96 bytes) {
        /// Origin of the next segment (not stored: no launch reads it back), then the
        /// throughput's largest channel leaving the light (Russian roulette's reference).
        pub o_beta0: Vec4,
        /// Its direction, then dVCM.
        pub d_dvcm: Vec4,
        /// Throughput, then dVC.
        pub beta_dvc: Vec4,
        /// sigma_a where the next segment leaves its surface; w unused.
        pub sigma: Vec4,
        /// The vertex count, the diffuse-capable vertices seen so far, those stored (bit 31: the
        /// light is at infinity), then the stochastic-opacity seed. Integers in integer words:
        /// small ones in a float's bits are denormals, which a device may flush to zero.
        pub counts: UVec4,
        /// The random-number state (state, index, dim), then PT_FRESH / PT_SUSPENDED / PT_DONE.
        pub rng_status: UVec4,
    }

    /// A stored light-subpath vertex (a diffuse-capable hit), for BDPT connections. MIS
    /// quantities follow Georgiev 2012 ("Implementing Vertex Connection and Merging"),
    /// power heuristic. Scenes that read none of its glossy, volume and merging fields store
    /// it in a compact 64-byte form instead (`SPEC_LIGHT_VERTEX_WORDS`, glsl/common/bdpt.glsl).
    pub struct LightVertex (96 bytes) {
        pub pos: Vec3,
        /// dVCM of the VCM technical report (Georgiev et al. 2012) at this vertex.
        pub d_vcm: f32,
        /// Shading normal facing the side light arrived from.
        pub ns: Vec3,
        /// dVC at this vertex.
        pub d_vc: f32,
        /// Geometric normal facing that side.
        pub ng: Vec3,
        /// Probability that the lobe choice took the continuous (non-delta) part here.
        pub pick: f32,
        /// Unit direction toward the previous vertex.
        pub wi: Vec3,
        /// Segments of the light subpath up to this vertex (a whole number).
        pub segments: f32,
        /// Throughput times the diffuse BSDF value, beta * P_d * albedo / pi; in scenes with
        /// GGX lobes (SPEC_HAS_GLOSSY), and where VCM merges, the throughput alone, the BSDF
        /// being evaluated per connection from `material` at `uv`.
        pub beta_f: Vec3,
        /// 1 where the light path arrived at the back face of the vertex's surface, so its
        /// connections run inside the closed mesh (SPEC_HAS_VOLUME: volume.glsl); else 0.
        pub back_face: u32,
        /// Texture coordinates of the vertex (SPEC_HAS_GLOSSY).
        pub uv: Vec2,
        /// Material index of the vertex (SPEC_HAS_GLOSSY).
        pub material: u32,
        /// dVM of the VCM technical report (SPEC_VCM; 0 for BDPT).
        pub d_vm: f32,
    }

    /// An entry of VCM's merge grid: a cached light vertex's position beside its slot, so a
    /// query reads a cell's candidates contiguously and loads the vertex only when it lies
    /// within the merge radius.
    pub struct MergeItem (16 bytes) {
        pub pos: Vec3,
        /// Index of the vertex in BIND_LIGHT_VERTICES.
        pub slot: u32,
    }

    /// A camera vertex waiting to be merged (VCM merging at the first continuous camera
    /// vertex: the camera pass records it, vcm_merge.comp merges it and adds the result to
    /// the sample's pixel).
    pub struct MergeQuery (96 bytes) {
        pub pos: Vec3,
        /// dVCM of the camera subpath at the vertex.
        pub d_vcm: f32,
        /// Shading normal facing `wo`.
        pub ns: Vec3,
        /// dVM of the camera subpath at the vertex.
        pub d_vm: f32,
        /// Geometric normal facing `wo`.
        pub ng: Vec3,
        /// Segments from the eye to the vertex; 0: this sample has no vertex to merge.
        pub depth: u32,
        /// Unit direction toward the previous camera vertex.
        pub wo: Vec3,
        /// Material index of the vertex.
        pub material: u32,
        /// Camera-path throughput arriving at the vertex.
        pub beta: Vec3,
        pub pad0: u32,
        /// Texture coordinates of the vertex.
        pub uv: Vec2,
        pub pad1: u32,
        pub pad2: u32,
    }

    /// Push constants of the BDPT kernels.
    pub struct BdptPush (128 bytes) {
        pub camera: GpuCamera,
        pub sample_base: u32,
        pub seed: u32,
        pub emitter_count: u32,
        pub emitter_weight: f32,
        /// 0: unbounded; else the most segments of a full path.
        pub max_depth: u32,
        pub rr_depth: u32,
        /// Light vertices stored per light path (reservoir size).
        pub light_path_len: u32,
        /// JOIN_FULL or JOIN_K.
        pub join: u32,
        /// Light vertices joined per camera vertex for JOIN_K.
        pub join_k: u32,
        /// Light paths per camera sample (pixels x the light-path ratio): light tracing and
        /// the MIS weights count with it.
        pub light_paths: u32,
        /// Camera samples per pixel in this iteration, one slice each (1: added straight
        /// into the film).
        pub camera_samples: u32,
        /// Light paths traced in this iteration: light_paths x camera_samples.
        pub light_path_total: u32,
    }

    /// Push constants of `bdpt_camera_wavefront.comp` and `bdpt_light_wavefront.comp`:
    /// BdptPush's, with the launch of the submission (its counters in BIND_WF_COUNTS; with
    /// WF_ALL_SLOTS for a pass's first launch, WF_FIRST_HITS for the one after it) in the
    /// join's place (the wavefront camera pass joins through the light vertex cache only).
    pub struct BdptWavefrontPush (128 bytes) {
        pub camera: GpuCamera,
        pub sample_base: u32,
        pub seed: u32,
        pub emitter_count: u32,
        pub emitter_weight: f32,
        pub max_depth: u32,
        pub rr_depth: u32,
        pub light_path_len: u32,
        pub launch: u32,
        /// Light vertices drawn from the cache per camera vertex (0: as many as a light path
        /// stores on average).
        pub join_k: u32,
        pub light_paths: u32,
        pub camera_samples: u32,
        pub light_path_total: u32,
    }

    /// Push constants of `film_slices.comp`.
    pub struct SlicesPush (16 bytes) {
        pub pixels: u32,
        pub slices: u32,
        pub pad0: u32,
        pub pad1: u32,
    }

    /// Push constants of `tonemap.comp`: the film's estimate (as `Film::resolve`) scaled by
    /// `scale`, clamped to [0, 1], sRGB-encoded, stored as 8-bit RGBA (or BGRA byte order).
    pub struct TonemapPush (32 bytes) {
        pub width: u32,
        pub height: u32,
        /// 1 / iterations: the splat buffer holds sums over iterations.
        pub inv_iterations: f32,
        /// 2^exposure.
        pub scale: f32,
        /// 1: add the splat buffer (BDPT films).
        pub has_splat: u32,
        /// 1: store B, G, R, A (B8G8R8A8 swapchains; the copy to them does not swizzle).
        pub bgra: u32,
        pub pad0: u32,
        pub pad1: u32,
    }

    /// Push constants of the sampling test kernel `glsl/tests/sampling.comp`.
    pub struct SamplingTestPush (96 bytes) {
        /// SAMPLING_COSINE, SAMPLING_COSINE_PDF, SAMPLING_EMITTER or SAMPLING_DIELECTRIC.
        pub mode: u32,
        pub count: u32,
        pub seed: u32,
        pub emitter_count: u32,
        /// Cosine modes: the unit normal (xyz). Dielectric: the incident direction (xyz)
        /// and eta = n_incident / n_transmitted (w).
        pub a: Vec4,
        /// Dielectric: the unit normal on the incident side (xyz). Glossy: the shading normal.
        pub b: Vec4,
        /// Glossy: (diffuse reflectance (rgb), coat).
        pub c: Vec4,
        /// Glossy: (specular F0 (rgb), specular weight).
        pub d: Vec4,
        /// Glossy: (coat F0, alpha, clear coat, the clear coat's alpha).
        pub e: Vec4,
    }

    /// Push constants of first_hit.comp: the pass's samples, as the integrator renders them.
    pub struct FirstHitPush (96 bytes) {
        pub camera: GpuCamera,
        /// Index of the first sample of this pass (per pixel).
        pub sample_base: u32,
        /// Samples per pixel in this pass.
        pub spp: u32,
        pub seed: u32,
        pub pad0: u32,
    }

    /// Per pixel, sums over its camera samples of what the camera ray found (first_hit.comp):
    /// the first non-specular surface's reflectance seen through specular chains (OIDN's
    /// albedo), its world-space shading normal facing the ray, whether the ray hit geometry,
    /// and the distance to the first hit. A sample whose ray escapes adds zero to each.
    pub struct FirstHitSums (32 bytes) {
        pub albedo: Vec3,
        /// Samples whose camera ray hit geometry (the EXR's alpha, over the samples).
        pub hits: f32,
        pub normal: Vec3,
        /// Camera-ray distance to the first hit.
        pub depth: f32,
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
