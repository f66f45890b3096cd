//! Bad input through the `bidir` binary (issue 18): each case exits non-zero with a message
//! naming the flag or file and the cause, never panics, writes no output and leaves an
//! existing output untouched. The last tests render on the GPU (lavapipe) and stop them with
//! SIGINT.

use bidir::imaging::{write_image, RgbImage};
use std::io::{BufRead, BufReader};
use std::os::unix::process::ExitStatusExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant};

fn data(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/bad").join(name).display().to_string()
}

/// A scratch directory of this test's own, empty.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("bidir-cli-bad-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The binary under test; BIDIR_TEST_BIN runs these cases against another build (e.g. an
/// older one, to see them fail).
fn bidir(args: &[&str]) -> Command {
    let bin = std::env::var_os("BIDIR_TEST_BIN").unwrap_or_else(|| env!("CARGO_BIN_EXE_bidir").into());
    let mut c = Command::new(bin);
    c.args(args).env("BIDIR_VALIDATION", "1").env_remove("BIDIR_GPU_TIMEOUT_S");
    c
}

/// Runs the binary and expects exit status 1 with an `error:` line containing every one of
/// `words`, no panic and no raw control characters; returns stderr.
fn fails(args: &[&str], words: &[&str]) -> String {
    let out = bidir(args).output().expect("bidir runs");
    check_failure(args, &out, words)
}

fn check_failure(args: &[&str], out: &Output, words: &[&str]) -> String {
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(1), "{args:?}: {:?}\n{err}", out.status);
    assert!(!err.contains("panicked"), "{args:?} panicked:\n{err}");
    assert!(!err.chars().any(|c| c.is_control() && c != '\n'), "{args:?}: control characters in {err:?}");
    let line = err.lines().find(|l| l.starts_with("error: ")).unwrap_or_else(|| panic!("{args:?}: no error line in:\n{err}"));
    for w in words {
        assert!(line.contains(w), "{args:?}: expected '{w}' in: {line}");
    }
    err
}

/// A file's bytes and modification time, to show it was not touched.
fn snapshot(p: &Path) -> (Vec<u8>, std::time::SystemTime) {
    (std::fs::read(p).unwrap(), std::fs::metadata(p).unwrap().modified().unwrap())
}

/// Files in `dir` other than `keep`.
fn others(dir: &Path, keep: &[&Path]) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).filter(|p| !keep.contains(&p.as_path())).collect();
    v.sort();
    v
}

/// A 1x1 EXR whose header claims `w` x `h` pixels (data and display windows patched).
fn exr_claiming(path: &Path, w: i32, h: i32) {
    write_image(path, &RgbImage::new(1, 1), 0.0).unwrap();
    let mut bytes = std::fs::read(path).unwrap();
    let mut patched = 0;
    for name in [&b"dataWindow\0box2i\0"[..], &b"displayWindow\0box2i\0"[..]] {
        let at = bytes.windows(name.len()).position(|x| x == name).expect("window attribute") + name.len() + 4;
        bytes[at + 8..at + 12].copy_from_slice(&(w - 1).to_le_bytes());
        bytes[at + 12..at + 16].copy_from_slice(&(h - 1).to_le_bytes());
        patched += 1;
    }
    assert_eq!(patched, 2);
    std::fs::write(path, bytes).unwrap();
}

#[test]
fn exr_header_too_large_is_refused_before_allocating() {
    let dir = scratch("exr");
    let big = dir.join("big.exr");
    exr_claiming(&big, 100_000, 100_000);
    let b = big.to_str().unwrap();
    fails(&["diff", b, b], &[b, "EXR too large", "100000x100000", "limit"]);
    let out = dir.join("out.exr");
    std::fs::write(&out, b"keep").unwrap();
    let o = out.to_str().unwrap();
    fails(&["render", "--reference", b, "--width", "8", "--height", "8", "--spp", "1", "-o", o], &["EXR too large"]);
    assert_eq!(std::fs::read(&out).unwrap(), b"keep");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn diff_blocks_zero() {
    let dir = scratch("blocks");
    let a = dir.join("a.exr");
    write_image(&a, &RgbImage::new(4, 4), 0.0).unwrap();
    let a = a.to_str().unwrap();
    fails(&["diff", a, a, "--blocks", "0"], &["--blocks must be at least 1"]);
    fails(&["diff", a, a, "--below", "nan"], &["--below must be a finite number"]);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn non_finite_pixels_are_counted_and_left_out() {
    let dir = scratch("nan");
    let mut img = RgbImage::new(2, 2);
    img.data.fill(0.5);
    let b = dir.join("b.exr");
    write_image(&b, &img, 0.0).unwrap();
    img.data[0] = f32::NAN;
    img.data[4] = f32::INFINITY;
    img.data[6..9].fill(1.0);
    let a = dir.join("a.exr");
    write_image(&a, &img, 0.0).unwrap();
    let out = bidir(&["diff", a.to_str().unwrap(), b.to_str().unwrap()]).output().unwrap();
    let (stdout, stderr) = (String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success(), "{stderr}");
    assert!(stderr.contains("a.exr: 2 of 4 pixels are NaN or infinite"), "{stderr}");
    // Over the two finite pixels: one equal, one off by 0.5 in each channel.
    let rmse: f64 = stdout.lines().find_map(|l| l.strip_prefix("RMSE")).unwrap().trim().parse().unwrap();
    assert!((rmse - 0.5f64.sqrt() * 0.5).abs() < 1e-5, "{stdout}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn closed_pipe_ends_quietly() {
    // The reader goes away before bidir writes a line (`bidir info ... | head -0`).
    let mut child = bidir(&["info", "--builtin"]).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!err.contains("panicked") && !err.contains("Broken pipe"), "{err}");
    assert!(out.status.success() || out.status.signal() == Some(libc::SIGPIPE), "{:?}: {err}", out.status);
}

#[test]
fn reference_size_is_checked_before_rendering() {
    let dir = scratch("refsize");
    let reference = dir.join("ref.exr");
    write_image(&reference, &RgbImage::new(8, 8), 0.0).unwrap();
    let out = dir.join("out.exr");
    write_image(&out, &RgbImage::new(3, 3), 0.0).unwrap();
    let before = snapshot(&out);
    let (r, o) = (reference.to_str().unwrap(), out.to_str().unwrap());
    fails(&["render", "--reference", r, "--width", "16", "--height", "16", "-o", o], &["--reference", "8x8", "16x16", "--width/--height"]);
    assert_eq!(snapshot(&out), before);
    assert_eq!(others(&dir, &[&reference, &out]), Vec::<PathBuf>::new());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn every_output_is_checked_before_rendering() {
    let dir = scratch("outputs");
    let out = dir.join("out.exr");
    std::fs::write(&out, b"keep").unwrap();
    let before = snapshot(&out);
    let o = out.to_str().unwrap();
    fails(&["render", "--spp", "1", "-o", o, "-o", "/missing/dir/x.png"], &["/missing/dir/x.png", "directory /missing/dir does not exist"]);
    fails(&["render", "--spp", "1", "-o", o, "-o", dir.to_str().unwrap()], &["output must end in .exr or .png"]);
    let sub = dir.join("d.png");
    std::fs::create_dir(&sub).unwrap();
    fails(&["render", "--spp", "1", "-o", o, "-o", sub.to_str().unwrap()], &["d.png", "is a directory"]);
    fails(&["render", "--spp", "1", "-o", o, "-o", o], &["given twice"]);
    assert_eq!(snapshot(&out), before);
    assert_eq!(others(&dir, &[&out, &sub]), Vec::<PathBuf>::new());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn numbers_out_of_range_are_rejected_with_the_flag() {
    fails(&["render", "--exposure", "nan", "--spp", "1"], &["--exposure NaN", "finite"]);
    fails(&["view", "--exposure", "inf", "--frames", "1"], &["--exposure inf", "finite"]);
    fails(&["info", "--builtin", "--fov", "-10"], &["--fov -10: must be in (0, 180)"]);
    fails(&["info", "--builtin", "--fov", "180"], &["--fov 180: must be in (0, 180)"]);
    fails(&["render", "--time", "-1"], &["--time -1: must be a positive number of seconds"]);
    fails(&["render", "--integrator", "bdpt", "--mis", "veach", "--spp", "1"], &["--mis veach: auto | balance | power"]);
    fails(
        &["render", "--integrator", "bdpt", "--connection-candidates", "0", "--spp", "1"],
        &["--connection-candidates 0: a whole number from 1 to 32"],
    );
    fails(
        &["render", "--integrator", "bdpt:full", "--connection-candidates", "4", "--spp", "1"],
        &["--connection-candidates", "not bdpt:full's"],
    );
    fails(
        &["render", "--integrator", "pt-nee", "--connection-candidates", "2", "--spp", "1"],
        &["--connection-candidates", "not pt-nee's"],
    );
    fails(&["render", "--integrator", "bdpt", "--light-path-len", "0", "--spp", "1"], &["--light-path-len must be at least 1"]);
    fails(&["bench", "render", "--spp", "0"], &["--spp and --runs must be at least 1", "--spp 0"]);
    fails(&["bench", "render", "--runs", "0"], &["--spp and --runs must be at least 1", "--runs 0"]);
    fails(&["bench", "traversal", "--leaf-size", "99"], &["--leaf-size 99: must be in 1..=16"]);
    fails(&["bench", "traversal", "--bvh", "cwbvh", "--leaf-size", "4"], &["--leaf-size 4: must be in 1..=3"]);
    fails(&["bench", "traversal", "--bvh", "cwbvh", "--short-stack"], &["--short-stack: only with the binary layouts"]);
    fails(&["bench", "traversal", "--rays-per-invocation", "0"], &["--rays-per-invocation 0: must be in 1..=64"]);
    fails(&["bench", "traversal", "--workgroup-size", "96"], &["--workgroup-size 96"]);
    fails(&["bench", "traversal", "--workgroup-size", "128", "--bvh", "bvh2q"], &["--workgroup-size 128", "only with --bvh bvh2"]);
    fails(&["bench", "traversal", "--rays-per-invocation", "2", "--persistent"], &["--rays-per-invocation 2", "1 with --persistent"]);
    fails(&["bench", "traversal", "--driver-rt", "--alpha"], &["--driver-rt", "leave out --alpha"]);
    fails(&["bench", "traversal", "--ploc", "7,0"], &["--ploc", "DISTANCE one of 1, 2, 6, 14, 24, 32"]);
    fails(&["bench", "traversal", "--ploc", "6"], &["--ploc", "expected DISTANCE,DEPTH"]);
    fails(&["bench", "traversal", "--ploc", "6,0", "--quality", "5"], &["--ploc", "quality 5 builds its own candidates"]);
    fails(
        &["info", "--builtin", "--width", "100000", "--height", "100000"],
        &["100000x100000", "limit of 134,217,728 pixels", "--width/--height"],
    );
    // clap's own error (exit 2) for a value the parser refuses, naming the flag.
    let out = bidir(&["info", "--builtin", "--quad-light", "0,0,0;1,0,0;0,1,0;3e38,3e38,3e38"]).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("--quad-light") && err.contains("radiance 3e38 is too large"), "{err}");
}

#[test]
fn gltf_cameras_name_the_file_and_camera() {
    let huge = data("gltf_camera_aspect_huge.gltf");
    fails(&["info", &huge], &[&huge, "camera 'CamNode'", "1080000000x1080", "--width/--height"]);
    // The flags that fix it are accepted.
    let out = bidir(&["info", &huge, "--width", "640", "--height", "480"]).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let yfov = data("gltf_camera_yfov_zero.gltf");
    fails(&["info", &yfov], &[&yfov, "camera 'CamNode'", "field of view 0", "--fov"]);
    let zero = data("gltf_camera_aspect_zero.gltf");
    let out = bidir(&["info", &zero]).output().unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success() && stdout.contains("aspect ratio 0 is not positive"), "{stdout}");
}

#[test]
fn bad_environment_is_warned_about() {
    let out = bidir(&["info", "--builtin"]).env("BIDIR_GPU_TIMEOUT_S", "abc").output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    assert!(err.contains("warning: BIDIR_GPU_TIMEOUT_S=abc is not a number of seconds"), "{err}");
}

#[test]
fn the_os_reason_is_said_once() {
    let dir = scratch("isdir");
    let d = dir.join("scene.obj");
    std::fs::create_dir(&d).unwrap();
    let err = fails(&["info", d.to_str().unwrap()], &["scene.obj", "cannot read"]);
    assert_eq!(err.matches("Is a directory").count(), 1, "{err}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn untrusted_text_is_escaped_and_truncated() {
    let err = fails(&["info", &data("obj_control_chars.obj")], &["obj_control_chars.mtl:2", "\\u{1b}[2J", "is not a number"]);
    assert!(!err.contains('\u{1b}') && !err.contains('\0'), "{err:?}");
    let err = fails(&["info", &data("obj_long_number.obj")], &["obj_long_number.mtl:2", "(60000 characters)"]);
    assert!(err.len() < 400, "{} bytes: {err}", err.len());
}

/// Paths in messages are shown whole however deep they are (the CLI's last escaping pass once
/// cut every word past 64 characters, paths among them), with control characters escaped.
#[test]
fn long_paths_are_shown_whole() {
    let dir = scratch(&format!("deep-{}", "d".repeat(90)));
    std::fs::create_dir_all(&dir).unwrap();
    let obj = dir.join("scene.obj");
    std::fs::write(&obj, "mtllib gone\u{7}.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    let missing = format!("{}/gone\\u{{7}}.mtl", dir.display());
    let err = fails(&["info", "--strict", obj.to_str().unwrap()], &["scene.obj:1: material library", &missing]);
    assert!(!err.contains('\u{7}') && !err.contains("characters)"), "{err:?}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn gltf_two_parents_and_bad_glb_magic() {
    fails(&["info", &data("gltf_two_parents.gltf")], &["node 1 \"Shared\": has two parents"]);
    fails(&["info", &data("glb_bad_magic.glb")], &["not a GLB file (magic"]);
    fails(&["info", &data("obj_huge_ke.obj")], &["material 'lamp'", "too large"]);
}

// ---- on the GPU --------------------------------------------------------------------------

/// `bench traversal --driver-rt` on a device without the driver's ray tracing (lavapipe):
/// an error naming the extension and the flag, before any report is written; on a device
/// with it, the yardstick's rows.
#[test]
fn driver_rt_needs_the_extension() {
    let json = scratch("driver_rt").join("report.json");
    let json_arg = json.to_string_lossy().into_owned();
    let args = [
        "bench",
        "traversal",
        "--driver-rt",
        "--rays",
        "primary",
        "--warmup",
        "0",
        "--reps",
        "5",
        "--width",
        "32",
        "--height",
        "32",
        "--json",
        &json_arg,
    ];
    let out = bidir(&args).output().expect("bidir runs");
    if out.status.success() {
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(text.contains("driver's ray-tracing pipeline") && text.contains("agree %"), "{text}");
        assert!(json.exists());
        return;
    }
    check_failure(&args, &out, &["VK_KHR_ray_tracing_pipeline", "--driver-rt"]);
    assert!(!json.exists(), "no report is written when the yardstick cannot run");
}

#[test]
fn gpu_memory_errors_name_the_flags() {
    fails(
        &["render", "--width", "512", "--height", "512", "--sample-slices", "100000", "--spp", "1", "-o", "/tmp/never.exr"],
        &["sample slices", "--sample-slices", "--width/--height"],
    );
    assert!(!Path::new("/tmp/never.exr").exists());
}

/// Starts a render and waits until it says it is rendering; returns the child and its stderr
/// so far (stderr keeps being collected by a thread).
fn start_render(args: &[&str]) -> (Child, std::sync::mpsc::Receiver<String>) {
    let mut child = bidir(args).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().unwrap();
    let stderr = child.stderr.take().unwrap();
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        for line in BufReader::new(stderr).lines().map_while(Result::ok) {
            let _ = tx.send(line);
        }
    });
    (child, rx)
}

/// Waits for a stderr line containing `what`; returns every line seen.
fn wait_for(rx: &std::sync::mpsc::Receiver<String>, what: &str, seen: &mut Vec<String>) {
    let deadline = Instant::now() + Duration::from_secs(120);
    while Instant::now() < deadline {
        if let Ok(l) = rx.recv_timeout(Duration::from_millis(100)) {
            let hit = l.contains(what);
            seen.push(l);
            if hit {
                return;
            }
        }
    }
    panic!("no '{what}' on stderr: {seen:?}");
}

fn sigint(child: &Child) {
    let ok = Command::new("kill").args(["-INT", &child.id().to_string()]).status().unwrap().success();
    assert!(ok, "kill -INT failed");
}

fn wait(child: &mut Child, limit: Duration) -> std::process::ExitStatus {
    let deadline = Instant::now() + limit;
    loop {
        if let Some(s) = child.try_wait().unwrap() {
            return s;
        }
        if Instant::now() > deadline {
            let _ = child.kill();
            panic!("bidir did not exit within {limit:?} of SIGINT");
        }
        std::thread::sleep(Duration::from_millis(50));
    }
}

#[test]
fn first_ctrl_c_writes_what_was_rendered() {
    let dir = scratch("sigint1");
    let (exr, png) = (dir.join("out.exr"), dir.join("out.png"));
    let args = ["render", "--width", "32", "--height", "32", "--time", "600", "-o", exr.to_str().unwrap(), "-o", png.to_str().unwrap()];
    let (mut child, rx) = start_render(&args);
    let mut seen = Vec::new();
    wait_for(&rx, "rendering 32x32", &mut seen);
    std::thread::sleep(Duration::from_millis(1500));
    sigint(&child);
    let status = wait(&mut child, Duration::from_secs(60));
    seen.extend(rx.try_iter());
    let mut stdout = String::new();
    std::io::Read::read_to_string(&mut child.stdout.take().unwrap(), &mut stdout).unwrap();
    assert!(status.success(), "{status:?}: {seen:?}");
    assert!(seen.iter().any(|l| l.starts_with("interrupted: writing the ")), "{seen:?}");
    let img = bidir::imaging::read_exr(&exr).unwrap();
    assert_eq!((img.width, img.height), (32, 32));
    assert!(img.mean()[0] > 0.0, "the Cornell box is not black");
    assert!(stdout.contains("wrote") && png.exists(), "{stdout}");
    assert_eq!(others(&dir, &[&exr, &png]), Vec::<PathBuf>::new(), "temporary files left");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn second_ctrl_c_aborts_with_nothing_written() {
    let dir = scratch("sigint2");
    let out = dir.join("out.exr");
    std::fs::write(&out, b"keep").unwrap();
    // BDPT at 256x256: a pass (one sample) takes long on lavapipe, so the second SIGINT comes
    // while the first pass is still running.
    let args = ["render", "--integrator", "bdpt", "--width", "256", "--height", "256", "--spp", "100000", "-o", out.to_str().unwrap()];
    let (mut child, rx) = start_render(&args);
    let mut seen = Vec::new();
    wait_for(&rx, "rendering 256x256", &mut seen);
    sigint(&child);
    wait_for(&rx, "interrupted: finishing the current pass", &mut seen);
    sigint(&child);
    let status = wait(&mut child, Duration::from_secs(30));
    seen.extend(rx.try_iter());
    assert_eq!(status.code(), Some(130), "{seen:?}");
    assert!(seen.iter().any(|l| l.starts_with("aborted: nothing written")), "{seen:?}");
    assert_eq!(std::fs::read(&out).unwrap(), b"keep");
    assert_eq!(others(&dir, &[&out]), Vec::<PathBuf>::new(), "temporary files left");
    std::fs::remove_dir_all(&dir).ok();
}
