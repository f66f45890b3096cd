//! GPU traversal against the CPU reference (obvhs' own BVH2 traversal with the same triangle
//! tests), hit for hit, and the watertightness of the watertight test.

mod common;

use bidir::bvh::{intersect::TriHit, BuildOptions, Bvh, BvhLayout, Collapse, CpuTracer, TriTest};
use bidir::gpu::abi::{self, GpuHit, GpuRay, NO_HIT};
use bidir::gpu_data::GpuBvh;
use bidir::trace::sort::{direction_cell, sort_key, sort_push};
use bidir::trace::{RaySorter, TraceOptions, Tracer};
use bidir::vk::Context;
use common::{finish, geometry, gpu, Pcg};
use glam::{Vec3, Vec4};
use std::sync::OnceLock;

/// How the device rounds the watertight test's fma() (asked once; see `bidir::bvh::intersect::Fma`),
/// for the CPU reference.
fn device_fma(ctx: &Context) -> bidir::bvh::intersect::Fma {
    static FMA: OnceLock<bidir::bvh::intersect::Fma> = OnceLock::new();
    *FMA.get_or_init(|| common::sampling_kernel::device_fma(ctx))
}

fn ray(o: Vec3, d: Vec3, tmax: f32) -> GpuRay {
    GpuRay { origin: o.extend(0.0), dir: d.extend(tmax) }
}

/// The trace kernels every scene is checked with: one invocation per ray, persistent threads
/// with a handful of workgroups (so every subgroup fetches many batches; more on llvmpipe,
/// see `persistent_batch_cap`) and with the device's default count, and for the binary
/// layout the plain (not speculative) while-while loop and the short stack (registers and
/// shared memory) with three rays per invocation and workgroups of 256 with two, for the
/// wide one triangle postponing; the quantised binary layout runs the binary loop on decoded
/// nodes, one invocation per ray. Alpha masks take those of the integrators' stack and
/// workgroup size.
fn variants(opts: &BuildOptions) -> Vec<(&'static str, TraceOptions)> {
    let (tri_test, layout) = (opts.tri_test, opts.layout);
    let base = TraceOptions { layout, ..TraceOptions::new(tri_test) };
    let mut v = vec![
        ("per-ray", base),
        ("persistent 3 groups", TraceOptions { persistent: Some(3), ..base }),
        ("persistent default", TraceOptions { persistent: Some(0), ..base }),
    ];
    match layout {
        BvhLayout::Bvh2 => {
            v.push(("not speculative", TraceOptions { speculative: false, ..base }));
            // The integrators' loops (the trace kernels run them in lockstep by default).
            v.push(("divergent loops", TraceOptions { lockstep: false, ..base }));
            // The stack is independent of the triangle test and of pre-splits (which make the
            // deeper trees): one build per scene is enough.
            if tri_test == TriTest::Watertight && opts.pre_split {
                let ss = TraceOptions { short_stack: true, rays_per_invocation: 3, ..base };
                v.push(("short stack, 3 rays per invocation", ss));
                let wg = TraceOptions { workgroup_size: 256, rays_per_invocation: 2, ..base };
                v.push(("workgroups of 256, 2 rays per invocation", wg));
                v.push(("float slab test", TraceOptions { int_slabs: false, ..base }));
            }
        }
        // The binary loop on decoded nodes: its variants are the exact layout's.
        BvhLayout::Bvh2q => v.truncate(1),
        // The greedy collapse: another tree for the same loop; its variants are the default
        // collapse's.
        BvhLayout::Bvh4 if opts.collapse == Collapse::Greedy => v.truncate(1),
        BvhLayout::Bvh4 => {
            v.truncate(2);
            v.push(("not speculative", TraceOptions { speculative: false, ..base }));
            v.push(("divergent loops", TraceOptions { lockstep: false, ..base }));
            v.push(("float slab test", TraceOptions { int_slabs: false, ..base }));
            // The lockstep kernel with the origin in shared memory (GPUs' default; lavapipe's
            // default is the other).
            v.push(("origin in shared memory", TraceOptions { shared_origin: Some(true), ..base }));
            // Leaf tests shared among the lanes (trace_bvh4_share.comp), one ray per invocation.
            v.push(("shared leaf tests", TraceOptions { share_leaves: true, ..base }));
            // The subgroup's rays as one packet (trace_bvh4_packet.comp).
            v.push(("packet", TraceOptions { packet: true, ..base }));
            // Dynamic fetch: lanes refilled one by one (3 groups: many refills per subgroup),
            // and three at a time with the device's default launch.
            v.push(("dynamic fetch at 1 lane, 3 groups", TraceOptions { persistent: Some(3), refill_lanes: 1, ..base }));
            v.push(("dynamic fetch at 3 lanes", TraceOptions { persistent: Some(0), refill_lanes: 3, ..base }));
            // The same with the leaf tests shared among the lanes (trace_bvh4_share.comp).
            v.push((
                "dynamic fetch at 1 lane, 3 groups, shared leaf tests",
                TraceOptions { persistent: Some(3), refill_lanes: 1, share_leaves: true, ..base },
            ));
            v.push((
                "dynamic fetch at 3 lanes, shared leaf tests",
                TraceOptions { persistent: Some(0), refill_lanes: 3, share_leaves: true, ..base },
            ));
        }
        BvhLayout::Cwbvh => {
            v.push(("postponing", TraceOptions { postpone: true, ..base }));
            v.push(("postponing, persistent 3 groups", TraceOptions { postpone: true, persistent: Some(3), ..base }));
            v.push(("float slab test", TraceOptions { int_slabs: false, ..base }));
        }
    }
    v
}

/// The CPU's closest hit (original triangle, hit) and any-hit verdict for every ray.
type Reference = (Vec<Option<(u32, TriHit)>>, Vec<bool>);

/// Compares GPU closest hits and any-hit verdicts with the CPU for every ray, for every node
/// layout and trace variant; returns (hits, misses) of the closest-hit pass. The quantised
/// binary layout (same tree as the exact one, same kernel loop: only the node fetch differs)
/// is checked once per scene (watertight test, pre-splits: the deeper tree), against the
/// binary layout's reference (the CPU time and the variants of the loop are not spent twice).
/// So is the 4-wide layout (the binary tree collapsed, same leaves; its own loop, with its
/// variants), against the same reference.
fn check_scene(ctx: &Context, name: &str, positions: &[Vec3], tris: &[[u32; 3]], rays: &[GpuRay], opts: BuildOptions) -> (usize, usize) {
    let (a, reference) = check_layout(ctx, name, positions, tris, rays, BuildOptions { layout: BvhLayout::Bvh2, ..opts }, None);
    let (b, _) = check_layout(ctx, name, positions, tris, rays, BuildOptions { layout: BvhLayout::Cwbvh, ..opts }, None);
    assert_eq!(a, b, "{name}: the binary and wide layouts' CPU references disagree on hits");
    if opts.tri_test == TriTest::Watertight && opts.pre_split {
        check_layout(ctx, name, positions, tris, rays, BuildOptions { layout: BvhLayout::Bvh2q, ..opts }, Some(reference.clone()));
        // The 4-wide layout: the binary tree's leaves under other inner nodes, its own loop.
        let (c, _) =
            check_layout(ctx, name, positions, tris, rays, BuildOptions { layout: BvhLayout::Bvh4, ..opts }, Some(reference.clone()));
        assert_eq!(a, c, "{name}: the binary and 4-wide layouts disagree on hits");
        let greedy = BuildOptions { layout: BvhLayout::Bvh4, collapse: Collapse::Greedy, ..opts };
        let (d, _) = check_layout(ctx, name, positions, tris, rays, greedy, Some(reference));
        assert_eq!(a, d, "{name}: the binary and greedily collapsed 4-wide layouts disagree on hits");
    }
    a
}

/// As `check_scene` for one layout, against `reference` if given (else the CPU traverses this
/// build's tree); returns (hits, misses) and the reference.
fn check_layout(
    ctx: &Context,
    name: &str,
    positions: &[Vec3],
    tris: &[[u32; 3]],
    rays: &[GpuRay],
    opts: BuildOptions,
    reference: Option<Reference>,
) -> ((usize, usize), Reference) {
    let bvh = Bvh::build(positions, tris, &opts).unwrap();
    let scale = positions.iter().fold(0f32, |m, p| m.max(p.abs().max_element()));
    let (want, want_any) = reference.unwrap_or_else(|| {
        let cpu = CpuTracer::new(&bvh, positions, tris).with_fma(device_fma(ctx));
        (
            rays.iter().map(|r| cpu.closest(r.origin.truncate(), r.dir.truncate(), r.origin.w, r.dir.w)).collect(),
            rays.iter().map(|r| cpu.any(r.origin.truncate(), r.dir.truncate(), r.origin.w, r.dir.w)).collect(),
        )
    });
    let gbvh = GpuBvh::upload(ctx, &bvh).unwrap();
    let (mut hits, mut misses) = (0, 0);
    for (variant, trace_opts) in variants(&opts) {
        let tracer = Tracer::with_options(ctx, &trace_opts).unwrap();
        let closest: Vec<GpuHit> = tracer.trace(ctx, &gbvh, rays, false).unwrap();
        let any: Vec<GpuHit> = tracer.trace(ctx, &gbvh, rays, true).unwrap();
        let mut ties = 0;
        (hits, misses) = (0, 0);
        for (i, r) in rays.iter().enumerate() {
            let (o, d, tmax) = (r.origin.truncate(), r.dir.truncate(), r.dir.w);
            let g = closest[i];
            match want[i] {
                None => {
                    assert_eq!(g.tri, NO_HIT, "{name} {variant} ray {i} ({o}, {d}): GPU hit prim {} at t={}, CPU missed", g.tri, g.t);
                    misses += 1;
                }
                Some((tri, h)) => {
                    assert_ne!(g.tri, NO_HIT, "{name} {variant} ray {i} ({o}, {d}): CPU hit triangle {tri} at t={}, GPU missed", h.t);
                    assert!((g.tri as usize) < bvh.tri_ids.len(), "{name} {variant} ray {i}: GPU hit prim {} is no triangle", g.tri);
                    let gtri = bvh.tri_ids[g.tri as usize];
                    if gtri != tri {
                        // A tie: two triangles at the same distance (a shared edge or vertex,
                        // or coincident geometry). Within 1e-6 relative t, or — for hits a tiny
                        // t from the origin, where 1e-6 t is below the coordinates' resolution —
                        // within 4 ulps of the hit point's largest coordinate: points that close
                        // are one point in f32, and which triangle wins is decided by rounding
                        // (seen on the H100 with the wide BVH: t 0.0086943 vs 0.0086948 at
                        // Sponza scale, 0.3 ulp of the coordinates apart).
                        let resolution = 4.0 * f32::EPSILON * (o + d * h.t).abs().max_element();
                        assert!(
                            (g.t - h.t).abs() <= (1e-6 * h.t.abs()).max(resolution),
                            "{name} {variant} ray {i}: GPU triangle {gtri} t={}, CPU triangle {tri} t={}",
                            g.t,
                            h.t
                        );
                        ties += 1;
                    } else {
                        // Same triangle. Its t is computed with the same operations on both sides,
                        // but GPUs round some of them differently (Vulkan allows 2.5 ulp division),
                        // and t is ill-conditioned for grazing hits and far-off vertices (the edge
                        // functions cancel), so its error is absolute, a few ulps of the coordinates
                        // (an H100: 3e-5 at Cornell scale). Only a guard against gross errors; the
                        // requirement is the triangle itself.
                        let tol = 1e-3 * h.t.abs() + 1e-5 * scale.max(o.abs().max_element());
                        assert!((g.t - h.t).abs() <= tol, "{name} {variant} ray {i}: t GPU {} CPU {}", g.t, h.t);
                    }
                    hits += 1;
                }
            }
            assert_eq!(
                any[i].tri != NO_HIT,
                want_any[i],
                "{name} {} {variant} ray {i} ({o}, {d}, tmax {tmax}): any-hit verdict",
                opts.layout.name()
            );
        }
        eprintln!(
            "{name} [{}, {}, {variant}]: {} rays, {hits} hits ({ties} ties), {misses} misses; {} nodes, depth {}",
            opts.tri_test.name(),
            opts.layout.name(),
            rays.len(),
            bvh.node_count(),
            bvh.depth
        );
    }
    drop(gbvh);
    ((hits, misses), (want, want_any))
}

/// `offset_ray_origin` of glsl/common/ray.glsl: `p` moved off its surface toward `n` by 256
/// ulps, or by its scale / 65536 where a coordinate is under its scale / 32 (the scale: its
/// largest coordinate, at least 1).
fn offset_ray_origin(p: Vec3, n: Vec3) -> Vec3 {
    let scale = p.abs().max_element().max(1.0);
    let off = |p: f32, n: f32| {
        if p.abs() < scale / 32.0 {
            p + n * (scale / 65536.0)
        } else {
            let i = (256.0 * n) as i32;
            f32::from_bits((p.to_bits() as i32 + if p < 0.0 { -i } else { i }) as u32)
        }
    };
    Vec3::new(off(p.x, n.x), off(p.y, n.y), off(p.z, n.z))
}

/// Shadow rays as the integrators trace them (`shadow_ray_between` in glsl/common/scene.glsl):
/// from points on the Cornell box's right wall and floor, offset off them, to points on the
/// light, offset below it, ending `slack` short of the target.
fn shadow_rays_to_the_light(rng: &mut Pcg, n: usize) -> Vec<GpuRay> {
    (0..n)
        .map(|i| {
            let (a, na) = if i % 2 == 0 {
                (Vec3::new(0.0, rng.next_f32() * 548.8, rng.next_f32() * 559.2), Vec3::X)
            } else {
                (Vec3::new(rng.next_f32() * 556.0, 0.0, rng.next_f32() * 559.2), Vec3::Y)
            };
            let b = Vec3::new(213.0 + rng.next_f32() * 130.0, 548.3, 227.0 + rng.next_f32() * 105.0);
            let (o, target) = (offset_ray_origin(a, na), offset_ray_origin(b, -Vec3::Y));
            let v = target - o;
            let len = v.length();
            let slack = o.abs().max(target.abs()).max_element() * (32.0 / 8_388_608.0);
            ray(o, v / len, len - slack)
        })
        .collect()
}

/// Rays of three kinds: from outside toward the scene, random directions from inside, and
/// segments between random points (shadow-like, finite tmax); every 101st a ray without a
/// segment (tmax < 0, as ray generation marks one that is not traced: no hit).
fn mixed_rays(rng: &mut Pcg, lo: Vec3, hi: Vec3, n: usize) -> Vec<GpuRay> {
    let c = (lo + hi) * 0.5;
    let ext = (hi - lo).length();
    let inside = |rng: &mut Pcg| lo + (hi - lo) * Vec3::new(rng.next_f32(), rng.next_f32(), rng.next_f32());
    (0..n)
        .map(|i| match i % 3 {
            0 => {
                let o = c + geometry::random_unit(rng) * ext * 1.5;
                ray(o, (inside(rng) - o).normalize(), 3.0e38)
            }
            1 => ray(inside(rng), geometry::random_unit(rng), 3.0e38),
            _ => {
                let (a, b) = (inside(rng), inside(rng));
                ray(a, (b - a).normalize(), (b - a).length())
            }
        })
        .enumerate()
        .map(|(i, r)| if i % 101 == 100 { GpuRay { dir: r.dir.truncate().extend(-1.0), ..r } } else { r })
        .collect()
}

#[test]
fn procedural_scene_matches_cpu_hit_for_hit() {
    let ctx = gpu();
    let mut rng = Pcg::new(10);
    let mut scene = geometry::icosphere(4, Vec3::new(0.2, 0.1, -0.3), 1.5);
    geometry::merge(&mut scene, geometry::soup(&mut rng, 20_000, Vec3::splat(-4.0), Vec3::splat(4.0), 0.4));
    geometry::merge(&mut scene, geometry::icosphere(2, Vec3::new(2.5, 2.0, 2.0), 0.7));
    let rays = mixed_rays(&mut rng, Vec3::splat(-4.0), Vec3::splat(4.0), 120_000);
    for tri_test in [TriTest::Watertight, TriTest::Woop] {
        for pre_split in [false, true] {
            let opts = BuildOptions { tri_test, pre_split, ..Default::default() };
            let (hits, misses) = check_scene(&ctx, "procedural", &scene.0, &scene.1, &rays, opts);
            assert!(hits > 10_000 && misses > 1_000, "the ray set must exercise both hits and misses");
        }
    }
    finish(ctx);
}

/// Small triangles far from the world's origin, rays starting among them: the slab tests'
/// rounding there is large against the boxes (a coordinate's unit of rounding is 1/64 at
/// 131072; the triangles are a few of those across). A slab test that precomputes the
/// origin's product with the reciprocal direction must widen its slabs by that product's
/// rounding (`ood_near` / `ood_far` in glsl/common/traverse_bvh4.glsl; the binary kernel
/// computes (p - o) idir instead): without the widening this scene loses hits. Every layout is checked against the CPU reference over the binary build: over
/// the compressed wide build's own source tree the reference (obvhs' BVH2 traversal,
/// `CpuTracer`) misses a hit here that it finds over the binary build and that every GPU
/// layout finds (session 12; obvhs' slab test, not bidir's, left for later).
#[test]
fn small_triangles_far_from_the_origin_match_cpu_hit_for_hit() {
    let ctx = gpu();
    let mut rng = Pcg::new(13);
    let offset = Vec3::new(131_072.0, -65_536.0, 98_304.0);
    let (mut positions, tris) = geometry::soup(&mut rng, 6_000, Vec3::splat(-3.0), Vec3::splat(3.0), 0.15);
    for p in &mut positions {
        *p += offset;
    }
    let rays = mixed_rays(&mut rng, offset - Vec3::splat(3.0), offset + Vec3::splat(3.0), 30_000);
    let opts = BuildOptions::default();
    let (hits_misses, reference) = check_layout(&ctx, "far from the origin", &positions, &tris, &rays, opts, None);
    for layout in [BvhLayout::Cwbvh, BvhLayout::Bvh4, BvhLayout::Bvh2q] {
        check_layout(&ctx, "far from the origin", &positions, &tris, &rays, BuildOptions { layout, ..opts }, Some(reference.clone()));
    }
    let (hits, misses) = hits_misses;
    assert!(hits > 3_000 && misses > 1_000, "the ray set must exercise both hits and misses ({hits} hits, {misses} misses)");
    finish(ctx);
}

#[test]
fn single_triangle_and_tiny_scenes() {
    let ctx = gpu();
    let mut rng = Pcg::new(11);
    let p = vec![Vec3::new(-1.0, -1.0, 0.0), Vec3::new(1.0, -1.0, 0.0), Vec3::new(0.0, 1.0, 0.0)];
    let rays = mixed_rays(&mut rng, Vec3::splat(-1.5), Vec3::splat(1.5), 3000);
    check_scene(&ctx, "one triangle", &p, &[[0, 1, 2]], &rays, BuildOptions::default());
    let two = geometry::icosphere(0, Vec3::ZERO, 1.0);
    check_scene(&ctx, "icosahedron", &two.0, &two.1, &rays, BuildOptions { max_leaf_tris: 16, ..Default::default() });
    finish(ctx);
}

/// Rays from the centre of a closed mesh aimed exactly at its vertices and at points on its
/// edges: every one must hit (none may slip between triangles).
fn edge_rays(rng: &mut Pcg, positions: &[Vec3], tris: &[[u32; 3]], n: usize) -> Vec<GpuRay> {
    let centre = Vec3::new(0.013, -0.007, 0.011); // off the exact centre: less symmetric
    (0..n)
        .map(|i| {
            let t = tris[rng.below(tris.len() as u32) as usize];
            let k = rng.below(3) as usize;
            let (a, b) = (positions[t[k] as usize], positions[t[(k + 1) % 3] as usize]);
            let target = if i % 4 == 0 { a } else { a + (b - a) * rng.next_f32() };
            ray(centre, (target - centre).normalize(), 3.0e38)
        })
        .collect()
}

#[test]
fn watertight_test_leaks_no_ray_through_shared_edges() {
    let ctx = gpu();
    let mut rng = Pcg::new(12);
    let (p, t) = geometry::icosphere(5, Vec3::ZERO, 1.0);
    let rays = edge_rays(&mut rng, &p, &t, 1_000_000);
    let mut leaks = Vec::new();
    for (test, layout) in [
        (TriTest::Watertight, BvhLayout::Bvh2),
        (TriTest::Woop, BvhLayout::Bvh2),
        (TriTest::Watertight, BvhLayout::Cwbvh),
        (TriTest::Watertight, BvhLayout::Bvh2q),
        (TriTest::Watertight, BvhLayout::Bvh4),
    ] {
        let bvh = Bvh::build(&p, &t, &BuildOptions { tri_test: test, layout, ..Default::default() }).unwrap();
        let g = GpuBvh::upload(&ctx, &bvh).unwrap();
        let tracer = Tracer::with_options(&ctx, &TraceOptions { layout, ..TraceOptions::new(test) }).unwrap();
        // The quantised layout changes boxes only (vertex rays aim at box corners): a tenth of
        // the rays suffices.
        let rays = if layout == BvhLayout::Bvh2q { &rays[..rays.len() / 10] } else { &rays[..] };
        let hits = tracer.trace(&ctx, &g, rays, false).unwrap();
        let missed = hits.iter().filter(|h| h.tri == NO_HIT).count();
        // Every fourth ray aims at a vertex (see edge_rays), the others at edge points.
        let at_vertices = hits.iter().step_by(4).filter(|h| h.tri == NO_HIT).count();
        eprintln!(
            "{} [{}]: {missed} of {} edge/vertex rays leaked ({:.4} %; {at_vertices} of {} vertex rays, {} of {} edge rays)",
            test.name(),
            layout.name(),
            rays.len(),
            100.0 * missed as f64 / rays.len() as f64,
            rays.len().div_ceil(4),
            missed - at_vertices,
            rays.len() - rays.len().div_ceil(4)
        );
        leaks.push(missed);
    }
    assert_eq!(leaks[0], 0, "watertight test leaked rays through shared edges");
    assert_eq!(leaks[2], 0, "watertight test leaked rays through shared edges (compressed wide BVH)");
    assert_eq!(leaks[3], 0, "watertight test leaked rays through shared edges (quantised binary BVH)");
    assert_eq!(leaks[4], 0, "watertight test leaked rays through shared edges (4-wide BVH)");
    finish(ctx);
}

#[test]
fn cornell_box_matches_cpu_hit_for_hit() {
    let ctx = gpu();
    let scene = bidir::scene::Scene::builtin_cornell_box();
    let mut rng = Pcg::new(13);
    let (lo, hi) = (Vec3::new(0.0, 0.0, 0.0), Vec3::new(556.0, 548.8, 559.2));
    let mut rays = mixed_rays(&mut rng, lo, hi, 90_000);
    rays.extend(shadow_rays_to_the_light(&mut rng, 30_000));
    // Camera rays through jittered pixels of the reference camera.
    let cam = &scene.cameras[0];
    let g = bidir::gpu_data::gpu_camera(cam);
    for _ in 0..60_000 {
        let (x, y) = (rng.next_f32() * 2.0 - 1.0, 1.0 - rng.next_f32() * 2.0);
        let d = (g.forward + (g.right * x + g.up * y).truncate()).normalize();
        rays.push(ray(cam.eye, d, 3.0e38));
    }
    for tri_test in [TriTest::Watertight, TriTest::Woop] {
        for pre_split in [false, true] {
            check_scene(
                &ctx,
                "cornell",
                &scene.positions,
                &scene.triangles,
                &rays,
                BuildOptions { tri_test, pre_split, ..Default::default() },
            );
        }
    }
    finish(ctx);
}

#[test]
fn sponza_matches_cpu_hit_for_hit() {
    let path = std::path::Path::new("../shared/scenes/sponza/Sponza.gltf");
    if !path.exists() {
        eprintln!("skipping: {} is absent", path.display());
        return;
    }
    let loaded = bidir::scene::load(path, &Default::default()).expect("Sponza loads");
    let scene = loaded.scene;
    let cam = scene.cameras.iter().find(|c| c.name == "CameraMain").expect("CameraMain");
    let g = bidir::gpu_data::gpu_camera(cam);
    let bvh = Bvh::build(&scene.positions, &scene.triangles, &BuildOptions::default()).unwrap();
    let ctx = gpu();
    let cpu = CpuTracer::new(&bvh, &scene.positions, &scene.triangles).with_fma(device_fma(&ctx));
    let mut rng = Pcg::new(14);
    // 100k camera rays through random image points, then from their hits: 50k segments to a
    // point light above the atrium and 50k random directions.
    let mut rays: Vec<GpuRay> = (0..100_000)
        .map(|_| {
            let (x, y) = (rng.next_f32() * 2.0 - 1.0, 1.0 - rng.next_f32() * 2.0);
            ray(cam.eye, (g.forward + (g.right * x + g.up * y).truncate()).normalize(), 3.0e38)
        })
        .collect();
    let light = Vec3::new(0.0, 40.0, 0.0);
    let mut hits = Vec::new();
    for r in &rays {
        let (o, d) = (r.origin.truncate(), r.dir.truncate());
        if let Some((t, h)) = cpu.closest(o, d, 0.0, 3.0e38) {
            let [a, b, c] = scene.triangles[t as usize].map(|i| scene.positions[i as usize]);
            let mut n = (b - a).cross(c - a).normalize();
            if n.dot(d) > 0.0 {
                n = -n;
            }
            hits.push(o + d * h.t + n * 1e-3);
        }
        if hits.len() == 100_000 {
            break;
        }
    }
    for (i, p) in hits.iter().enumerate() {
        if i % 2 == 0 {
            rays.push(ray(*p, (light - *p).normalize(), (light - *p).length()));
        } else {
            rays.push(ray(*p, geometry::random_unit(&mut rng), 3.0e38));
        }
    }
    drop(cpu);
    let (hit, miss) = check_scene(&ctx, "sponza", &scene.positions, &scene.triangles, &rays, BuildOptions::default());
    assert!(hit > 50_000 && miss > 1_000);
    finish(ctx);
}

/// The alpha of `scene`'s triangle `tri` at barycentrics (u, v) of vertices 1 and 2, as
/// glsl/common/scene.glsl computes it (interpolated UV, bilinear filtering between texel
/// centres, repeat wrap, uv (0, 0) at the image's top-left corner); `None` if opaque.
fn cpu_alpha(scene: &bidir::scene::Scene, tri: u32, u: f32, v: f32) -> Option<(f32, f32)> {
    let m = &scene.materials[scene.material_ids[tri as usize] as usize];
    let mask = m.alpha?;
    let uvs = scene.uvs.as_ref()?;
    let [a, b, c] = scene.triangles[tri as usize].map(|i| uvs[i as usize]);
    let uv = (1.0 - u - v) * a + u * b + v * c;
    let t = &scene.textures[mask.texture as usize];
    let (w, h) = (t.width as i32, t.height as i32);
    let p = uv * glam::Vec2::new(w as f32, h as f32) - 0.5;
    let (i, f) = (p.floor(), p - p.floor());
    let texel = |x: i32, y: i32| t.rgba8[((y.rem_euclid(h) * w + x.rem_euclid(w)) * 4 + 3) as usize] as f32 / 255.0;
    let (x, y) = (i.x as i32, i.y as i32);
    let top = texel(x, y) * (1.0 - f.x) + texel(x + 1, y) * f.x;
    let bottom = texel(x, y + 1) * (1.0 - f.x) + texel(x + 1, y + 1) * f.x;
    Some((top * (1.0 - f.y) + bottom * f.y, mask.cutoff))
}

/// Writes the alpha-test scene (OBJ + MTL + two PNG masks) into a fresh directory: two
/// alpha-masked quads (z = 0: an RGBA mask, UVs over [0, 2]² so it repeats; z = -0.5: a grey
/// mask, whose luminance is its alpha, under skewed UVs reaching negative values) in front of
/// an opaque quad (z = -1). Masks are 16x16 texels: fully transparent, fully opaque or random.
fn write_alpha_scene(rng: &mut Pcg) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("bidir-alpha-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let level = |rng: &mut Pcg| match rng.below(5) {
        0 | 1 => 0u8,
        2 | 3 => 255,
        _ => rng.below(256) as u8,
    };
    let rgba: Vec<u8> = (0..16 * 16).flat_map(|_| [200, 180, 90, level(rng)]).collect();
    image::save_buffer(dir.join("mask_rgba.png"), &rgba, 16, 16, image::ExtendedColorType::Rgba8).unwrap();
    let grey: Vec<u8> = (0..16 * 16).map(|_| level(rng)).collect();
    image::save_buffer(dir.join("mask_grey.png"), &grey, 16, 16, image::ExtendedColorType::L8).unwrap();
    std::fs::write(
        dir.join("alpha.mtl"),
        "newmtl leaves\nKd 0.5 0.6 0.2\nmap_d mask_rgba.png\n\nnewmtl fence\nKd 0.7 0.7 0.7\nmap_d mask_grey.png\n\nnewmtl wall\nKd 0.8 0.8 0.8\n",
    )
    .unwrap();
    // OBJ texture coordinates have v upwards; the loader flips them (uv (0, 0) top-left).
    std::fs::write(
        dir.join("alpha.obj"),
        "mtllib alpha.mtl\n\
         v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n\
         v -1 -1 -0.5\nv 1 -1 -0.5\nv 1 1 -0.5\nv -1 1 -0.5\n\
         v -2 -2 -1\nv 2 -2 -1\nv 2 2 -1\nv -2 2 -1\n\
         vt 0 0\nvt 2 0\nvt 2 2\nvt 0 2\n\
         vt -0.3 0.1\nvt 1.1 -0.4\nvt 1.6 0.9\nvt 0.2 1.3\n\
         vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n\
         usemtl leaves\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n\
         usemtl fence\nf 5/5 6/6 7/7\nf 5/5 7/7 8/8\n\
         usemtl wall\nf 9/9 10/10 11/11\nf 9/9 11/11 12/12\n",
    )
    .unwrap();
    dir.join("alpha.obj")
}

#[test]
fn alpha_masked_triangles_are_skipped_as_the_integrators_skip_them() {
    let mut rng = Pcg::new(15);
    let path = write_alpha_scene(&mut rng);
    let scene = bidir::scene::load(&path, &Default::default()).expect("the alpha scene loads").scene;
    std::fs::remove_dir_all(path.parent().unwrap()).ok();
    assert_eq!(scene.materials.iter().filter(|m| m.alpha.is_some()).count(), 2);
    assert!(bidir::gpu_data::SceneFeatures::of(&scene).alpha);
    // Rays from in front (z = 3) and from between the back quads (z = -0.75, facing +z, so
    // masks are also seen from behind), to random points past the masks: whole rays
    // (closest hit) and segments that stop before the opaque quad (any-hit verdicts that
    // depend only on the masks).
    let point = |rng: &mut Pcg, z: f32, r: f32| Vec3::new((rng.next_f32() * 2.0 - 1.0) * r, (rng.next_f32() * 2.0 - 1.0) * r, z);
    let mut rays = Vec::new();
    for i in 0..60_000 {
        let (o, target, stop) = match i % 4 {
            0 | 1 => (point(&mut rng, 3.0, 1.5), point(&mut rng, -1.0, 1.2), false),
            2 => (point(&mut rng, 3.0, 1.5), point(&mut rng, -0.75, 1.0), true),
            _ => (point(&mut rng, -0.75, 0.9), point(&mut rng, 2.0, 1.5), i % 8 == 3),
        };
        let d = (target - o).normalize();
        rays.push(ray(o, d, if stop { (target - o).length() } else { 3.0e38 }));
    }
    let ctx = gpu();
    for (tri_test, layout) in [
        (TriTest::Watertight, BvhLayout::Bvh2),
        (TriTest::Woop, BvhLayout::Bvh2),
        (TriTest::Watertight, BvhLayout::Cwbvh),
        (TriTest::Watertight, BvhLayout::Bvh2q),
        (TriTest::Watertight, BvhLayout::Bvh4),
    ] {
        let bvh = Bvh::build(&scene.positions, &scene.triangles, &BuildOptions { tri_test, layout, ..Default::default() }).unwrap();
        let cpu = CpuTracer::new(&bvh, &scene.positions, &scene.triangles).with_fma(device_fma(&ctx));
        let gscene = bidir::render::GpuScene::upload(&ctx, &scene, &bvh).unwrap();
        let build = BuildOptions { tri_test, layout, ..Default::default() };
        // The variants with an alpha-tested kernel (no short stack, other workgroup sizes, shared
        // leaf tests or packets).
        let alpha_ok =
            |o: &TraceOptions| !o.short_stack && !o.share_leaves && !o.packet && o.workgroup_size == bidir::gpu::abi::TRACE_WG_SIZE;
        for (variant, mut opts) in variants(&build).into_iter().filter(|(_, o)| alpha_ok(o)) {
            opts.alpha = Some(gscene.features);
            let tracer = Tracer::with_options(&ctx, &opts).unwrap();
            let closest = tracer.trace_with(&ctx, &gscene.binds(), &rays, false).unwrap();
            let any = tracer.trace_with(&ctx, &gscene.binds(), &rays, true).unwrap();
            let (mut compared, mut near_cutoff, mut through_mask, mut occluded, mut unoccluded) = (0, 0, 0, 0, 0);
            let mut per_layer = [0usize; 3];
            // Layer of a triangle: 0 (z = 0), 1 (z = -0.5), 2 (z = -1).
            let layer = |tri: u32| (-2.0 * scene.positions[scene.triangles[tri as usize][0] as usize].z).round() as usize;
            for (i, r) in rays.iter().enumerate() {
                let (o, d, tmax) = (r.origin.truncate(), r.dir.truncate(), r.dir.w);
                // The reference with the same cutoff; a ray whose alpha lands within 1e-3 of the
                // cutoff is not compared (GPU and CPU may round the UV differently).
                let ambiguous = std::cell::Cell::new(false);
                let accept = |tri: u32, h: &bidir::bvh::intersect::TriHit| match cpu_alpha(&scene, tri, h.u, h.v) {
                    None => true,
                    Some((a, cutoff)) => {
                        if (a - cutoff).abs() < 1e-3 {
                            ambiguous.set(true);
                        }
                        a >= cutoff
                    }
                };
                let want = cpu.closest_where(o, d, 0.0, tmax, accept);
                let want_any = cpu.any_where(o, d, 0.0, tmax, accept);
                if ambiguous.get() {
                    near_cutoff += 1;
                    continue;
                }
                compared += 1;
                let g = closest[i];
                match want {
                    None => {
                        assert_eq!(g.tri, NO_HIT, "{variant} ray {i} ({o}, {d}): GPU hit prim {} at t={}, CPU (alpha) missed", g.tri, g.t)
                    }
                    Some((tri, h)) => {
                        assert_ne!(g.tri, NO_HIT, "{variant} ray {i} ({o}, {d}): CPU (alpha) hit triangle {tri} at t={}, GPU missed", h.t);
                        let gtri = bvh.tri_ids[g.tri as usize];
                        // The two triangles of a quad share a diagonal: a tie there is fine.
                        assert!(
                            layer(gtri) == layer(tri) && (g.t - h.t).abs() <= 1e-4 * h.t,
                            "{variant} ray {i} ({o}, {d}): GPU triangle {gtri} t={}, CPU (alpha) triangle {tri} t={}",
                            g.t,
                            h.t
                        );
                        per_layer[layer(tri)] += 1;
                        if cpu.closest(o, d, 0.0, tmax).is_some_and(|(t0, _)| layer(t0) != layer(tri)) {
                            through_mask += 1;
                        }
                    }
                }
                assert_eq!(any[i].tri != NO_HIT, want_any, "{variant} ray {i} ({o}, {d}, tmax {tmax}): any-hit verdict with alpha");
                if tmax < 1e30 {
                    if want_any {
                        occluded += 1
                    } else {
                        unoccluded += 1
                    }
                }
            }
            eprintln!(
                "alpha [{}, {}, {variant}]: {compared} rays compared ({near_cutoff} within 1e-3 of the cutoff skipped); closest hits on leaves/fence/wall {per_layer:?}, {through_mask} through a transparent texel; segments {occluded} occluded, {unoccluded} unoccluded",
                tri_test.name(),
                layout.name()
            );
            assert!(near_cutoff * 100 < rays.len(), "too many rays near the cutoff: {near_cutoff}");
            assert!(per_layer.iter().all(|&n| n > 2_000) && through_mask > 10_000, "the rays must see every layer and pass through holes");
            assert!(occluded > 2_000 && unoccluded > 2_000, "segments must be both blocked and let through");
        }
        drop(gscene);
    }
    finish(ctx);
}

/// Ray reordering (`bench traversal --sort`): the GPU's counting sort returns a permutation of
/// the rays in the order of the key the CPU computes with the same operations (direction
/// octant, then origin cell's Morton code), and tracing the sorted rays gives every ray
/// exactly the hit (and any-hit verdict) it gets unsorted.
#[test]
fn sorted_rays_are_a_permutation_in_key_order_with_the_same_hits() {
    let ctx = gpu();
    let scene = bidir::scene::Scene::builtin_cornell_box();
    let mut rng = Pcg::new(16);
    let (lo, hi) = (Vec3::new(0.0, 0.0, 0.0), Vec3::new(556.0, 548.8, 559.2));
    let rays = mixed_rays(&mut rng, lo, hi, 30_000);
    let sorter = RaySorter::new(&ctx, rays.len() as u32).unwrap();
    let (sorted, order) = sorter.sort(&ctx, &rays, lo, hi).unwrap();
    let push = sort_push(lo, hi, rays.len() as u32);
    let mut seen = vec![false; rays.len()];
    let (mut prev, mut distinct) = (0, 0);
    for (j, (&i, r)) in order.iter().zip(&sorted).enumerate() {
        assert!(!std::mem::replace(&mut seen[i as usize], true), "ray {i} placed twice");
        assert!(r.origin == rays[i as usize].origin && r.dir == rays[i as usize].dir, "slot {j} holds a different ray than {i}");
        let key = sort_key(&push, r.origin.truncate(), r.dir.truncate());
        assert!(key >= prev, "slot {j}: key {key} after {prev}");
        distinct += (j == 0 || key != prev) as usize;
        prev = key;
    }
    assert!(distinct > 500, "the rays must spread over many keys ({distinct})");
    let bvh = Bvh::build(&scene.positions, &scene.triangles, &BuildOptions::default()).unwrap();
    let gbvh = GpuBvh::upload(&ctx, &bvh).unwrap();
    let tracer = Tracer::new(&ctx, TriTest::Watertight, false).unwrap();
    for any_hit in [false, true] {
        let unsorted = tracer.trace(&ctx, &gbvh, &rays, any_hit).unwrap();
        let hits = tracer.trace(&ctx, &gbvh, &sorted, any_hit).unwrap();
        for (j, &i) in order.iter().enumerate() {
            let (a, b) = (unsorted[i as usize], hits[j]);
            assert!(a.tri == b.tri && a.t.to_bits() == b.t.to_bits(), "ray {i} (any hit: {any_hit}): {a:?} unsorted, {b:?} sorted");
        }
    }
    drop((gbvh, tracer, sorter));
    eprintln!("sort: {} rays over {distinct} keys, hits identical", rays.len());
    finish(ctx);
}

/// The local ray sort (`bench traversal --sort-local GRID,BLOCK`): a permutation that keeps
/// every ray in its block of consecutive rays, puts each block in the order of its rays'
/// direction cells (the cells the CPU computes, but for a division's rounding on a cell's
/// border), and leaves every ray's hit (and any-hit verdict) as it is unsorted. A last block
/// shorter than the others and a grid of one cell included.
#[test]
fn locally_sorted_rays_stay_in_their_blocks_in_direction_order_with_the_same_hits() {
    let ctx = gpu();
    let scene = bidir::scene::Scene::builtin_cornell_box();
    let mut rng = Pcg::new(17);
    let (lo, hi) = (Vec3::new(0.0, 0.0, 0.0), Vec3::new(556.0, 548.8, 559.2));
    let rays = mixed_rays(&mut rng, lo, hi, 30_000);
    let sorter = RaySorter::new(&ctx, rays.len() as u32).unwrap();
    let bvh = Bvh::build(&scene.positions, &scene.triangles, &BuildOptions::default()).unwrap();
    let gbvh = GpuBvh::upload(&ctx, &bvh).unwrap();
    let tracer = Tracer::new(&ctx, TriTest::Watertight, false).unwrap();
    let unsorted: Vec<_> = [false, true].map(|any_hit| tracer.trace(&ctx, &gbvh, &rays, any_hit).unwrap()).into();
    for (grid, block) in [(4u32, 1024u32), (8, 256), (16, 4096), (1, 1000), (3, 7)] {
        let (sorted, order, cells) = sorter.sort_local(&ctx, &rays, grid, block).unwrap();
        let mut seen = vec![false; rays.len()];
        let (mut moved, mut on_border) = (0, 0);
        let mut distinct = std::collections::HashSet::new();
        for (j, (&i, r)) in order.iter().zip(&sorted).enumerate() {
            let i = i as usize;
            assert!(!std::mem::replace(&mut seen[i], true), "{grid}x{grid}, blocks of {block}: ray {i} placed twice");
            assert!(
                r.origin == rays[i].origin && r.dir == rays[i].dir,
                "{grid}x{grid}, blocks of {block}: slot {j} holds a different ray than {i}"
            );
            assert_eq!(i / block as usize, j / block as usize, "{grid}x{grid}: ray {i} left its block of {block} for slot {j}");
            if j % block as usize != 0 {
                assert!(
                    cells[j] >= cells[j - 1],
                    "{grid}x{grid}, blocks of {block}: slot {j} has cell {} after {}",
                    cells[j],
                    cells[j - 1]
                );
            }
            let cell = direction_cell(grid, r.dir.truncate());
            on_border += (cell != cells[j]) as usize;
            moved += (i != j) as usize;
            distinct.insert(cells[j]);
        }
        assert!(on_border <= 3, "{grid}x{grid}: {on_border} rays in another cell than the CPU's");
        assert!(distinct.len() as u32 == grid * grid, "{grid}x{grid}: the rays must reach every cell ({})", distinct.len());
        assert!(grid == 1 || moved > rays.len() / 2, "{grid}x{grid}, blocks of {block}: only {moved} rays moved");
        for (k, any_hit) in [false, true].into_iter().enumerate() {
            let hits = tracer.trace(&ctx, &gbvh, &sorted, any_hit).unwrap();
            for (j, &i) in order.iter().enumerate() {
                let (a, b) = (unsorted[k][i as usize], hits[j]);
                assert!(a.tri == b.tri && a.t.to_bits() == b.t.to_bits(), "ray {i} (any hit: {any_hit}): {a:?} unsorted, {b:?} sorted");
            }
        }
        eprintln!("local sort {grid}x{grid}, blocks of {block}: {moved} of {} rays moved, {on_border} on a border", rays.len());
    }
    drop((gbvh, tracer, sorter));
    finish(ctx);
}

/// Rays a kernel queued (`Tracer::record_trace_queued`, the wavefront path tracer's): the
/// trace kernels take the ray count from a buffer, so they trace the first count[i] rays of
/// the buffer and no more, with the hits of tracing those rays alone, for every launch shape the
/// wavefront tracer may use (one invocation per ray; persistent threads; dynamic fetch), each
/// launched directly (over the queue's capacity) and from an indirect dispatch sized for the
/// queued rays as wf_end_launch sizes it (glsl/common/wf_active.glsl; BDPT's wavefront passes: a workgroup per
/// TRACE_WG_SIZE rays, at most `queued_groups` of the capacity).
#[test]
fn queued_ray_counts_trace_only_the_queued_rays() {
    use bidir::vk::{Bind, Memory};
    let ctx = gpu();
    let scene = bidir::scene::Scene::builtin_cornell_box();
    let mut rng = Pcg::new(29);
    let (lo, hi) = (Vec3::new(0.0, 0.0, 0.0), Vec3::new(556.0, 548.8, 559.2));
    let rays = mixed_rays(&mut rng, lo, hi, 5_000);
    let opts = BuildOptions { layout: BvhLayout::Bvh4, ..Default::default() };
    let bvh = Bvh::build(&scene.positions, &scene.triangles, &opts).unwrap();
    let gbvh = GpuBvh::upload(&ctx, &bvh).unwrap();
    let base = TraceOptions { layout: BvhLayout::Bvh4, ..TraceOptions::new(opts.tri_test) };
    let plain = Tracer::with_options(&ctx, &base).unwrap();
    let shapes = [
        ("per-ray", base),
        ("per-ray, origin in shared memory", TraceOptions { shared_origin: Some(true), ..base }),
        ("per-ray, shared leaf tests", TraceOptions { share_leaves: true, ..base }),
        ("packet", TraceOptions { packet: true, ..base }),
        ("persistent 3 groups", TraceOptions { persistent: Some(3), ..base }),
        ("dynamic fetch at 3 lanes", TraceOptions { persistent: Some(0), refill_lanes: 3, ..base }),
        ("dynamic fetch at 3 lanes, shared leaf tests", TraceOptions { persistent: Some(0), refill_lanes: 3, share_leaves: true, ..base }),
    ];
    // Shared leaf tests belong to lockstep loops: refused for plain persistent threads' batches.
    assert!(Tracer::with_options(&ctx, &TraceOptions { share_leaves: true, persistent: Some(3), ..base }).is_err());
    // Packets are one ray per invocation over the 4-wide layout: refused with persistent threads
    // and over the binary layout.
    assert!(Tracer::with_options(&ctx, &TraceOptions { packet: true, persistent: Some(0), refill_lanes: 3, ..base }).is_err());
    assert!(Tracer::with_options(&ctx, &TraceOptions { packet: true, layout: BvhLayout::Bvh2, ..base }).is_err());
    // Queued: 1,234 rays (the count at index 1; index 0 holds a decoy).
    let queued = 1_234usize;
    let counts = ctx.upload_buffer("test.counts", &[4_321u32, queued as u32]).unwrap();
    let ray_buf = ctx.upload_buffer("test.rays", &rays).unwrap();
    let hits = ctx.create_buffer("test.hits", rays.len() as u64 * 16, Memory::Device).unwrap();
    let stats = ctx.create_buffer("test.stats", 8, Memory::Device).unwrap();
    const UNTOUCHED: u32 = 0xdead_beef;
    // An indirect dispatch at byte 16 (entry 1), as wf_end_launch writes it.
    let dispatch = ctx.create_indirect_buffer("test.dispatch", 32).unwrap();
    for any_hit in [false, true] {
        let want: Vec<GpuHit> = plain.trace(&ctx, &gbvh, &rays[..queued], any_hit).unwrap();
        for ((shape, o), indirect) in shapes.iter().flat_map(|s| [(s, false), (s, true)]) {
            let tracer = Tracer::with_options(&ctx, &TraceOptions { count_buffer: true, ..*o }).unwrap();
            let capacity = rays.len() as u32;
            let groups = (queued as u32).div_ceil(bidir::gpu::abi::TRACE_WG_SIZE).min(tracer.queued_groups(capacity));
            let shape = format!("{shape}{}", if indirect { format!(", indirect ({groups} groups)") } else { String::new() });
            // Twice with one tracer: a persistent launch leaves its ray counter at 0 for the
            // next (no fill between them).
            for trace in ["first", "second"] {
                ctx.submit("queued trace", |rec| {
                    rec.fill_buffer(&hits, UNTOUCHED);
                    rec.fill_buffer_range(&dispatch, 16, 4, groups);
                    rec.fill_buffer_range(&dispatch, 20, 8, 1);
                    let geometry: Vec<Bind> = gbvh.binds();
                    let sized = indirect.then_some((&dispatch, 16));
                    tracer.record_trace_queued(rec, &geometry, &ray_buf, &hits, &stats, capacity, Some((&counts, 1)), any_hit, sized)
                })
                .unwrap();
                let got: Vec<GpuHit> = ctx.read_buffer(&hits).unwrap();
                for (i, (g, w)) in got.iter().zip(&want).enumerate() {
                    assert_eq!((g.tri, g.t.to_bits()), (w.tri, w.t.to_bits()), "{shape}, any hit {any_hit}, {trace} trace: ray {i}");
                }
                let traced_past = got[queued..].iter().filter(|h| h.tri != UNTOUCHED).count();
                assert_eq!(traced_past, 0, "{shape}, any hit {any_hit}: {traced_past} rays past the queued count were traced");
            }
        }
    }
    drop((gbvh, plain, counts, ray_buf, hits, stats, dispatch));
    finish(ctx);
}

/// The wavefront passes' compact ray forms (`TraceOptions::ray_words`; glsl/common/ray_words.glsl,
/// `bidir::trace::ray_forms`): segments in 24 bytes, closest hit, and shadow rays in 28, any hit,
/// each traced to the hit its `GpuRay` gets, bit for bit, in every loop the queued traces run
/// (per ray, dynamic fetch); a segment's zero direction is no segment. Forms the kernels do not
/// read are refused.
#[test]
fn compact_ray_forms_trace_as_their_gpu_rays() {
    use bidir::trace::ray_forms;
    use bidir::vk::{Bind, Memory};
    let ctx = gpu();
    let scene = bidir::scene::Scene::builtin_cornell_box();
    let mut rng = Pcg::new(37);
    let (lo, hi) = (Vec3::new(0.0, 0.0, 0.0), Vec3::new(556.0, 548.8, 559.2));
    let mixed = mixed_rays(&mut rng, lo, hi, 3_000);
    // Segments: unbounded, every 101st absent (tmax < 0, a zero direction); shadow rays as drawn.
    let segments: Vec<GpuRay> = mixed
        .iter()
        .map(|r| match r.dir.w < 0.0 {
            true => GpuRay { origin: Vec4::ZERO, dir: Vec4::new(0.0, 0.0, 0.0, -1.0) },
            false => GpuRay { dir: r.dir.truncate().extend(ray_forms::SEGMENT_TMAX), ..*r },
        })
        .collect();
    let opts = BuildOptions { layout: BvhLayout::Bvh4, ..Default::default() };
    let bvh = Bvh::build(&scene.positions, &scene.triangles, &opts).unwrap();
    let gbvh = GpuBvh::upload(&ctx, &bvh).unwrap();
    let base = TraceOptions { layout: BvhLayout::Bvh4, count_buffer: true, ..TraceOptions::new(opts.tri_test) };
    let compact = [abi::RAY_WORDS_SEGMENT, abi::RAY_WORDS_BOUNDED];
    for bad in [[abi::RAY_WORDS_BOUNDED, abi::RAY_WORDS_BOUNDED], [abi::RAY_WORDS_SEGMENT, abi::RAY_WORDS_SEGMENT], [5, 8]] {
        assert!(Tracer::with_options(&ctx, &TraceOptions { ray_words: bad, ..base }).is_err(), "{bad:?}");
    }
    let seeded = TraceOptions { ray_words: compact, ray_seed: true, alpha: Some(bidir::gpu_data::SceneFeatures::default()), ..base };
    assert!(Tracer::with_options(&ctx, &seeded).is_err(), "compact rays with an opacity seed");
    let plain = Tracer::with_options(&ctx, &TraceOptions { count_buffer: false, ..base }).unwrap();
    let counts = ctx.upload_buffer("test.counts", &[mixed.len() as u32]).unwrap();
    let hits = ctx.create_buffer("test.hits", mixed.len() as u64 * 16, Memory::Device).unwrap();
    let stats = ctx.create_buffer("test.stats", 8, Memory::Device).unwrap();
    for (loop_kind, o) in [("per ray", base), ("dynamic fetch at 3 lanes", TraceOptions { persistent: Some(0), refill_lanes: 3, ..base })] {
        let tracer = Tracer::with_options(&ctx, &TraceOptions { ray_words: compact, ..o }).unwrap();
        for (any_hit, rays) in [(false, &segments), (true, &mixed)] {
            let want: Vec<GpuHit> = plain.trace(&ctx, &gbvh, rays, any_hit).unwrap();
            let form = compact[any_hit as usize];
            let queue = ray_forms::pack(rays, form).unwrap();
            let ray_buf = ctx.upload_buffer("test.compact_rays", &queue).unwrap();
            ctx.submit("compact trace", |rec| {
                let geometry: Vec<Bind> = gbvh.binds();
                tracer.record_trace_queued(rec, &geometry, &ray_buf, &hits, &stats, rays.len() as u32, Some((&counts, 0)), any_hit, None)
            })
            .unwrap();
            let got: Vec<GpuHit> = ctx.read_buffer(&hits).unwrap();
            let hit_count = want.iter().filter(|h| h.tri != NO_HIT).count();
            assert!(hit_count * 4 > rays.len(), "{loop_kind}, any hit {any_hit}: only {hit_count} rays hit");
            for (i, (g, w)) in got.iter().zip(&want).enumerate() {
                assert_eq!(
                    (g.tri, g.t.to_bits(), g.u.to_bits(), g.v.to_bits()),
                    (w.tri, w.t.to_bits(), w.u.to_bits(), w.v.to_bits()),
                    "{loop_kind}, any hit {any_hit}, form {form}: ray {i} ({:?})",
                    rays[i]
                );
            }
            drop(ray_buf);
        }
    }
    drop((gbvh, plain, counts, hits, stats));
    finish(ctx);
}

/// Any-hit rays over the 4-wide layout traverse their own copy of the nodes
/// (`Bvh::bvh4_any_nodes`, slots in occlusion order) from the root node 0 names, and closest-hit
/// rays the tree itself, in every loop the kernels have (lockstep, divergent, dynamic fetch):
/// with the copy's root emptied every any-hit ray misses and no closest hit moves; without a
/// copy (`occlusion_copy: false`) the verdicts are the copy's.
#[test]
fn any_hit_rays_traverse_their_own_copy_of_the_4_wide_nodes() {
    let ctx = gpu();
    let scene = bidir::scene::Scene::builtin_cornell_box();
    let mut rng = Pcg::new(31);
    let (lo, hi) = (Vec3::new(0.0, 0.0, 0.0), Vec3::new(556.0, 548.8, 559.2));
    let rays = mixed_rays(&mut rng, lo, hi, 4_000);
    let opts = BuildOptions { layout: BvhLayout::Bvh4, ..Default::default() };
    let bvh = Bvh::build(&scene.positions, &scene.triangles, &opts).unwrap();
    let plain = Bvh::build(&scene.positions, &scene.triangles, &BuildOptions { occlusion_copy: false, ..opts }).unwrap();
    let mut emptied = bvh.clone();
    let root = &mut emptied.bvh4_any_nodes[0];
    for s in 0..4 {
        for axis in 0..3 {
            root.planes[2 * axis][s] = f32::INFINITY;
            root.planes[2 * axis + 1][s] = f32::NEG_INFINITY;
        }
    }
    let [gbvh, gplain, gemptied] = [&bvh, &plain, &emptied].map(|b| GpuBvh::upload(&ctx, b).unwrap());
    let base = TraceOptions { layout: BvhLayout::Bvh4, ..TraceOptions::new(opts.tri_test) };
    for (loop_kind, o) in [
        ("lockstep", base),
        ("lockstep, origin in shared memory", TraceOptions { shared_origin: Some(true), ..base }),
        ("lockstep, shared leaf tests", TraceOptions { share_leaves: true, ..base }),
        ("divergent loops", TraceOptions { lockstep: false, ..base }),
        ("dynamic fetch at 3 lanes", TraceOptions { persistent: Some(0), refill_lanes: 3, ..base }),
        ("dynamic fetch at 3 lanes, shared leaf tests", TraceOptions { persistent: Some(0), refill_lanes: 3, share_leaves: true, ..base }),
    ] {
        let tracer = Tracer::with_options(&ctx, &o).unwrap();
        let closest = tracer.trace(&ctx, &gbvh, &rays, false).unwrap();
        let any = tracer.trace(&ctx, &gbvh, &rays, true).unwrap();
        let blocked = any.iter().filter(|h| h.tri != NO_HIT).count();
        assert!(blocked > rays.len() / 4, "{loop_kind}: only {blocked} of {} rays blocked", rays.len());
        let any_plain = tracer.trace(&ctx, &gplain, &rays, true).unwrap();
        for (i, (a, b)) in any.iter().zip(&any_plain).enumerate() {
            assert_eq!(a.tri != NO_HIT, b.tri != NO_HIT, "{loop_kind}: ray {i}'s verdict differs without the copy");
        }
        let closest_emptied = tracer.trace(&ctx, &gemptied, &rays, false).unwrap();
        for (i, (a, b)) in closest.iter().zip(&closest_emptied).enumerate() {
            assert_eq!((a.tri, a.t.to_bits()), (b.tri, b.t.to_bits()), "{loop_kind}: ray {i}'s closest hit read the any-hit copy");
        }
        let missed = tracer.trace(&ctx, &gemptied, &rays, true).unwrap().iter().filter(|h| h.tri == NO_HIT).count();
        assert_eq!(missed, rays.len(), "{loop_kind}: any-hit rays found hits past the copy's empty root");
    }
    drop((gbvh, gplain, gemptied));
    finish(ctx);
}
