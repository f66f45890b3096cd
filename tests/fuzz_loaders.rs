//! A structure-aware loader fuzzer (issue 18): good scenes mutated the way a careless or
//! hostile user would break them, each loaded as `bidir info SCENE` loads it (`scene::load`,
//! then every camera validated and the derived data computed), under `catch_unwind`.
//! Asserts no panic, a bounded time per case and a bounded peak memory for the whole run.
//!
//! The mutators know the formats: OBJ/MTL statements and their numbers and indices, the glTF
//! JSON tree (numbers, indices, arrays, keys; node children that make cycles and shared
//! parents), the GLB container (magic, lengths, chunks) and image headers (PNG IHDR with a
//! valid CRC, TGA). The normal suite runs a fixed number of cases from a fixed seed (seconds);
//! `scripts/fuzz-long` runs many more from fresh seeds (BIDIR_FUZZ_CASES, BIDIR_FUZZ_SEED;
//! failing inputs are kept under BIDIR_FUZZ_KEEP or the temporary directory).

mod common;

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use bidir::scene::{self, LoadOptions};
use common::Pcg;
use serde_json::Value;

/// Longest one load may take (a debug-free release build loads these in milliseconds).
const CASE_TIME: Duration = Duration::from_secs(10);
/// Peak resident memory of the whole run (the seeds are kilobytes; a mutation that makes the
/// loader allocate from a claimed size would show here).
const PEAK_RSS_BYTES: u64 = 2 << 30;

/// Numbers a user or an attacker would try.
const NUMBERS: [&str; 20] = [
    "0",
    "-0",
    "1",
    "-1",
    "2",
    "3",
    "0.5",
    "-7",
    "255",
    "65535",
    "65536",
    "4294967295",
    "4294967296",
    "99999999999",
    "1e38",
    "3e38",
    "-3e38",
    "1e40",
    "nan",
    "inf",
];
const OBJ_KEYS: [&str; 12] = ["v", "vt", "vn", "f", "l", "p", "o", "g", "s", "usemtl", "mtllib", "vp"];
const MTL_KEYS: [&str; 14] =
    ["newmtl", "Kd", "Ke", "Ks", "Ni", "d", "Tr", "illum", "map_Kd", "map_d", "emissivity", "reflectivity", "refractivity", "IOR"];

fn seed_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data")
}

fn env_u64(key: &str, default: u64) -> u64 {
    std::env::var(key).ok().and_then(|v| v.parse().ok()).unwrap_or(default)
}

fn pick<'a, T>(rng: &mut Pcg, items: &'a [T]) -> &'a T {
    &items[rng.below(items.len() as u32) as usize]
}

/// A number, a very long one, or an index near the ends of the ranges a file uses.
fn number(rng: &mut Pcg) -> String {
    match rng.below(10) {
        0 => "9".repeat(1 + rng.below(5000) as usize),
        1 => format!("{}", rng.below(64)),
        2 => format!("-{}", rng.below(64)),
        _ => pick(rng, &NUMBERS).to_string(),
    }
}

/// Text garbage: control characters, NUL, non-UTF-8 bytes, separators.
fn garbage(rng: &mut Pcg) -> Vec<u8> {
    let pool: [&[u8]; 9] = [b"\0", b"\x1b[2J", b"\xff\xfe", b"/", b"//", b"#", b"\r", b"\t", b"\\"];
    (0..1 + rng.below(4)).flat_map(|_| pick(rng, &pool).to_vec()).collect()
}

// ---- OBJ and MTL: statements ---------------------------------------------------------

fn mutate_text(rng: &mut Pcg, text: &[u8], keys: &[&str]) -> Vec<u8> {
    let mut lines: Vec<Vec<u8>> = text.split(|&b| b == b'\n').map(<[u8]>::to_vec).collect();
    for _ in 0..1 + rng.below(4) {
        let n = lines.len() as u32;
        let at = rng.below(n) as usize;
        match rng.below(9) {
            // A number or index replaced.
            0..=2 => {
                let mut words: Vec<Vec<u8>> = lines[at].split(|&b| b == b' ').map(<[u8]>::to_vec).collect();
                let w = 1 + rng.below(words.len().max(2) as u32 - 1) as usize;
                if w < words.len() {
                    let word = String::from_utf8_lossy(&words[w]).into_owned();
                    // Face vertices: one of v/vt/vn replaced.
                    let parts: Vec<&str> = word.split('/').collect();
                    let p = rng.below(parts.len() as u32) as usize;
                    let new: Vec<String> =
                        parts.iter().enumerate().map(|(i, s)| if i == p { number(rng) } else { s.to_string() }).collect();
                    words[w] = new.join("/").into_bytes();
                }
                lines[at] = words.join(&b' ');
            }
            // The statement's keyword swapped.
            3 => {
                let rest: Vec<u8> = lines[at].iter().copied().skip_while(|&b| b != b' ').collect();
                lines[at] = [pick(rng, keys).as_bytes(), &rest].concat();
            }
            // A statement repeated, dropped, or cut short.
            4 => {
                let l = lines[at].clone();
                lines.insert(at, l);
            }
            5 => {
                lines.remove(at);
                if lines.is_empty() {
                    lines.push(Vec::new());
                }
            }
            6 => {
                let cut = rng.below(lines[at].len() as u32 + 1) as usize;
                lines[at].truncate(cut);
            }
            // Words with too few or too many arguments, or garbage.
            7 => {
                let extra = if rng.below(2) == 0 { number(rng).into_bytes() } else { garbage(rng) };
                lines[at].push(b' ');
                lines[at].extend(extra);
            }
            _ => {
                let keep = rng.below(lines.len() as u32) as usize + 1;
                lines.truncate(keep);
            }
        }
    }
    lines.join(&b'\n')
}

// ---- glTF: the JSON tree -------------------------------------------------------------

/// Every path (keys and indices) in the tree.
fn paths(v: &Value, here: &mut Vec<Value>, out: &mut Vec<Vec<Value>>) {
    out.push(here.clone());
    match v {
        Value::Object(m) => {
            for (k, c) in m {
                here.push(Value::String(k.clone()));
                paths(c, here, out);
                here.pop();
            }
        }
        Value::Array(a) => {
            for (i, c) in a.iter().enumerate() {
                here.push(Value::from(i));
                paths(c, here, out);
                here.pop();
            }
        }
        _ => {}
    }
}

fn at_path<'a>(v: &'a mut Value, path: &[Value]) -> &'a mut Value {
    path.iter().fold(v, |v, step| match step {
        Value::String(k) => &mut v[k.as_str()],
        Value::Number(i) => &mut v[i.as_u64().unwrap_or(0) as usize],
        _ => v,
    })
}

fn mutate_json(rng: &mut Pcg, doc: &mut Value) {
    for _ in 0..1 + rng.below(3) {
        let mut all = Vec::new();
        paths(doc, &mut Vec::new(), &mut all);
        let path = pick(rng, &all).clone();
        // Graph edits: shared children and cycles (the case that once took all memory).
        if rng.below(6) == 0 {
            let nodes = doc["nodes"].as_array().map_or(0, Vec::len) as u32;
            if nodes > 0 {
                let (p, c) = (rng.below(nodes) as usize, rng.below(nodes + 1) as usize);
                if let Some(n) = doc["nodes"][p].as_object_mut() {
                    let children = n.entry("children").or_insert_with(|| Value::Array(vec![]));
                    if let Some(a) = children.as_array_mut() {
                        a.push(Value::from(c));
                    }
                }
            }
            continue;
        }
        let v = at_path(doc, &path);
        match (rng.below(6), &mut *v) {
            (0..=2, Value::Number(_)) => {
                let n = number(rng);
                *v = serde_json::from_str(&n).unwrap_or(Value::String(n));
            }
            (0..=2, Value::String(s)) => {
                let choices = ["SCALAR", "VEC2", "VEC3", "VEC4", "MAT4", "image/png", "data:,", "../x.bin", ""];
                *s = pick(rng, &choices).to_string();
            }
            (3, Value::Array(a)) if !a.is_empty() => {
                let i = rng.below(a.len() as u32) as usize;
                if rng.below(2) == 0 {
                    a.remove(i);
                } else {
                    let e = a[i].clone();
                    a.insert(i, e);
                }
            }
            (4, Value::Object(m)) if !m.is_empty() => {
                let keys: Vec<String> = m.keys().cloned().collect();
                m.remove(pick(rng, &keys));
            }
            _ => *v = pick(rng, &[Value::Null, Value::from(-1), Value::from(1u64 << 40), Value::Array(vec![])]).clone(),
        }
    }
}

// ---- GLB: the container --------------------------------------------------------------

/// `glTF` header + JSON chunk (+ BIN chunk), with its lengths consistent.
fn glb(json: &[u8], bin: Option<&[u8]>) -> Vec<u8> {
    let pad = |b: &[u8], with: u8| {
        let mut v = b.to_vec();
        while v.len() % 4 != 0 {
            v.push(with);
        }
        v
    };
    let (json, bin) = (pad(json, b' '), bin.map(|b| pad(b, 0)));
    let total = 12 + 8 + json.len() + bin.as_ref().map_or(0, |b| 8 + b.len());
    let mut out = b"glTF".to_vec();
    out.extend(2u32.to_le_bytes());
    out.extend((total as u32).to_le_bytes());
    out.extend((json.len() as u32).to_le_bytes());
    out.extend(b"JSON");
    out.extend(&json);
    if let Some(b) = bin {
        out.extend((b.len() as u32).to_le_bytes());
        out.extend(b"BIN\0");
        out.extend(&b);
    }
    out
}

/// The JSON and BIN chunks of a well-formed GLB.
fn glb_chunks(bytes: &[u8]) -> (Vec<u8>, Option<Vec<u8>>) {
    let len = |at: usize| u32::from_le_bytes(bytes[at..at + 4].try_into().unwrap()) as usize;
    let j = len(12);
    let json = bytes[20..20 + j].to_vec();
    let bin = (bytes.len() > 28 + j).then(|| bytes[28 + j..28 + j + len(20 + j)].to_vec());
    (json, bin)
}

fn mutate_glb(rng: &mut Pcg, seed: &[u8]) -> Vec<u8> {
    let (json, bin) = glb_chunks(seed);
    let mut doc: Value = serde_json::from_slice(&json).expect("seed GLB JSON");
    if rng.below(2) == 0 {
        mutate_json(rng, &mut doc);
    }
    let mut bin = bin;
    if rng.below(4) == 0 {
        if let Some(b) = &mut bin {
            let cut = rng.below(b.len() as u32 + 1) as usize;
            b.truncate(cut);
        }
    }
    let mut out = glb(&serde_json::to_vec(&doc).unwrap(), bin.as_deref());
    // Header and chunk fields: magic, version, total length, chunk lengths and types.
    if rng.below(2) == 0 {
        let json_len = u32::from_le_bytes(out[12..16].try_into().unwrap()) as usize;
        let fields = [0usize, 4, 8, 12, 16, 20 + json_len, 24 + json_len];
        let at = *pick(rng, &fields);
        if at + 4 <= out.len() {
            let values = [0u32, 1, 3, 0xffff_ffff, 0x8000_0000, out.len() as u32 + 4, 0x4e4f534a, 0x004e4942];
            out[at..at + 4].copy_from_slice(&pick(rng, &values).to_le_bytes());
        }
    }
    if rng.below(8) == 0 {
        let cut = rng.below(out.len() as u32) as usize;
        out.truncate(cut);
    }
    out
}

// ---- image headers -----------------------------------------------------------------

fn crc32(bytes: &[u8]) -> u32 {
    let mut c = 0xffff_ffffu32;
    for &b in bytes {
        c ^= b as u32;
        for _ in 0..8 {
            c = if c & 1 != 0 { 0xedb8_8320 ^ (c >> 1) } else { c >> 1 };
        }
    }
    !c
}

/// PNG: IHDR fields (size, depth, colour type, interlace) changed and its CRC recomputed, or
/// the data cut; TGA: header fields changed.
fn mutate_image(rng: &mut Pcg, seed: &[u8], png: bool) -> Vec<u8> {
    let mut out = seed.to_vec();
    let dims = [0u32, 1, 2, 16384, 65535, 100_000, 0x7fff_ffff, 0xffff_ffff];
    if png && out.len() >= 33 {
        match rng.below(4) {
            0 => out[16..20].copy_from_slice(&pick(rng, &dims).to_be_bytes()),
            1 => out[20..24].copy_from_slice(&pick(rng, &dims).to_be_bytes()),
            2 => out[24 + rng.below(5) as usize] = *pick(rng, &[0u8, 1, 3, 4, 6, 16, 255]),
            _ => {
                let cut = 33 + rng.below(out.len() as u32 - 33) as usize;
                out.truncate(cut);
            }
        }
        let crc = crc32(&out[12..29]);
        out[29..33].copy_from_slice(&crc.to_be_bytes());
    } else if out.len() >= 18 {
        let at = *pick(rng, &[2usize, 12, 14, 16, 17]);
        let v = (*pick(rng, &dims) as u16).to_le_bytes();
        out[at] = v[0];
        if at == 12 || at == 14 {
            out[at + 1] = v[1];
        }
    }
    out
}

// ---- the driver ----------------------------------------------------------------------

/// What `bidir info` does with a loaded scene (cameras, emitters, bounds, sizes).
fn as_info_does(path: &Path, strict: bool) -> Result<(), String> {
    let l = scene::load(path, &LoadOptions { strict }).map_err(|e| e.to_string())?;
    let s = &l.scene;
    for c in &s.cameras {
        let _ = c.validate();
    }
    let _ = (s.emitters().len(), s.total_emitted_power(), s.bounds(), s.material_counts());
    let _ = (s.texture_bytes(), s.gpu_bytes_estimate().total(), s.features());
    Ok(())
}

/// Peak resident set of this process (Linux), if known.
fn peak_rss() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let kb: u64 = status.lines().find_map(|l| l.strip_prefix("VmHWM:"))?.trim().trim_end_matches(" kB").trim().parse().ok()?;
    Some(kb * 1024)
}

#[test]
fn structure_aware_loader_fuzz() {
    let cases = env_u64("BIDIR_FUZZ_CASES", 200);
    let seed = env_u64("BIDIR_FUZZ_SEED", 18);
    let dir = std::env::temp_dir().join(format!("bidir-fuzz-{}-{seed}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let keep = std::env::var_os("BIDIR_FUZZ_KEEP").map_or_else(|| dir.join("findings"), PathBuf::from);
    let d = seed_dir();
    let read = |p: &str| std::fs::read(d.join(p)).unwrap();
    let (obj, mtl) = (read("room/room.obj"), read("room/room.mtl"));
    let (tga, leaf, mask) = (read("room/floor_d.tga"), read("room/leaf.png"), read("room/mask_grey.png"));
    let (gltf_json, glb_bytes, bin) = (read("gltf/instanced.gltf"), read("gltf/instanced.glb"), read("gltf/instanced.bin"));
    let mut gltf_doc: Value = serde_json::from_slice(&gltf_json).unwrap();
    // A clear coat on the mirror, with both textures and a normal texture, so that mutations
    // reach KHR_materials_clearcoat's reading (material.rs reads its JSON by hand).
    gltf_doc["materials"][0]["extensions"] = serde_json::json!({"KHR_materials_clearcoat": {
        "clearcoatFactor": 0.8, "clearcoatTexture": {"index": 0}, "clearcoatRoughnessFactor": 0.2,
        "clearcoatRoughnessTexture": {"index": 0}, "clearcoatNormalTexture": {"index": 0}}});
    gltf_doc["extensionsUsed"].as_array_mut().unwrap().push("KHR_materials_clearcoat".into());

    let mut rng = Pcg::new(seed);
    let mut findings = Vec::new();
    let (mut loaded, mut refused, mut slowest) = (0u64, 0u64, Duration::ZERO);
    let start = Instant::now();
    for case in 0..cases {
        // The unmutated companions, then one target mutated.
        let files: Vec<(&str, Vec<u8>)> = vec![
            ("room.obj", obj.clone()),
            ("room.mtl", mtl.clone()),
            ("floor_d.tga", tga.clone()),
            ("leaf.png", leaf.clone()),
            ("mask_grey.png", mask.clone()),
            ("instanced.bin", bin.clone()),
        ];
        for (name, bytes) in &files {
            std::fs::write(dir.join(name), bytes).unwrap();
        }
        let kind = rng.below(7);
        let (name, bytes, target) = match kind {
            0 => ("room.obj", mutate_text(&mut rng, &obj, &OBJ_KEYS), "room.obj"),
            1 => ("room.mtl", mutate_text(&mut rng, &mtl, &MTL_KEYS), "room.obj"),
            2 | 3 => {
                let mut doc = gltf_doc.clone();
                mutate_json(&mut rng, &mut doc);
                ("instanced.gltf", serde_json::to_vec_pretty(&doc).unwrap(), "instanced.gltf")
            }
            4 => ("instanced.glb", mutate_glb(&mut rng, &glb_bytes), "instanced.glb"),
            5 => ("floor_d.tga", mutate_image(&mut rng, &tga, false), "room.obj"),
            _ => {
                let (n, seed) = if rng.below(2) == 0 { ("leaf.png", &leaf) } else { ("mask_grey.png", &mask) };
                (n, mutate_image(&mut rng, seed, true), "room.obj")
            }
        };
        std::fs::write(dir.join(name), &bytes).unwrap();
        for strict in [false, true] {
            let t = Instant::now();
            let r = std::panic::catch_unwind(|| as_info_does(&dir.join(target), strict));
            let took = t.elapsed();
            slowest = slowest.max(took);
            let problem = match &r {
                Err(_) => Some("panicked".to_owned()),
                Ok(_) if took > CASE_TIME => Some(format!("took {took:?}")),
                Ok(Ok(())) => {
                    loaded += 1;
                    None
                }
                Ok(Err(msg)) => {
                    refused += 1;
                    // Messages are printable: escaped, truncated.
                    (msg.chars().any(|c| c.is_control() && c != '\n') || msg.len() > 8192)
                        .then(|| format!("unprintable message: {:?}", &msg[..msg.len().min(200)]))
                }
            };
            if let Some(p) = problem {
                std::fs::create_dir_all(&keep).unwrap();
                let kept = keep.join(format!("seed{seed}-case{case}-{name}"));
                std::fs::write(&kept, &bytes).unwrap();
                findings.push(format!("{} (strict {strict}): {p}", kept.display()));
            }
        }
    }
    let rss = peak_rss();
    println!(
        "fuzz: seed {seed}, {cases} cases x 2 in {:.1} s: {loaded} loaded, {refused} refused, slowest {slowest:?}, peak RSS {} MiB, {} findings",
        start.elapsed().as_secs_f64(),
        rss.map_or(0, |b| b >> 20),
        findings.len()
    );
    std::fs::remove_dir_all(&dir).ok();
    assert!(findings.is_empty(), "findings (inputs kept):\n{}", findings.join("\n"));
    assert!(rss.is_none_or(|b| b < PEAK_RSS_BYTES), "peak RSS {} MiB", rss.unwrap_or(0) >> 20);
    // The mutators must leave many inputs loadable, or they only test the first parse error.
    assert!(loaded > cases / 10 && refused > cases / 10, "{loaded} loaded, {refused} refused");
}
