//! Wavefront OBJ + MTL, through tobj.
//!
//! 1. `obj_check` validates every line (errors name file and line) and notes `mtllib` and
//!    `usemtl` statements.
//! 2. Material libraries are read and parsed by `mtl` (with the thesis' keys). A missing
//!    library or unknown material name is a warning (faces fall back to a default grey
//!    material), or an error with `strict`.
//! 3. tobj parses the geometry: polygons are fan-triangulated (convex polygons only, as
//!    OBJ exporters write them), and each object/material group becomes a mesh whose
//!    vertices are the distinct (position, uv, normal) index triples of its faces.
//! 4. The builder concatenates the meshes. A mesh whose faces all have normals keeps them; one
//!    without normals, in a file where others have them, gets flat face normals; a mesh in
//!    which only *some* faces have normals cannot be told apart by tobj's output, so it is
//!    treated as having none (flat normals, warned). UVs likewise, filled with (0, 0). OBJ's
//!    `v` runs up the image, so it is flipped to the scene's top-left origin.

use std::cell::Cell;
use std::collections::HashMap;
use std::path::{Path, PathBuf};

use glam::{Vec2, Vec3};

use super::builder::{Builder, Part};
use super::mtl::{self, MtlEntry};
use super::texture::{Request, Requests, Role, Source};
use super::warnings::Warnings;
use super::{obj_check, LoadOptions, Loaded, Material, Scene, SceneError};

/// Where material libraries and textures come from.
enum Files<'a> {
    /// Next to the OBJ file.
    Dir(&'a Path),
    /// Supplied by the caller (the embedded Cornell box); no textures.
    Memory(&'a dyn Fn(&str) -> Option<String>),
}

/// Loads an OBJ file and the material libraries (and textures) it references.
pub fn load_obj(path: &Path, opts: &LoadOptions) -> Result<Loaded, SceneError> {
    let bytes = std::fs::read(path).map_err(|e| SceneError::io(path, e))?;
    let text = String::from_utf8_lossy(&bytes);
    let dir = path.parent().unwrap_or(Path::new(""));
    load_text(path, &text, Files::Dir(dir), opts)
}

/// Loads OBJ text held in memory; `mtl(name)` returns the material library `mtllib name`
/// refers to (`None`: missing). `name` labels messages. Textures cannot be loaded this way.
pub fn load_obj_str(name: &str, obj: &str, mtl: &dyn Fn(&str) -> Option<String>, opts: &LoadOptions) -> Result<Loaded, SceneError> {
    load_text(Path::new(name), obj, Files::Memory(mtl), opts)
}

/// `a\b.png` from Windows exporters means `a/b.png`.
fn portable(name: &str) -> String {
    name.replace('\\', "/")
}

fn load_text(file: &Path, text: &str, files: Files, opts: &LoadOptions) -> Result<Loaded, SceneError> {
    let mut w = Warnings::default();
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let check = obj_check::check(file, text, &mut w)?;

    // Material libraries, in `mtllib` order: (library path, entry).
    let mut entries: Vec<(PathBuf, MtlEntry)> = Vec::new();
    // The material names each `mtllib` statement defined, for tobj's loader callback.
    let mut per_statement: Vec<Vec<String>> = Vec::new();
    for (line, spec) in &check.mtllibs {
        let mut names = Vec::new();
        for lib in library_names(spec, &files) {
            match read_library(&files, &lib).map_err(|e| SceneError::Io { file: e.0, source: e.1 })? {
                Some((lib_path, lib_text)) => {
                    for e in mtl::parse(&lib_path, &lib_text, &mut w)? {
                        names.push(e.name.clone());
                        entries.push((lib_path.clone(), e));
                    }
                }
                None => {
                    let missing = library_path(&files, &lib);
                    if opts.strict {
                        return Err(SceneError::Missing {
                            file: file.to_path_buf(),
                            line: *line,
                            what: "material library",
                            name: crate::text::quote(&lib),
                            missing,
                        });
                    }
                    w.warn(format!(
                        "{}:{line}: material library '{lib}' not found (looked for {}); its materials become default grey",
                        file.display(),
                        missing.display()
                    ));
                }
            }
        }
        per_statement.push(names);
    }

    // One material per name; a later definition replaces an earlier one.
    let mut by_name: HashMap<String, usize> = HashMap::new();
    let mut defs: Vec<usize> = Vec::new(); // index into `entries`
    for (k, (lib, e)) in entries.iter().enumerate() {
        match by_name.get(&e.name) {
            Some(&m) => {
                w.warn(format!("{}:{}: material '{}' defined again; the later definition wins", lib.display(), e.line, e.name));
                defs[m] = k;
            }
            None => {
                by_name.insert(e.name.clone(), defs.len());
                defs.push(k);
            }
        }
    }
    for (line, name) in &check.usemtls {
        if !by_name.contains_key(name) {
            if opts.strict {
                return Err(SceneError::UnknownMaterial { file: file.to_path_buf(), line: *line, name: crate::text::quote(name) });
            }
            w.warn_once(&format!("usemtl-{name}"), || {
                format!("{}:{line}: unknown material '{name}'; its faces use the default grey", file.display())
            });
        }
    }

    // Materials, requesting their textures.
    let mut requests = Requests::default();
    let mut materials: Vec<Material> = defs
        .iter()
        .map(|&k| {
            let (lib, e) = &entries[k];
            mtl::to_material(e, lib, &mut w, &mut |name, line, role, w| texture_request(&files, &mut requests, lib, name, line, role, w))
        })
        .collect();

    // Geometry, through tobj.
    let source = check.rewritten.as_deref().unwrap_or(text);
    let calls = Cell::new(0usize);
    let load_options = tobj::LoadOptions { single_index: true, triangulate: true, ignore_points: true, ignore_lines: true };
    let (models, tobj_materials) = tobj::load_obj_buf(&mut source.as_bytes(), &load_options, |_| {
        // Called once per `mtllib`, in order: answer with the names that statement defined.
        let k = calls.get();
        calls.set(k + 1);
        let names = per_statement.get(k).cloned().unwrap_or_default();
        let map = names.iter().enumerate().map(|(i, n)| (n.clone(), i)).collect();
        Ok((names.into_iter().map(|name| tobj::Material { name, ..Default::default() }).collect(), map))
    })
    .map_err(|e| SceneError::Parse { file: file.to_path_buf(), msg: format!("tobj: {e}") })?;
    let tobj_materials = tobj_materials.unwrap_or_default();

    let mut default_material: Option<u32> = None;
    let mut material_of = |id: Option<usize>, materials: &mut Vec<Material>| -> u32 {
        let named = id.and_then(|i| tobj_materials.get(i)).and_then(|m| by_name.get(&m.name));
        match named {
            Some(&m) => m as u32,
            None => *default_material.get_or_insert_with(|| {
                materials.push(Material { name: "default".into(), ..Default::default() });
                (materials.len() - 1) as u32
            }),
        }
    };

    let has = |attr: usize, verts: usize| attr == verts && verts > 0;
    let with_normals = models.iter().any(|m| has(m.mesh.normals.len() / 3, m.mesh.positions.len() / 3));
    let with_uvs = models.iter().any(|m| has(m.mesh.texcoords.len() / 2, m.mesh.positions.len() / 3));
    let mut b = Builder::new(with_normals, with_uvs);
    let total_indices: usize = models.iter().map(|m| m.mesh.indices.len()).sum();
    let total_vertices: usize = models.iter().map(|m| m.mesh.positions.len() / 3).sum();
    b.reserve(total_vertices, total_indices / 3);
    for model in &models {
        let mesh = &model.mesh;
        let verts = mesh.positions.len() / 3;
        let positions: Vec<Vec3> = mesh.positions.chunks_exact(3).map(Vec3::from_slice).collect();
        let normals_ok = has(mesh.normals.len() / 3, verts);
        let uvs_ok = has(mesh.texcoords.len() / 2, verts);
        for (what, len) in [("normals", mesh.normals.len()), ("texture coordinates", mesh.texcoords.len())] {
            if len > 0 && !(if what == "normals" { normals_ok } else { uvs_ok }) {
                w.warn(format!("{}: object '{}' has {what} on only some faces; using none for it", file.display(), model.name));
            }
        }
        let normals: Option<Vec<Vec3>> = normals_ok.then(|| mesh.normals.chunks_exact(3).map(Vec3::from_slice).collect());
        let uvs: Option<Vec<Vec2>> = uvs_ok.then(|| mesh.texcoords.chunks_exact(2).map(|t| Vec2::new(t[0], 1.0 - t[1])).collect());
        let triangles: Vec<[u32; 3]> = mesh.indices.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect();
        let material = material_of(mesh.material_id, &mut materials);
        b.push(
            &Part {
                positions: &positions,
                normals: normals.as_deref(),
                uvs: uvs.as_deref(),
                tangents: None,
                triangles: &triangles,
                material,
            },
            None,
        );
    }

    let decoded = requests.decode(opts.strict, &mut w)?;
    decoded.apply(&mut materials);
    if b.triangles.is_empty() {
        return Err(SceneError::Empty { file: file.to_path_buf(), dropped: b.dropped_degenerate });
    }
    let scene = Scene {
        source: file.display().to_string(),
        positions: b.positions,
        normals: b.normals,
        uvs: b.uvs,
        tangents: None,
        triangles: b.triangles,
        material_ids: b.material_ids,
        materials,
        textures: decoded.textures,
        cameras: Vec::new(),
        dropped_degenerate: b.dropped_degenerate,
        environment: None,
        punctual_lights: Vec::new(),
    };
    Ok(Loaded { scene, warnings: w.into_vec() })
}

/// `mtllib a.mtl b.mtl` may name several files; a single name may contain spaces. The whole
/// text is taken as one name when such a file exists, else split at whitespace.
fn library_names(spec: &str, files: &Files) -> Vec<String> {
    let whole = portable(spec);
    let exists = match files {
        Files::Dir(dir) => dir.join(&whole).is_file(),
        Files::Memory(get) => get(&whole).is_some(),
    };
    if exists || !spec.contains(char::is_whitespace) {
        vec![whole]
    } else {
        spec.split_whitespace().map(portable).collect()
    }
}

fn library_path(files: &Files, name: &str) -> PathBuf {
    match files {
        Files::Dir(dir) => dir.join(name),
        Files::Memory(_) => PathBuf::from(name),
    }
}

/// The library's path and text, `None` if it does not exist.
fn read_library(files: &Files, name: &str) -> Result<Option<(PathBuf, String)>, (PathBuf, std::io::Error)> {
    let path = library_path(files, name);
    match files {
        Files::Dir(_) => match std::fs::read(&path) {
            Ok(bytes) => Ok(Some((path, String::from_utf8_lossy(&bytes).into_owned()))),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(None),
            Err(e) => Err((path, e)),
        },
        Files::Memory(get) => Ok(get(name).map(|t| (path, t))),
    }
}

fn texture_request(
    files: &Files,
    requests: &mut Requests,
    lib: &Path,
    name: &str,
    line: usize,
    role: Role,
    w: &mut Warnings,
) -> Option<u32> {
    let name = portable(name);
    match files {
        Files::Dir(_) => {
            let path = lib.parent().unwrap_or(Path::new("")).join(&name);
            let key = path.display().to_string();
            Some(requests.request(key, role, || Request {
                name: name.clone(),
                source: Source::File(path),
                role,
                at: format!("{}:{line}", crate::text::path(lib)),
                file: lib.to_path_buf(),
                line: Some(line),
            }))
        }
        Files::Memory(_) => {
            w.warn_once("obj-memory-textures", || format!("{}:{line}: texture '{name}' not loaded (scene held in memory)", lib.display()));
            None
        }
    }
}
