//! GPU traversal against the CPU reference (obvhs' own BVH2 traversal with the same triangle
//! tests), hit for hit, and the watertightness of the watertight test.

mod common;

use bidir::bvh::{BuildOptions, Bvh, CpuTracer, TriTest};
use bidir::gpu::abi::{GpuHit, GpuRay, NO_HIT};
use bidir::trace::{GpuBvh, Tracer};
use bidir::vk::Context;
use common::{finish, geometry, gpu, Pcg};
use glam::Vec3;

fn ray(o: Vec3, d: Vec3, tmax: f32) -> GpuRay {
    GpuRay { origin: o.extend(0.0), dir: d.extend(tmax) }
}

/// Compares GPU closest hits and any-hit verdicts with the CPU for every ray; returns
/// (hits, misses) of the closest-hit pass.
fn check_scene(ctx: &Context, name: &str, positions: &[Vec3], tris: &[[u32; 3]], rays: &[GpuRay], opts: BuildOptions) -> (usize, usize) {
    let bvh = Bvh::build(positions, tris, &opts).unwrap();
    let cpu = CpuTracer::new(&bvh, positions, tris);
    let scale = positions.iter().fold(0f32, |m, p| m.max(p.abs().max_element()));
    let gbvh = GpuBvh::upload(ctx, &bvh).unwrap();
    let tracer = Tracer::new(ctx, opts.tri_test, false).unwrap();
    let closest: Vec<GpuHit> = tracer.trace(ctx, &gbvh, rays, false).unwrap();
    let any: Vec<GpuHit> = tracer.trace(ctx, &gbvh, rays, true).unwrap();
    let (mut hits, mut misses, mut ties) = (0, 0, 0);
    for (i, r) in rays.iter().enumerate() {
        let (o, d, tmax) = (r.origin.truncate(), r.dir.truncate(), r.dir.w);
        let want = cpu.closest(o, d, r.origin.w, tmax);
        let g = closest[i];
        match want {
            None => {
                assert_eq!(g.tri, NO_HIT, "{name} ray {i} ({o}, {d}): GPU hit prim {} at t={}, CPU missed", g.tri, g.t);
                misses += 1;
            }
            Some((tri, h)) => {
                assert_ne!(g.tri, NO_HIT, "{name} ray {i} ({o}, {d}): CPU hit triangle {tri} at t={}, GPU missed", h.t);
                let gtri = bvh.tri_ids[g.tri as usize];
                if gtri != tri {
                    // A tie: two triangles at the same distance (a shared edge or vertex).
                    assert!((g.t - h.t).abs() <= 1e-6 * h.t.abs(), "{name} ray {i}: GPU triangle {gtri} t={}, CPU triangle {tri} t={}", g.t, h.t);
                    ties += 1;
                } else {
                    // Same triangle. Its t is computed with the same operations on both sides,
                    // but GPUs round some of them differently (Vulkan allows 2.5 ulp division),
                    // and t is ill-conditioned for grazing hits and far-off vertices (the edge
                    // functions cancel), so its error is absolute, a few ulps of the coordinates
                    // (an H100: 3e-5 at Cornell scale). Only a guard against gross errors; the
                    // requirement is the triangle itself.
                    let tol = 1e-3 * h.t.abs() + 1e-5 * scale.max(o.abs().max_element());
                    assert!((g.t - h.t).abs() <= tol, "{name} ray {i}: t GPU {} CPU {}", g.t, h.t);
                }
                hits += 1;
            }
        }
        let cpu_any = cpu.any(o, d, r.origin.w, tmax);
        assert_eq!(any[i].tri != NO_HIT, cpu_any, "{name} ray {i} ({o}, {d}, tmax {tmax}): any-hit verdict");
    }
    eprintln!("{name} [{}]: {} rays, {hits} hits ({ties} ties), {misses} misses; {} nodes, depth {}", opts.tri_test.name(), rays.len(), bvh.nodes.len(), bvh.depth);
    drop((gbvh, tracer));
    (hits, misses)
}

/// Rays of three kinds: from outside toward the scene, random directions from inside, and
/// segments between random points (shadow-like, finite tmax).
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
    for test in [TriTest::Watertight, TriTest::Woop] {
        let bvh = Bvh::build(&p, &t, &BuildOptions { tri_test: test, ..Default::default() }).unwrap();
        let g = GpuBvh::upload(&ctx, &bvh).unwrap();
        let tracer = Tracer::new(&ctx, test, false).unwrap();
        let hits = tracer.trace(&ctx, &g, &rays, false).unwrap();
        let missed = hits.iter().filter(|h| h.tri == NO_HIT).count();
        eprintln!("{}: {missed} of {} edge/vertex rays leaked ({:.4} %)", test.name(), rays.len(), 100.0 * missed as f64 / rays.len() as f64);
        leaks.push(missed);
    }
    assert_eq!(leaks[0], 0, "watertight test leaked rays through shared edges");
    finish(ctx);
}

#[test]
fn cornell_box_matches_cpu_hit_for_hit() {
    let ctx = gpu();
    let scene = bidir::scene::Scene::builtin_cornell_box();
    let mut rng = Pcg::new(13);
    let (lo, hi) = (Vec3::new(0.0, 0.0, 0.0), Vec3::new(556.0, 548.8, 559.2));
    let mut rays = mixed_rays(&mut rng, lo, hi, 90_000);
    // Camera rays through jittered pixels of the reference camera.
    let cam = &scene.cameras[0];
    let g = bidir::trace::gpu_camera(cam);
    for _ in 0..60_000 {
        let (x, y) = (rng.next_f32() * 2.0 - 1.0, 1.0 - rng.next_f32() * 2.0);
        let d = (g.forward + g.right * x + g.up * y).truncate().normalize();
        rays.push(ray(cam.eye, d, 3.0e38));
    }
    for tri_test in [TriTest::Watertight, TriTest::Woop] {
        for pre_split in [false, true] {
            check_scene(&ctx, "cornell", &scene.positions, &scene.triangles, &rays, BuildOptions { tri_test, pre_split, ..Default::default() });
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
    let g = bidir::trace::gpu_camera(cam);
    let bvh = Bvh::build(&scene.positions, &scene.triangles, &BuildOptions::default()).unwrap();
    let cpu = CpuTracer::new(&bvh, &scene.positions, &scene.triangles);
    let mut rng = Pcg::new(14);
    // 100k camera rays through random image points, then from their hits: 50k segments to a
    // point light above the atrium and 50k random directions.
    let mut rays: Vec<GpuRay> = (0..100_000)
        .map(|_| {
            let (x, y) = (rng.next_f32() * 2.0 - 1.0, 1.0 - rng.next_f32() * 2.0);
            ray(cam.eye, (g.forward + g.right * x + g.up * y).truncate().normalize(), 3.0e38)
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
    let ctx = gpu();
    let (hit, miss) = check_scene(&ctx, "sponza", &scene.positions, &scene.triangles, &rays, BuildOptions::default());
    assert!(hit > 50_000 && miss > 1_000);
    finish(ctx);
}
