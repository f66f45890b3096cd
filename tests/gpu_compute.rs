//! Real kernels on whatever Vulkan device is present (lavapipe in CI), checked against the
//! CPU, validation-clean.

mod common;

use bidir::compute::Scan;
use bidir::gpu::{abi, kernels};
use bidir::vk::{Bind, Format, Memory};
use common::{finish, gpu, Pcg};

/// Sizes around the edges of one block, one block of blocks, and odd sizes in between.
const SIZES: &[u32] = &[1, 2, 7, 255, 256, 257, 1000, 4099, 65_535, 65_536, 65_537, 100_003, 1_000_001];

#[test]
fn subgroup_reduction_matches_cpu() {
    let ctx = gpu();
    let scan = Scan::new(&ctx).unwrap();
    let mut rng = Pcg::new(1);
    for &n in SIZES {
        let values: Vec<u32> = (0..n).map(|_| rng.below(4096)).collect();
        let input = ctx.upload_buffer("reduce.in", &values).unwrap();
        let expect = values.iter().fold(0u32, |a, &v| a.wrapping_add(v));
        assert_eq!(scan.sum(&ctx, &input, n).unwrap(), expect, "sum of {n} values");
        // Only the first `count` elements count.
        if n > 3 {
            let partial = values[..n as usize - 3].iter().fold(0u32, |a, &v| a.wrapping_add(v));
            assert_eq!(scan.sum(&ctx, &input, n - 3).unwrap(), partial, "sum of the first {} of {n}", n - 3);
        }
    }
    drop(scan);
    finish(ctx);
}

#[test]
fn subgroup_prefix_sum_matches_cpu() {
    let ctx = gpu();
    let scan = Scan::new(&ctx).unwrap();
    let mut rng = Pcg::new(2);
    for &n in SIZES {
        let values: Vec<u32> = (0..n).map(|_| rng.below(1000)).collect();
        let data = ctx.upload_buffer("scan.data", &values).unwrap();
        scan.exclusive_scan(&ctx, &data, n).unwrap();
        let got: Vec<u32> = ctx.read_buffer(&data).unwrap();
        let mut acc = 0u32;
        for (i, &v) in values.iter().enumerate() {
            assert_eq!(got[i], acc, "exclusive scan of {n} values differs at index {i}");
            acc = acc.wrapping_add(v);
        }
    }
    drop(scan);
    finish(ctx);
}

#[test]
fn shader_subgroup_size_matches_device_report() {
    let ctx = gpu();
    let k = ctx.create_kernel(&kernels::SUBGROUP_PROBE, &[]).unwrap();
    let n = abi::SCAN_WG_SIZE * 3;
    let out = ctx.create_buffer("probe.out", n as u64 * 16, Memory::Device).unwrap();
    ctx.submit("probe", |rec| rec.dispatch(&k, &[Bind::buffer(abi::PROBE_BIND_OUT, &out)], &[], [3, 1, 1])).unwrap();
    let probes: Vec<abi::SubgroupProbe> = ctx.read_buffer(&out).unwrap();
    let reported = ctx.info().subgroup_size;
    for (i, p) in probes.iter().enumerate() {
        assert!(
            p.subgroup_size >= ctx.info().min_subgroup_size && p.subgroup_size <= ctx.info().max_subgroup_size,
            "invocation {i}: shader subgroup size {} outside the device's {}..{}",
            p.subgroup_size,
            ctx.info().min_subgroup_size,
            ctx.info().max_subgroup_size
        );
        assert_eq!(p.num_subgroups, abi::SCAN_WG_SIZE.div_ceil(p.subgroup_size), "invocation {i}");
        assert!(p.invocation_id < p.subgroup_size && p.subgroup_id < p.num_subgroups);
    }
    // Without a required size the default must be the one the device reports.
    assert_eq!(probes[0].subgroup_size, reported, "default subgroup size");
    drop((k, out));
    finish(ctx);
}

#[test]
fn buffer_round_trip() {
    let ctx = gpu();
    let mut rng = Pcg::new(3);
    for n in [1usize, 3, 1024, 333_333] {
        let data: Vec<u32> = (0..n).map(|_| rng.next_u32()).collect();
        let buf = ctx.upload_buffer("round_trip", &data).unwrap();
        assert_eq!(ctx.read_buffer::<u32>(&buf).unwrap()[..n], data[..], "{n} words");
        // And through a host-visible buffer written directly.
        let mut up = ctx.create_buffer("round_trip.upload", n as u64 * 4, Memory::Upload).unwrap();
        up.write(0, &data).unwrap();
        let dev = ctx.create_buffer("round_trip.device", n as u64 * 4, Memory::Device).unwrap();
        ctx.submit("copy", |rec| {
            rec.copy_buffer(&up, &dev, n as u64 * 4);
            Ok(())
        })
        .unwrap();
        assert_eq!(ctx.read_buffer::<u32>(&dev).unwrap()[..n], data[..]);
    }
    finish(ctx);
}

#[test]
fn image_round_trip_and_kernel() {
    let ctx = gpu();
    let mut rng = Pcg::new(4);
    for (w, h) in [(1u32, 1u32), (13, 7), (256, 256), (321, 123)] {
        let texels: Vec<f32> = (0..w * h * 4).map(|_| rng.next_f32() * 100.0 - 50.0).collect();
        let src = ctx.create_image("img.src", w, h, Format::R32G32B32A32_SFLOAT).unwrap();
        ctx.write_image(&src, &texels).unwrap();
        assert_eq!(ctx.read_image::<f32>(&src).unwrap(), texels, "{w}x{h} round trip");

        let dst = ctx.create_image("img.dst", w, h, Format::R32G32B32A32_SFLOAT).unwrap();
        let k = ctx.create_kernel(&kernels::IMAGE_AFFINE, &[]).unwrap();
        let push = abi::ImageAffinePush {
            scale: glam::Vec4::new(2.0, -1.0, 0.5, 0.0),
            offset: glam::Vec4::new(1.0, 0.0, -3.0, 7.0),
            size: glam::UVec4::new(w, h, 0, 0),
        };
        let wg = abi::IMAGE_WG_SIZE;
        ctx.submit("affine", |rec| {
            rec.dispatch(
                &k,
                &[Bind::image(abi::IMAGE_AFFINE_BIND_SRC, &src), Bind::image(abi::IMAGE_AFFINE_BIND_DST, &dst)],
                bytemuck::bytes_of(&push),
                [w.div_ceil(wg), h.div_ceil(wg), 1],
            )
        })
        .unwrap();
        let got: Vec<f32> = ctx.read_image(&dst).unwrap();
        for (i, (g, s)) in got.iter().zip(&texels).enumerate() {
            let c = i % 4;
            let expect = s * push.scale[c] + push.offset[c];
            assert!((g - expect).abs() <= 1e-5 * expect.abs().max(1.0), "{w}x{h} texel {i}: {g} != {expect}");
        }
    }
    finish(ctx);
}

/// A context compiles a kernel once per source and specialisation: asking again gives the same
/// pipeline (a renderer made again compiles nothing), other constants or another source a new
/// one; the context still closes cleanly with kernels cached.
#[test]
fn kernels_are_compiled_once_per_specialisation() {
    let ctx = gpu();
    let spec = |value| [bidir::vk::Spec { id: abi::SPEC_SAMPLER, value }];
    let a = ctx.create_kernel(&kernels::SAMPLING, &spec(8)).unwrap();
    let b = ctx.create_kernel(&kernels::SAMPLING, &spec(8)).unwrap();
    let c = ctx.create_kernel(&kernels::SAMPLING, &spec(2)).unwrap();
    let d = ctx.create_kernel(&kernels::REDUCE_SUM, &[]).unwrap();
    assert!(a.same_pipeline(&b), "the same kernel and constants were compiled twice");
    assert!(!a.same_pipeline(&c), "other constants reused a pipeline");
    assert!(!a.same_pipeline(&d) && d.same_pipeline(&ctx.create_kernel(&kernels::REDUCE_SUM, &[]).unwrap()));
    // The driver's time is measured when the pipeline is built and kept with it.
    assert!(a.build_time() > std::time::Duration::ZERO && c.build_time() > std::time::Duration::ZERO);
    assert_eq!(b.build_time(), a.build_time(), "the cached kernel reports the build it came from");
    drop((a, b, c, d));
    finish(ctx);
}

#[test]
fn dispatch_rejects_wrong_bindings_push_constants_and_group_counts() {
    let ctx = gpu();
    let k = ctx.create_kernel(&kernels::REDUCE_SUM, &[]).unwrap();
    let buf = ctx.create_buffer("b", 64, Memory::Device).unwrap();
    let img = ctx.create_image("i", 4, 4, Format::R32G32B32A32_SFLOAT).unwrap();
    let push = abi::ScanPush::default();
    let missing =
        ctx.submit("missing", |rec| rec.dispatch(&k, &[Bind::buffer(abi::REDUCE_BIND_INPUT, &buf)], bytemuck::bytes_of(&push), [1, 1, 1]));
    assert!(missing.unwrap_err().to_string().contains("binding 1"), "a missing binding is named");
    let wrong = ctx.submit("wrong", |rec| {
        rec.dispatch(
            &k,
            &[Bind::buffer(abi::REDUCE_BIND_INPUT, &buf), Bind::image(abi::REDUCE_BIND_OUTPUT, &img)],
            bytemuck::bytes_of(&push),
            [1, 1, 1],
        )
    });
    assert!(wrong.unwrap_err().to_string().contains("expects"), "a wrong resource type is named");
    let short = ctx.submit("short", |rec| {
        rec.dispatch(&k, &[Bind::buffer(abi::REDUCE_BIND_INPUT, &buf), Bind::buffer(abi::REDUCE_BIND_OUTPUT, &buf)], &[0u8; 4], [1, 1, 1])
    });
    assert!(short.unwrap_err().to_string().contains("push constants"));
    let binds = [Bind::buffer(abi::REDUCE_BIND_INPUT, &buf), Bind::buffer(abi::REDUCE_BIND_OUTPUT, &buf)];
    let limit = ctx.info().max_workgroup_count;
    for axis in 0..3 {
        if limit[axis] == u32::MAX {
            eprintln!("skipped: axis {axis} allows every u32 workgroup count");
            continue;
        }
        let mut groups = [1u32; 3];
        groups[axis] = limit[axis] + 1;
        let many = ctx.submit("too many groups", |rec| rec.dispatch(&k, &binds, bytemuck::bytes_of(&push), groups));
        let err = many.unwrap_err().to_string();
        assert!(err.contains("workgroups in one dispatch"), "axis {axis}: {err}");
    }
    drop((k, buf, img));
    finish(ctx);
}

#[test]
fn timestamps_measure_gpu_work() {
    let ctx = gpu();
    let scan = Scan::new(&ctx).unwrap();
    let timer = ctx.create_timer("t", 2).unwrap();
    let data = ctx.upload_buffer("t.data", &vec![1u32; 1 << 20]).unwrap();
    let k = ctx.create_kernel(&kernels::REDUCE_SUM, &[]).unwrap();
    let out = ctx.create_buffer("t.out", 4, Memory::Device).unwrap();
    let push = abi::ScanPush { count: 1 << 20, ..Default::default() };
    ctx.submit("timed", |rec| {
        rec.reset_timer(&timer);
        rec.fill_buffer(&out, 0);
        rec.timestamp(&timer, 0);
        rec.dispatch(
            &k,
            &[Bind::buffer(abi::REDUCE_BIND_INPUT, &data), Bind::buffer(abi::REDUCE_BIND_OUTPUT, &out)],
            bytemuck::bytes_of(&push),
            [64, 1, 1],
        )?;
        rec.timestamp(&timer, 1);
        Ok(())
    })
    .unwrap();
    let ns = timer.elapsed_ns(0, 1).unwrap();
    assert!(ns > 0.0 && ns < 10e9, "elapsed {ns} ns");
    assert_eq!(ctx.read_buffer::<u32>(&out).unwrap()[0], 1 << 20);
    drop((scan, timer, data, k, out));
    finish(ctx);
}

/// Per-kernel GPU timing (what `bidir bench render` reports): every dispatch of a profiled
/// submission is timed under its kernel's name, fills apart, and nothing is recorded while
/// profiling is off.
#[test]
fn profiling_times_each_dispatch_by_kernel() {
    let ctx = gpu();
    if ctx.info().timestamp_valid_bits == 0 {
        eprintln!("skipped: {} has no timestamps", ctx.info().name);
        return;
    }
    let values: Vec<u32> = (0..100_000).collect();
    let input = ctx.upload_buffer("profile.in", &values).unwrap();
    let sum = ctx.create_buffer("profile.sum", 4, Memory::Device).unwrap();
    let k = ctx.create_kernel(&kernels::REDUCE_SUM, &[]).unwrap();
    let push = abi::ScanPush { count: 100_000, ..Default::default() };
    let binds = [Bind::buffer(abi::REDUCE_BIND_INPUT, &input), Bind::buffer(abi::REDUCE_BIND_OUTPUT, &sum)];
    let record = |rec: &mut bidir::vk::Recorder| {
        rec.fill_buffer(&sum, 0);
        for _ in 0..3 {
            rec.dispatch(&k, &binds, bytemuck::bytes_of(&push), [k.groups_for(100_000), 1, 1])?;
        }
        Ok(())
    };
    ctx.submit("unprofiled", record).unwrap();
    assert!(ctx.take_profile().0.is_empty(), "profiling is off by default");
    ctx.set_profiling(true).unwrap();
    ctx.submit("profiled", record).unwrap();
    ctx.submit("profiled again", record).unwrap();
    let (times, untimed) = ctx.take_profile();
    assert_eq!(untimed, 0);
    let names: Vec<(&str, u64)> = times.iter().map(|t| (t.name.as_str(), t.dispatches)).collect();
    assert!(names.contains(&("reduce_sum", 6)) && names.contains(&("fill", 2)) && names.len() == 2, "{names:?}");
    assert!(times.iter().all(|t| t.ns.is_finite() && t.ns >= 0.0), "{times:?}");
    assert!(times.iter().find(|t| t.name == "reduce_sum").unwrap().ns > 0.0, "{times:?}");
    assert!(ctx.take_profile().0.is_empty(), "take_profile empties the table");
    ctx.set_profiling(false).unwrap();
    ctx.submit("off again", record).unwrap();
    assert!(ctx.take_profile().0.is_empty());
    assert_eq!(ctx.read_buffer::<u32>(&sum).unwrap(), vec![(0..100_000u32).fold(0u32, |a, v| a.wrapping_add(v)) * 3]);
    drop((k, input, sum));
    finish(ctx);
}

/// `Recorder::concurrent`: independent commands recorded without barriers between them, one
/// after them all (a copy after the group reads what both wrote), profiled as one interval
/// that counts each command; many submissions in a row reuse their fences and command buffers.
#[test]
fn concurrent_commands_end_in_one_barrier_and_one_profile_interval() {
    let ctx = gpu();
    let values: Vec<u32> = (0..10_000).collect();
    let input = ctx.upload_buffer("concurrent.in", &values).unwrap();
    let [a, b] = ["concurrent.a", "concurrent.b"].map(|n| ctx.create_buffer(n, 4, Memory::Device).unwrap());
    let out = ctx.create_buffer("concurrent.out", 8, Memory::Device).unwrap();
    let k = ctx.create_kernel(&kernels::REDUCE_SUM, &[]).unwrap();
    let push = abi::ScanPush { count: 10_000, ..Default::default() };
    let sum_into = |rec: &mut bidir::vk::Recorder, sum: &bidir::vk::Buffer| {
        let binds = [Bind::buffer(abi::REDUCE_BIND_INPUT, &input), Bind::buffer(abi::REDUCE_BIND_OUTPUT, sum)];
        rec.dispatch(&k, &binds, bytemuck::bytes_of(&push), [k.groups_for(10_000), 1, 1])
    };
    let profiled = ctx.info().timestamp_valid_bits != 0;
    ctx.set_profiling(profiled).unwrap();
    let want = (0..10_000u32).sum::<u32>();
    for round in 0..20 {
        ctx.submit("concurrent", |rec| {
            rec.fill_buffer(&a, 0);
            rec.fill_buffer(&b, 0);
            rec.concurrent(|rec| {
                sum_into(rec, &a)?;
                sum_into(rec, &b)
            })?;
            rec.copy_buffer_range(&a, 0, &out, 0, 4);
            rec.copy_buffer_range(&b, 0, &out, 4, 4);
            Ok(())
        })
        .unwrap();
        assert_eq!(ctx.read_buffer::<u32>(&out).unwrap(), vec![want, want], "round {round}");
    }
    if profiled {
        let (times, _) = ctx.take_profile();
        let names: Vec<(&str, u64)> = times.iter().map(|t| (t.name.as_str(), t.dispatches)).collect();
        // (Each round's read_buffer adds a copy of its own.)
        assert!(names.contains(&("reduce_sum", 40)) && names.contains(&("fill", 40)) && names.contains(&("copy", 60)), "{names:?}");
        ctx.set_profiling(false).unwrap();
    }
    drop((k, input, a, b, out));
    finish(ctx);
}

/// Submissions queued behind one another (`Context::start`, as BDPT's passes are): each runs
/// after the one before (a copy in the second reads what the first summed), and each keeps its
/// own timestamps, so the profiled GPU time of the chain is no more than the wall time it took
/// (when the two shared the profiler's queries, the second reset the first's before they were
/// read: lavapipe then counted 690 ms of GPU time in 480 of wall).
#[test]
fn submissions_queued_behind_one_another_run_in_order_and_keep_their_profiles() {
    let ctx = gpu();
    // Three short submissions, then a long one: were the last one's timestamps read as the third's
    // too, the chain's GPU time would be about twice its wall time.
    let n = 1u32 << 22;
    let counts = [1024u32, 1024, 1024, n];
    let values: Vec<u32> = (0..n).collect();
    let input = ctx.upload_buffer("queued.in", &values).unwrap();
    let sums: Vec<_> = (0..4).map(|i| ctx.create_buffer(&format!("queued.sum{i}"), 4, Memory::Device).unwrap()).collect();
    let out = ctx.create_buffer("queued.out", 16, Memory::Device).unwrap();
    let k = ctx.create_kernel(&kernels::REDUCE_SUM, &[]).unwrap();
    let profiled = ctx.info().timestamp_valid_bits != 0;
    ctx.set_profiling(profiled).unwrap();
    // Submission i sums the input's first counts[i] values into sums[i] (four times over) and
    // copies sums[i - 1] out.
    let record = |i: usize| {
        let (k, input, sums, out) = (&k, &input, &sums, &out);
        let push = abi::ScanPush { count: counts[i], ..Default::default() };
        ctx.record("queued sum", move |rec| {
            if i > 0 {
                rec.copy_buffer_range(&sums[i - 1], 0, out, 4 * (i as u64 - 1), 4);
            }
            rec.fill_buffer(&sums[i], 0);
            let binds = [Bind::buffer(abi::REDUCE_BIND_INPUT, input), Bind::buffer(abi::REDUCE_BIND_OUTPUT, &sums[i])];
            for _ in 0..4 {
                rec.dispatch(k, &binds, bytemuck::bytes_of(&push), [k.groups_for(counts[i]), 1, 1])?;
            }
            Ok(())
        })
    };
    let start = std::time::Instant::now();
    let mut running = ctx.start(record(0).unwrap()).unwrap();
    for i in 1..4 {
        let next = ctx.start(record(i).unwrap()).unwrap();
        running.wait().unwrap();
        running = next;
    }
    running.wait().unwrap();
    let wall_ns = start.elapsed().as_nanos() as f64;
    let expected = values[..1024].iter().fold(0u32, |a, &v| a.wrapping_add(v)).wrapping_mul(4);
    assert_eq!(ctx.read_buffer::<u32>(&out).unwrap()[..3], [expected; 3]);
    if profiled {
        let (times, untimed) = ctx.take_profile();
        assert_eq!(untimed, 0);
        let names: Vec<(&str, u64)> = times.iter().map(|t| (t.name.as_str(), t.dispatches)).collect();
        // (read_buffer's copy is timed too.)
        assert!(names.contains(&("reduce_sum", 16)) && names.contains(&("fill", 4)), "{names:?}");
        let gpu_ns: f64 = times.iter().filter(|t| t.name != "copy").map(|t| t.ns).sum();
        assert!(gpu_ns > 0.0 && gpu_ns <= wall_ns, "{gpu_ns} ns of GPU time in {wall_ns} ns of wall time: {times:?}");
        // Three recordings held at once: the pool holds two, so the third is not timed; its
        // six commands (a copy, a fill, four sums) are counted apart, and its part comes back.
        let held: Vec<_> = (1..4).map(|i| record(i).unwrap()).collect();
        for r in held {
            ctx.run(r, || ()).unwrap();
        }
        let (times, untimed) = ctx.take_profile();
        let sums = times.iter().find(|t| t.name == "reduce_sum").map(|t| t.dispatches);
        assert_eq!((sums, untimed), (Some(8), 6), "{times:?}");
        ctx.run(record(1).unwrap(), || ()).unwrap();
        assert_eq!(ctx.take_profile().1, 0, "every part is free again");
        ctx.set_profiling(false).unwrap();
    }
    drop((k, input, sums, out));
    finish(ctx);
}

/// Commands recorded now and run later (`Context::record`, `Context::run`): the next submission
/// recorded while the GPU runs one, both results right; commands dropped unrun are freed; and
/// commands recorded with profiling on refuse to run once it has been switched (their
/// timestamps would go to a pool that no longer exists).
#[test]
fn recorded_commands_run_later_and_not_across_a_profiling_switch() {
    let ctx = gpu();
    let values: Vec<u32> = (0..50_000).collect();
    let input = ctx.upload_buffer("recorded.in", &values).unwrap();
    let sums =
        [ctx.create_buffer("recorded.sum0", 4, Memory::Device).unwrap(), ctx.create_buffer("recorded.sum1", 4, Memory::Device).unwrap()];
    let k = ctx.create_kernel(&kernels::REDUCE_SUM, &[]).unwrap();
    let push = abi::ScanPush { count: 50_000, ..Default::default() };
    let record = |i: usize| {
        let (k, input, sum) = (&k, &input, &sums[i]);
        ctx.record("recorded sum", move |rec| {
            rec.fill_buffer(sum, 0);
            let binds = [Bind::buffer(abi::REDUCE_BIND_INPUT, input), Bind::buffer(abi::REDUCE_BIND_OUTPUT, sum)];
            rec.dispatch(k, &binds, bytemuck::bytes_of(&push), [k.groups_for(50_000), 1, 1])
        })
    };
    let expected = (0..50_000u32).fold(0u32, |a, v| a.wrapping_add(v));
    let first = record(0).unwrap();
    let second = ctx.run(first, || record(1)).unwrap().unwrap();
    ctx.run(second, || ()).unwrap();
    for sum in &sums {
        assert_eq!(ctx.read_buffer::<u32>(sum).unwrap(), vec![expected]);
    }
    drop(record(0).unwrap()); // never run: freed
    if ctx.info().timestamp_valid_bits > 0 {
        // Off, and off then on again (a new pool).
        for again in [false, true] {
            ctx.set_profiling(true).unwrap();
            let profiled = record(0).unwrap();
            ctx.set_profiling(false).unwrap();
            ctx.set_profiling(again).unwrap();
            let err = ctx.run(profiled, || ()).err().map(|e| e.to_string()).unwrap_or_default();
            assert!(err.contains("profiling was switched"), "{err:?}");
        }
        ctx.set_profiling(false).unwrap();
    }
    drop((k, input, sums));
    finish(ctx);
}
