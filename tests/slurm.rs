//! A render farm on Slurm, on this machine: `scripts/slurm-local` starts a single-node Slurm
//! (slurmctld + slurmd, authenticated by munge), `scripts/slurm-render` submits the Cornell
//! box as 4 array tasks (sample ranges) and a dependent merge job; the merged image must equal
//! one render of all the samples (every pixel within 1e-5 relative). Skipped, with a message,
//! where Slurm cannot start (not installed, no permission).

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Stops the daemons `slurm-local` started, whatever happens to the test.
struct Cluster(PathBuf);
impl Drop for Cluster {
    fn drop(&mut self) {
        let _ = Command::new(root().join("scripts/slurm-local")).arg("stop").arg(&self.0).status();
    }
}

#[test]
fn slurm_array_and_merge() {
    let dir = std::env::temp_dir().join(format!("bidir-slurm-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let start = Instant::now();
    let port = 20000 + (std::process::id() % 10000) * 2;
    let up = Command::new(root().join("scripts/slurm-local"))
        .arg("start")
        .arg(dir.join("cluster"))
        .env("BIDIR_SLURM_PORT", port.to_string())
        .output()
        .unwrap();
    let cluster = Cluster(dir.join("cluster"));
    if !up.status.success() {
        eprintln!("SKIPPED: a local Slurm could not start here: {}", String::from_utf8_lossy(&up.stderr).trim());
        return;
    }
    let conf = dir.join("cluster/slurm.conf");
    let bidir = env!("CARGO_BIN_EXE_bidir");
    let out = dir.join("farm");
    let args = ["--width", "24", "--height", "16", "--seed", "9"];
    let submit = Command::new(root().join("scripts/slurm-render"))
        .args(["--tasks", "4", "--spp", "12", "--bidir", bidir, "--out"])
        .arg(&out)
        .arg("--")
        .args(args)
        .env("SLURM_CONF", &conf)
        .env("BIDIR_VALIDATION", "1")
        .output()
        .unwrap();
    let said = String::from_utf8_lossy(&submit.stdout).into_owned() + &String::from_utf8_lossy(&submit.stderr);
    assert!(submit.status.success(), "slurm-render failed: {said}");
    eprintln!("{said}");
    let merged = out.join("merged.exr");
    let deadline = Instant::now() + Duration::from_secs(300);
    while !merged.exists() {
        assert!(Instant::now() < deadline, "no merged image after 300 s; logs in {}", out.join("logs").display());
        std::thread::sleep(Duration::from_millis(200));
    }
    let wall = start.elapsed();
    // The merged image is renamed into place before the job ends; Slurm writes the job's log
    // as it ends, so an empty log here is a log not yet written (seen once in CI), not a failure.
    let read_merge_log = || std::fs::read_to_string(out.join("logs/merge.log")).unwrap_or_default();
    let mut merge_log = read_merge_log();
    while !merge_log.contains("merged 4 parts") && Instant::now() < deadline {
        std::thread::sleep(Duration::from_millis(200));
        merge_log = read_merge_log();
    }
    eprintln!("Slurm: 4 array tasks + merge in {:.2} s wall (cluster start included)\n{merge_log}", wall.as_secs_f64());
    assert!(merge_log.contains("merged 4 parts") && merge_log.contains("samples 0..12 (12 spp)"), "{merge_log}");
    for i in 0..4 {
        let log = std::fs::read_to_string(out.join(format!("logs/part-{i}.log"))).unwrap_or_default();
        assert!(!log.to_lowercase().contains("validation"), "task {i}: {log}");
    }
    // The same render in one go.
    let whole = dir.join("whole.exr");
    let one = Command::new(bidir).arg("render").args(args).args(["--spp", "12", "-o"]).arg(&whole).output().unwrap();
    assert!(one.status.success(), "{}", String::from_utf8_lossy(&one.stderr));
    same(&merged, &whole);
    drop(cluster);
    let _ = std::fs::remove_dir_all(&dir);
}

fn same(a: &Path, b: &Path) {
    let (a, b) = (bidir::imaging::read_exr(a).unwrap(), bidir::imaging::read_exr(b).unwrap());
    assert_eq!((a.width, a.height), (b.width, b.height));
    for (x, y) in a.data.iter().zip(&b.data) {
        assert!((x - y).abs() <= 1e-5 * x.abs().max(y.abs()), "{x} vs {y}");
    }
    assert!(a.mean()[0] > 0.0);
}
