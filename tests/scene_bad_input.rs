//! Bad scene files (tests/data/bad/, written for these tests; the binary ones by
//! tests/data/make_data.py): each must be a `SceneError` naming the file and the line (OBJ,
//! MTL) or element (glTF), and none may panic.

mod common;

use std::path::{Path, PathBuf};

use bidir::scene::{self, LoadOptions, SceneError};

fn bad(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/bad").join(name)
}

fn load(name: &str, strict: bool) -> Result<scene::Loaded, SceneError> {
    scene::load(&bad(name), &LoadOptions { strict })
}

fn error(name: &str) -> SceneError {
    match load(name, false) {
        Ok(l) => panic!("{name} loaded ({} triangles, warnings {:?})", l.scene.triangles.len(), l.warnings),
        Err(e) => e,
    }
}

/// The message starts with `<path>:<line>: ` and contains every one of `words`.
fn assert_line(e: &SceneError, file: &str, line: usize, words: &[&str]) {
    let msg = e.to_string();
    let want = format!("{}:{line}: ", bad(file).display());
    assert!(msg.starts_with(&want), "expected '{want}...', got: {msg}");
    assert_eq!(e.line(), Some(line), "{msg}");
    assert_eq!(e.file(), Some(bad(file).as_path()), "{msg}");
    for w in words {
        assert!(msg.contains(w), "expected '{w}' in: {msg}");
    }
}

/// The message starts with `<path>: <element>` and contains every one of `words`.
fn assert_element(e: &SceneError, file: &str, element: &str, words: &[&str]) {
    let msg = e.to_string();
    let want = format!("{}: {element}", bad(file).display());
    assert!(msg.starts_with(&want), "expected '{want}...', got: {msg}");
    for w in words {
        assert!(msg.contains(w), "expected '{w}' in: {msg}");
    }
}

// ---- OBJ --------------------------------------------------------------------------------

#[test]
fn obj_bad_number() {
    assert_line(&error("obj_bad_number.obj"), "obj_bad_number.obj", 3, &["'x' is not a number"]);
}

#[test]
fn obj_nan() {
    assert_line(&error("obj_nan.obj"), "obj_nan.obj", 3, &["'nan' is not a finite number"]);
}

#[test]
fn obj_inf() {
    assert_line(&error("obj_inf.obj"), "obj_inf.obj", 4, &["'1e39' is not a finite number"]);
}

#[test]
fn obj_index_out_of_range() {
    assert_line(
        &error("obj_index_out_of_range.obj"),
        "obj_index_out_of_range.obj",
        5,
        &["vertex index 5 out of range (3 vertices so far)"],
    );
}

#[test]
fn obj_index_zero() {
    assert_line(&error("obj_index_zero.obj"), "obj_index_zero.obj", 5, &["index 0 is invalid"]);
}

#[test]
fn obj_negative_index() {
    assert_line(&error("obj_negative_index.obj"), "obj_negative_index.obj", 5, &["vertex index -4 out of range"]);
}

#[test]
fn obj_uv_index() {
    assert_line(&error("obj_uv_index.obj"), "obj_uv_index.obj", 6, &["texture coordinate index 2 out of range"]);
}

#[test]
fn obj_normal_index() {
    assert_line(&error("obj_normal_index.obj"), "obj_normal_index.obj", 6, &["normal index 3 out of range"]);
}

#[test]
fn obj_face_two_vertices() {
    assert_line(&error("obj_face_two_vertices.obj"), "obj_face_two_vertices.obj", 4, &["at least 3 vertices"]);
}

#[test]
fn obj_bad_face_token() {
    assert_line(&error("obj_bad_face_token.obj"), "obj_bad_face_token.obj", 5, &["'3/x'"]);
}

#[test]
fn obj_bad_normal() {
    assert_line(&error("obj_bad_normal.obj"), "obj_bad_normal.obj", 3, &["a normal needs 3 numbers"]);
}

#[test]
fn obj_partial_colours() {
    assert_line(&error("obj_partial_colours.obj"), "obj_partial_colours.obj", 3, &["vertex colours"]);
}

#[test]
fn obj_empty() {
    let e = error("obj_empty.obj");
    assert!(matches!(e, SceneError::Empty { dropped: 0, .. }), "{e:?}");
    assert_element(&e, "obj_empty.obj", "the scene has no triangles", &[]);
}

#[test]
fn obj_all_degenerate() {
    let e = error("obj_all_degenerate.obj");
    assert!(matches!(e, SceneError::Empty { dropped: 2, .. }), "{e:?}");
    assert_element(&e, "obj_all_degenerate.obj", "the scene has no triangles", &["all 2 were degenerate"]);
}

#[test]
fn obj_missing_mtl_warns_or_fails_when_strict() {
    let l = load("obj_missing_mtl.obj", false).unwrap();
    let w = l.warnings.join("\n");
    let at = format!("{}:2: material library 'nothere.mtl' not found", bad("obj_missing_mtl.obj").display());
    assert!(w.contains(&at), "{w}");
    assert!(w.contains("unknown material 'red'"), "{w}");
    assert_eq!(l.scene.materials.len(), 1);
    assert_eq!(l.scene.materials[0].name, "default");
    let e = load("obj_missing_mtl.obj", true).unwrap_err();
    assert_line(&e, "obj_missing_mtl.obj", 2, &["material library 'nothere.mtl' not found"]);
}

#[test]
fn obj_unknown_material_strict() {
    assert!(load("obj_unknown_material.obj", false).is_ok());
    let e = load("obj_unknown_material.obj", true).unwrap_err();
    assert_line(&e, "obj_unknown_material.obj", 5, &["unknown material 'nosuch'"]);
}

#[test]
fn mtl_bad_colour_names_the_mtl_line() {
    assert_line(&error("obj_bad_mtl.obj"), "obj_bad_mtl.mtl", 3, &["expected 3 numbers"]);
}

#[test]
fn mtl_bad_thesis_key_names_the_mtl_line() {
    assert_line(&error("obj_bad_thesis_key.obj"), "obj_bad_thesis_key.mtl", 4, &["'lots' is not a number"]);
}

#[test]
fn missing_texture_warns_or_fails_when_strict() {
    let l = load("obj_missing_texture.obj", false).unwrap();
    let at = format!("{}:3: texture 'nothere.png' not found", bad("obj_missing_texture.mtl").display());
    assert!(l.warnings.iter().any(|w| w.starts_with(&at)), "{:?}", l.warnings);
    assert_eq!(l.scene.materials[0].albedo_texture, None);
    assert!(l.scene.textures.is_empty());
    let e = load("obj_missing_texture.obj", true).unwrap_err();
    assert_line(&e, "obj_missing_texture.mtl", 3, &["texture 'nothere.png' not found", "nothere.png"]);
}

#[test]
fn corrupt_texture_warns_or_fails_when_strict() {
    let l = load("obj_corrupt_texture.obj", false).unwrap();
    let at = format!("{}:3: cannot decode texture 'corrupt.png'", bad("obj_corrupt_texture.mtl").display());
    assert!(l.warnings.iter().any(|w| w.starts_with(&at)), "{:?}", l.warnings);
    let e = load("obj_corrupt_texture.obj", true).unwrap_err();
    assert!(e.to_string().starts_with(&at), "{e}");
    assert_eq!(e.file(), Some(bad("obj_corrupt_texture.mtl").as_path()));
}

// ---- files --------------------------------------------------------------------------------

#[test]
fn missing_file() {
    let e = error("does_not_exist.obj");
    assert!(matches!(e, SceneError::Io { .. }), "{e:?}");
    assert_element(&e, "does_not_exist.obj", "cannot read", &[]);
    let e = error("does_not_exist.gltf");
    assert_element(&e, "does_not_exist.gltf", "cannot read", &[]);
}

#[test]
fn unknown_format() {
    let e = error("unknown_format.ply");
    assert_element(&e, "unknown_format.ply", "unknown scene format", &[]);
}

#[test]
fn garbage_obj() {
    // Random bytes: whatever the first bad line is, the error names the file.
    let e = error("garbage.obj");
    assert_eq!(e.file(), Some(bad("garbage.obj").as_path()), "{e}");
}

// ---- glTF ---------------------------------------------------------------------------------

#[test]
fn gltf_draco() {
    let e = error("gltf_draco.gltf");
    assert!(matches!(e, SceneError::Unsupported { .. }), "{e:?}");
    assert_element(&e, "gltf_draco.gltf", "extensionsRequired[0]", &["Draco", "not supported"]);
}

#[test]
fn gltf_meshopt() {
    let e = error("gltf_meshopt.gltf");
    assert_element(&e, "gltf_meshopt.gltf", "extensionsRequired[1]", &["meshopt", "not supported"]);
}

#[test]
fn gltf_image_without_source() {
    let e = error("gltf_image_without_source.gltf");
    assert_element(&e, "gltf_image_without_source.gltf", "images[0]", &["neither uri nor bufferView"]);
}

#[test]
fn gltf_missing_image_warns_or_fails_when_strict() {
    let l = load("gltf_missing_image.gltf", false).unwrap();
    let at = format!("{}: image 0 \"gone\": texture 'gone' not found", bad("gltf_missing_image.gltf").display());
    assert!(l.warnings.iter().any(|w| w.starts_with(&at) && w.contains("nothere.png")), "{:?}", l.warnings);
    assert_eq!(l.scene.materials[0].albedo_texture, None);
    let e = load("gltf_missing_image.gltf", true).unwrap_err();
    assert_element(&e, "gltf_missing_image.gltf", "image 0 \"gone\"", &["not found", "nothere.png"]);
}

#[test]
fn gltf_camera_without_projection() {
    let e = error("gltf_camera_without_projection.gltf");
    assert_element(&e, "gltf_camera_without_projection.gltf", "cameras[0]", &["projection"]);
}

#[test]
fn gltf_sparse() {
    let e = error("gltf_sparse.gltf");
    assert!(matches!(e, SceneError::Unsupported { .. }), "{e:?}");
    assert_element(&e, "gltf_sparse.gltf", "mesh 0 \"Q\", primitive 0, accessor 0 (POSITION)", &["a sparse accessor is not supported"]);
}

#[test]
fn gltf_index_out_of_range() {
    let e = error("gltf_index_out_of_range.gltf");
    assert_element(&e, "gltf_index_out_of_range.gltf", "mesh 0 \"Q\", primitive 0, accessor 5 (indices)", &["index 7", "4 vertices"]);
}

#[test]
fn gltf_wrong_accessor_type() {
    let e = error("gltf_wrong_accessor_type.gltf");
    assert_element(&e, "gltf_wrong_accessor_type.gltf", "mesh 0 \"Q\", primitive 0, accessor 0 (POSITION)", &["Vec2"]);
}

#[test]
fn gltf_accessor_overrun() {
    let e = error("gltf_accessor_overrun.gltf");
    assert_element(&e, "gltf_accessor_overrun.gltf", "mesh 0 \"Q\", primitive 0, accessor 0 (POSITION)", &["400 elements", "run past"]);
}

#[test]
fn gltf_nan_position() {
    let e = error("gltf_nan_position.gltf");
    assert_element(&e, "gltf_nan_position.gltf", "mesh 0 \"Q\", primitive 0, accessor 5 (POSITION)", &["element 1 is not finite"]);
}

#[test]
fn gltf_bad_reference() {
    let e = error("gltf_bad_reference.gltf");
    assert_element(&e, "gltf_bad_reference.gltf", "meshes[0].primitives[0].attributes", &["invalid"]);
}

#[test]
fn gltf_node_cycle() {
    let e = error("gltf_node_cycle.gltf");
    assert_element(&e, "gltf_node_cycle.gltf", "node", &["cycle"]);
}

#[test]
fn gltf_normal_count() {
    let e = error("gltf_normal_count.gltf");
    assert_element(&e, "gltf_normal_count.gltf", "mesh 0 \"Q\", primitive 0, accessor 1 (NORMAL)", &["3 elements, but POSITION has 4"]);
}

#[test]
fn gltf_short_buffer() {
    let e = error("gltf_short_buffer.gltf");
    assert_element(&e, "gltf_short_buffer.gltf", "buffer 0", &["the file declares"]);
}

#[test]
fn gltf_missing_bin() {
    let e = error("gltf_missing_bin.gltf");
    assert_element(&e, "gltf_missing_bin.gltf", "buffer 0", &["cannot read 'gltf_missing_bin.bin'"]);
}

#[test]
fn gltf_points_only() {
    let e = error("gltf_points_only.gltf");
    assert!(matches!(e, SceneError::Empty { .. }), "{e:?}");
    assert_element(&e, "gltf_points_only.gltf", "the scene has no triangles", &[]);
}

#[test]
fn gltf_invalid_json() {
    let e = error("gltf_invalid_json.gltf");
    assert_element(&e, "gltf_invalid_json.gltf", "file", &["line"]);
}

#[test]
fn glb_truncated() {
    let e = error("glb_truncated.glb");
    assert_element(&e, "glb_truncated.glb", "file", &[]);
    let e = error("garbage.glb");
    assert_element(&e, "garbage.glb", "file", &[]);
}

// ---- issue 18 ---------------------------------------------------------------------------

/// Found by the loader fuzzer: a `usemtl` name echoed raw (terminal escapes) in the error.
#[test]
fn unknown_material_name_is_escaped() {
    let dir = std::env::temp_dir().join(format!("bidir-usemtl-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let obj = dir.join("esc.obj");
    std::fs::write(&obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl Stencil\x1b[2J\nf 1 2 3\n").unwrap();
    let e = scene::load(&obj, &LoadOptions { strict: true }).expect_err("strict").to_string();
    std::fs::remove_dir_all(&dir).ok();
    assert!(e.ends_with("unknown material 'Stencil\\u{1b}[2J'"), "{e:?}");
    // And a face vertex of garbage (also a fuzzer finding).
    let e = scene::load_obj_str("esc.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3/\x1b[2J\r\n", &|_| None, &LoadOptions::default())
        .expect_err("bad face")
        .to_string();
    assert!(!e.chars().any(char::is_control) && e.contains("'3/\\u{1b}[2J'"), "{e:?}");
}

/// Found by the loader fuzzer's long run (session 39): a material library whose name holds a
/// NUL and terminal escapes made an error (the library cannot be opened) that echoed its path
/// raw; paths in messages are escaped, and kept whole however long they are.
#[test]
fn library_path_with_control_characters_is_escaped() {
    let dir = std::env::temp_dir().join(format!("bidir-mtllib-{}-{}", std::process::id(), "d".repeat(80)));
    std::fs::create_dir_all(&dir).unwrap();
    let obj = dir.join("esc.obj");
    std::fs::write(&obj, "mtllib \x1b[2J\u{9b}\0.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    let e = scene::load(&obj, &LoadOptions { strict: false }).expect_err("a NUL in a file name").to_string();
    std::fs::remove_dir_all(&dir).ok();
    assert!(!e.chars().any(char::is_control), "{e:?}");
    assert!(e.contains(&format!("{}/\\u{{1b}}[2J\\u{{9b}}\\u{{0}}.mtl: cannot read", dir.display())), "{e}");
}

#[test]
fn gltf_node_with_two_parents() {
    let e = error("gltf_two_parents.gltf");
    assert_element(&e, "gltf_two_parents.gltf", "node 1 \"Shared\"", &["has two parents, nodes 0 and 2", "forest"]);
}

#[test]
fn glb_bad_magic_says_so() {
    let e = error("glb_bad_magic.glb");
    assert_element(&e, "glb_bad_magic.glb", "file", &["not a GLB file (magic \"GLB\\x00\", expected \"glTF\")"]);
}

#[test]
fn gltf_camera_aspect_zero_warns() {
    let l = load("gltf_camera_aspect_zero.gltf", false).unwrap();
    let file = bad("gltf_camera_aspect_zero.gltf").display().to_string();
    assert!(
        l.warnings.iter().any(|w| w.starts_with(&file) && w.contains("camera 0 \"CamNode\": aspect ratio 0 is not positive")),
        "{:?}",
        l.warnings
    );
    assert_eq!((l.scene.cameras[0].width, l.scene.cameras[0].height), (1920, 1080));
}

#[test]
fn mtl_huge_emission_is_refused() {
    let e = error("obj_huge_ke.obj");
    assert_element(&e, "obj_huge_ke.obj", "material 'lamp': emitted radiance 3e38 is too large", &["limit 1e12"]);
}

/// Radiance within the limit on a vast emitter: pi x area x radiance overflows float32.
/// (Loaders drop such triangles as degenerate; added lights and other producers may not.)
#[test]
fn emitted_power_overflow_is_refused() {
    let mut s = scene::Scene::builtin_cornell_box();
    s.positions.iter_mut().for_each(|p| *p *= 1e16);
    let e = s.check_emission().expect_err("refused").to_string();
    assert!(e.starts_with(scene::BUILTIN_SOURCE) && e.contains("emitted power") && e.contains("overflows"), "{e}");
    assert!(scene::Scene::builtin_cornell_box().check_emission().is_ok());
}

#[test]
fn untrusted_text_is_escaped_and_truncated() {
    let e = error("obj_control_chars.obj").to_string();
    assert!(!e.chars().any(|c| c.is_control()), "{e:?}");
    assert!(e.contains("'\\u{1b}[2J\\u{1b}]0;pwned\\u{7}\\u{0}' is not a number"), "{e}");
    let e = error("obj_long_number.obj").to_string();
    assert!(e.len() < 300 && e.contains("... (60000 characters)' is not a finite number"), "{e}");
}

/// Every file of the corpus, strict or not, through `catch_unwind`: an error or a scene,
/// never a panic.
#[test]
fn no_bad_file_panics() {
    let dir = bad("");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).collect();
    files.sort();
    assert!(files.len() >= 30, "corpus too small: {}", files.len());
    let mut panicked = Vec::new();
    for f in &files {
        for strict in [false, true] {
            let r = std::panic::catch_unwind(|| scene::load(f, &LoadOptions { strict }).map(|l| l.scene.triangles.len()));
            if r.is_err() {
                panicked.push(format!("{} (strict {strict})", f.display()));
            }
        }
    }
    assert!(panicked.is_empty(), "panicked on: {panicked:?}");
}

/// Deterministic random edits of good files (bytes flipped, ranges dropped or repeated,
/// numbers swapped for `0`, `-9`, `nan`, `1e40`...): each load is an error or a scene, never a
/// panic.
#[test]
fn mutated_files_never_panic() {
    let dir = std::env::temp_dir().join(format!("bidir-scene-mutations-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let good = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let originals = [
        ("room.obj", std::fs::read(good.join("room/room.obj")).unwrap()),
        ("room.mtl", std::fs::read(good.join("room/room.mtl")).unwrap()),
        ("instanced.gltf", std::fs::read(good.join("gltf/instanced.gltf")).unwrap()),
        ("instanced.glb", std::fs::read(good.join("gltf/instanced.glb")).unwrap()),
    ];
    // The room's textures next to the mutated files, so texture decoding is exercised too.
    for t in ["floor_d.tga", "leaf.png", "mask_grey.png"] {
        std::fs::copy(good.join("room").join(t), dir.join(t)).unwrap();
    }
    std::fs::copy(good.join("gltf/instanced.bin"), dir.join("instanced.bin")).unwrap();
    const TOKENS: [&[u8]; 9] = [b"0", b"-9", b"nan", b"1e40", b"/", b" ", b"\n", b"99999999999", b"\""];
    // More rounds or another seed: BIDIR_MUTATION_ROUNDS, BIDIR_MUTATION_SEED.
    let env = |k: &str, d: u64| std::env::var(k).ok().and_then(|v| v.parse().ok()).unwrap_or(d);
    let rounds = env("BIDIR_MUTATION_ROUNDS", 150);
    let mut rng = common::Pcg::new(env("BIDIR_MUTATION_SEED", 1234));
    let mut panicked = Vec::new();
    for (name, original) in &originals {
        for round in 0..rounds {
            let mut bytes = original.clone();
            for _ in 0..1 + rng.below(4) {
                let len = bytes.len() as u32;
                let at = rng.below(len) as usize;
                match rng.below(4) {
                    0 => bytes[at] ^= 1 << rng.below(8),
                    1 => {
                        let n = (rng.below(16) as usize).min(bytes.len() - at);
                        bytes.drain(at..at + n);
                    }
                    2 => {
                        let n = (rng.below(32) as usize).min(bytes.len() - at);
                        let copy = bytes[at..at + n].to_vec();
                        bytes.splice(at..at, copy);
                    }
                    _ => {
                        let t = TOKENS[rng.below(TOKENS.len() as u32) as usize];
                        bytes.splice(at..at, t.iter().copied());
                    }
                }
            }
            // The OBJ loads its unmodified library and vice versa.
            for (f, b) in [("room.obj", &originals[0].1), ("room.mtl", &originals[1].1)] {
                std::fs::write(dir.join(f), b).unwrap();
            }
            std::fs::write(dir.join(name), &bytes).unwrap();
            let target = dir.join(if *name == "room.mtl" { "room.obj" } else { name });
            for strict in [false, true] {
                let r = std::panic::catch_unwind(|| scene::load(&target, &LoadOptions { strict }).map(|l| l.scene.triangles.len()));
                if r.is_err() {
                    let keep = dir.join(format!("panic-{round}-{name}"));
                    std::fs::write(&keep, &bytes).unwrap();
                    panicked.push(keep.display().to_string());
                }
            }
        }
    }
    assert!(panicked.is_empty(), "panicked on (inputs kept): {panicked:?}");
    std::fs::remove_dir_all(&dir).ok();
}
