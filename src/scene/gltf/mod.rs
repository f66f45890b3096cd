//! glTF 2.0 (`.gltf` + `.bin` + images, or `.glb`) into one flat scene.
//!
//! The node hierarchy of the default scene (else the first; else every root node) is
//! flattened: each node that references a mesh adds a copy of it transformed by the node's
//! world matrix (positions by the matrix, normals by its inverse transpose, winding swapped
//! when the determinant is negative), so instancing costs memory, not traversal. Each mesh is
//! read once, however often it is instanced. Perspective cameras become [`Camera`]s,
//! `KHR_lights_punctual` lights punctual lights (`lights.rs`).
//!
//! Textures the materials use (`material.rs`: base colour, metallic-roughness, normal,
//! emissive, transmission and the extensions' maps) are decoded on worker threads while the
//! geometry is assembled. Vertex attributes are read by `accessor.rs`, floats or
//! `KHR_mesh_quantization`'s integers (the node transforms and texture transforms that
//! dequantize them are applied as for any mesh).
//!
//! Errors (geometry that cannot be read): invalid JSON or references, required geometry
//! encodings (Draco, meshopt, GPU instancing) or texture formats, sparse accessors, accessors
//! of the wrong type, out of range or non-finite, unreadable buffers. Texture coordinate sets
//! and `KHR_texture_transform` are baked into the UVs per material (`uv_map.rs`).
//!
//! Warnings (ignored once, by name): other unsupported extensions (material extensions even
//! when required), texture kinds, non-triangle primitives, vertex colours, skins, morph
//! targets, orthographic cameras, extra scenes.

mod accessor;
mod files;
mod lights;
mod material;
mod uv_map;

use std::path::Path;

use ::gltf::mesh::{Mode, Semantic};
use ::gltf::{Document, Node};
use glam::{Mat4, Quat, Vec2, Vec3};

use self::accessor::{read_indices, read_uv, read_vec3, read_vec4, AccessorError, Attribute};
use super::builder::{Builder, Part, Transform};
use super::texture::Requests;
use super::warnings::Warnings;
use super::{Camera, LoadOptions, Loaded, Material, Scene, SceneError};
use crate::limits::{thousands, MAX_INSTANCES, MAX_TRIANGLES};

/// Extensions the loader reads.
const SUPPORTED_EXTENSIONS: &[&str] = &[
    "KHR_materials_transmission",
    "KHR_materials_ior",
    "KHR_materials_emissive_strength",
    "KHR_materials_volume",
    "KHR_materials_specular",
    "KHR_lights_punctual",
    "KHR_texture_transform",
    "KHR_mesh_quantization",
    "KHR_materials_clearcoat",
];

/// Supported extensions that the `gltf` crate's validation does not know, so that a file
/// requiring one is taken out of its `extensionsRequired` before validation (the loader's
/// own accessor reader, accessor.rs, reads quantized attributes; material.rs reads the clear
/// coat from the extension's JSON).
const READ_BY_THE_LOADER: &[&str] = &["KHR_mesh_quantization", "KHR_materials_clearcoat"];

/// Loads a `.gltf` or `.glb` file with its buffers and base colour textures.
pub fn load_gltf(path: &Path, opts: &LoadOptions) -> Result<Loaded, SceneError> {
    let file = path;
    let gerr = |element: &str, msg: String| SceneError::Gltf { file: file.to_path_buf(), element: element.into(), msg };
    let bytes = std::fs::read(path).map_err(|e| SceneError::io(path, e))?;
    check_glb_magic(file, &bytes)?;
    let mut w = Warnings::default();
    let ::gltf::Gltf { document, blob } = ::gltf::Gltf::from_slice_without_validation(&bytes).map_err(|e| gerr("file", e.to_string()))?;
    drop(bytes);
    let relaxed = check_extensions(file, &document, &mut w)?;
    check_what_validation_misses(file, &document)?;
    let mut json = document.into_json();
    json.extensions_required.retain(|e| !relaxed.contains(e));
    let doc = Document::from_json(json).map_err(|e| match e {
        ::gltf::Error::Validation(errs) => {
            let (path, why) = &errs[0];
            let more = if errs.len() > 1 { format!(" (and {} more problems)", errs.len() - 1) } else { String::new() };
            gerr(&path.to_string(), format!("invalid: {why}{more}"))
        }
        e => gerr("file", e.to_string()),
    })?;
    let base = path.parent().unwrap_or(Path::new(""));
    let buffers = files::load_buffers(file, &doc, base, blob)?;

    let mut requests = Requests::default();
    let mut materials = material::convert(file, &doc, &buffers, base, &mut requests, &mut w)?;
    let default_material = materials.len() as u32;
    let uv_maps = uv_map::uv_maps(file, &doc, &mut w);

    let mut tex_warnings = Warnings::default();
    let (geometry, decoded) = std::thread::scope(|s| {
        let decoder = s.spawn(|| requests.decode(opts.strict, &mut tex_warnings));
        let geometry = geometry(file, &doc, &buffers, default_material, &uv_maps, &mut w);
        let decoded =
            decoder.join().unwrap_or_else(|_| Err(SceneError::Parse { file: file.to_path_buf(), msg: "texture decoding failed".into() }));
        (geometry, decoded)
    });
    let (b, cameras, used_default) = geometry?;
    let decoded = decoded?;
    for msg in tex_warnings.into_vec() {
        w.warn(msg);
    }
    decoded.apply(&mut materials);
    if used_default {
        materials.push(Material { name: "default".into(), ..Default::default() });
    }
    if b.triangles.is_empty() {
        return Err(SceneError::Empty { file: file.to_path_buf(), dropped: b.dropped_degenerate });
    }
    let scene = Scene {
        source: file.display().to_string(),
        positions: b.positions,
        normals: b.normals,
        uvs: b.uvs,
        tangents: b.tangents,
        triangles: b.triangles,
        material_ids: b.material_ids,
        materials,
        textures: decoded.textures,
        cameras,
        dropped_degenerate: b.dropped_degenerate,
        environment: None,
        punctual_lights: lights::punctual_lights(&doc, scene_roots(&doc)),
    };
    Ok(Loaded { scene, warnings: w.into_vec() })
}

/// A `.glb` must start with the magic `glTF` (else the `gltf` crate reads it as JSON and says
/// "expected value at line 1 column 1").
fn check_glb_magic(file: &Path, bytes: &[u8]) -> Result<(), SceneError> {
    let is_glb = file.extension().is_some_and(|e| e.eq_ignore_ascii_case("glb"));
    if is_glb && !bytes.starts_with(b"glTF") {
        let magic = bytes[..bytes.len().min(4)].escape_ascii().to_string();
        return Err(SceneError::Gltf {
            file: file.to_path_buf(),
            element: "file".into(),
            msg: format!("not a GLB file (magic \"{magic}\", expected \"glTF\")"),
        });
    }
    Ok(())
}

/// Checks that the node graph is a forest (glTF 2.0 §3.5.3): no node has two parents, and no
/// root of the scene has a parent (else a cycle). A 6 KB file whose nodes share children
/// would otherwise expand into ~10^12 instances.
fn check_forest(file: &Path, doc: &Document, roots: &[Node]) -> Result<(), SceneError> {
    let gerr = |element: String, msg: String| SceneError::Gltf { file: file.to_path_buf(), element, msg };
    let mut parent: Vec<Option<usize>> = vec![None; doc.nodes().len()];
    for n in doc.nodes() {
        for c in n.children() {
            if let Some(p) = parent[c.index()] {
                return Err(gerr(
                    node_element(&c),
                    format!("has two parents, nodes {p} and {} (the node graph must be a forest)", n.index()),
                ));
            }
            parent[c.index()] = Some(n.index());
        }
    }
    for r in roots {
        if let Some(p) = parent[r.index()] {
            // Follow the parents up: back at `r` is a cycle.
            let (mut at, mut steps) = (Some(p), 0);
            while let Some(a) = at.filter(|&a| a != r.index() && steps <= parent.len()) {
                at = parent[a];
                steps += 1;
            }
            let msg = if at == Some(r.index()) {
                "the node hierarchy has a cycle".to_owned()
            } else {
                format!("is a root of the scene but also a child of node {p} (the node graph must be a forest)")
            };
            return Err(gerr(node_element(r), msg));
        }
    }
    Ok(())
}

/// `node 3 "Name"`, for messages.
fn node_element(node: &Node) -> String {
    format!("node {}{}", node.index(), node.name().map_or(String::new(), |n| format!(" \"{}\"", crate::text::quote(n))))
}

/// Whether a file that *requires* extension `ext` can still be loaded, approximately: the
/// extension changes materials, texture placement or lights, not whether the geometry can be
/// read. Such requirements are warned about and removed before validation (which would
/// otherwise reject them). Geometry encodings (Draco, meshopt, GPU instancing)
/// and texture formats stay errors.
fn degradable(ext: &str) -> bool {
    ext.starts_with("KHR_materials_") || ext == "KHR_texture_transform"
}

/// Required extensions the loader cannot honour are errors; the others, and those merely
/// used, are warnings (once each, by name). Returns the names to drop from
/// `extensionsRequired`.
fn check_extensions(file: &Path, doc: &Document, w: &mut Warnings) -> Result<Vec<String>, SceneError> {
    let json = doc.as_json();
    let mut relaxed = Vec::new();
    for (i, ext) in json.extensions_required.iter().enumerate() {
        if READ_BY_THE_LOADER.contains(&ext.as_str()) {
            relaxed.push(ext.clone());
            continue;
        }
        if SUPPORTED_EXTENSIONS.contains(&ext.as_str()) {
            continue;
        }
        if degradable(ext) {
            relaxed.push(ext.clone());
            continue;
        }
        let what = match ext.as_str() {
            "KHR_draco_mesh_compression" => "Draco mesh compression (KHR_draco_mesh_compression)".to_owned(),
            "EXT_meshopt_compression" => "meshopt compression (EXT_meshopt_compression)".to_owned(),
            _ => format!("the required extension {ext}"),
        };
        return Err(SceneError::Unsupported { file: file.to_path_buf(), element: format!("extensionsRequired[{i}]"), what });
    }
    for ext in json.extensions_used.iter().chain(&relaxed) {
        if !SUPPORTED_EXTENSIONS.contains(&ext.as_str()) {
            let effect = match ext.as_str() {
                "KHR_texture_transform" => "texture transforms ignored, textures may be misplaced",
                "KHR_draco_mesh_compression" => "uncompressed fallback data is read",
                _ => "ignored",
            };
            w.warn_once(&format!("gltf-ext-{ext}"), || format!("{}: glTF extension {ext} is not supported; {effect}", file.display()));
        }
    }
    Ok(relaxed)
}

/// What the `gltf` crate's validation lets through but its accessors then `unwrap` (a panic):
/// a dangling POSITION reference (its validation indexes it unchecked), an image with neither
/// `uri` nor `bufferView` + `mimeType`, a camera whose `type` names a projection it lacks.
fn check_what_validation_misses(file: &Path, doc: &Document) -> Result<(), SceneError> {
    use ::gltf::json::camera::Type;
    use ::gltf::json::{mesh::Semantic as S, validation::Checked};
    let err = |element: String, msg: String| Err(SceneError::Gltf { file: file.to_path_buf(), element, msg });
    let json = doc.as_json();
    for (mi, mesh) in json.meshes.iter().enumerate() {
        for (pi, prim) in mesh.primitives.iter().enumerate() {
            if let Some(acc) = prim.attributes.get(&Checked::Valid(S::Positions)) {
                if acc.value() >= json.accessors.len() {
                    return err(
                        format!("meshes[{mi}].primitives[{pi}].attributes[\"POSITION\"]"),
                        format!("invalid: accessor {} does not exist ({} accessors)", acc.value(), json.accessors.len()),
                    );
                }
            }
        }
    }
    for (i, img) in json.images.iter().enumerate() {
        if img.buffer_view.is_some() && img.mime_type.is_none() {
            return err(format!("images[{i}]"), "invalid: an image in a bufferView needs a mimeType".into());
        }
        if img.buffer_view.is_none() && img.uri.is_none() {
            return err(format!("images[{i}]"), "invalid: neither uri nor bufferView".into());
        }
    }
    for (i, cam) in json.cameras.iter().enumerate() {
        let missing = match cam.type_ {
            Checked::Valid(Type::Perspective) => cam.perspective.is_none(),
            Checked::Valid(Type::Orthographic) => cam.orthographic.is_none(),
            Checked::Invalid => false, // validation reports it
        };
        if missing {
            return err(format!("cameras[{i}]"), "invalid: the projection its type names is missing".into());
        }
    }
    Ok(())
}

/// One primitive in mesh space.
struct Prim {
    positions: Vec<Vec3>,
    normals: Option<Vec<Vec3>>,
    uvs: Option<Vec<Vec2>>,
    tangents: Option<Vec<glam::Vec4>>,
    triangles: Vec<[u32; 3]>,
    material: u32,
}

type Geometry = (Builder, Vec<Camera>, bool);

/// Flattens the scene graph: returns the geometry, the cameras, and whether the default
/// material (index `default_material`) was used.
fn geometry(
    file: &Path,
    doc: &Document,
    buffers: &[Vec<u8>],
    default_material: u32,
    uv_maps: &[uv_map::UvMap],
    w: &mut Warnings,
) -> Result<Geometry, SceneError> {
    let gerr = |element: String, msg: String| SceneError::Gltf { file: file.to_path_buf(), element, msg };
    let nodes = doc.nodes().len();
    if let Some(scene) = doc.default_scene().or_else(|| doc.scenes().next()) {
        if doc.scenes().len() > 1 {
            w.warn(format!("{}: {} scenes; loading scene {} only", file.display(), doc.scenes().len(), scene.index()));
        }
    }
    let roots = scene_roots(doc);
    check_forest(file, doc, &roots)?;

    // Instances (mesh, world matrix) and cameras, in document order.
    let mut instances: Vec<(usize, Mat4)> = Vec::new();
    let mut cameras = Vec::new();
    let mut stack: Vec<(Node, Mat4, usize)> = roots.into_iter().rev().map(|n| (n, Mat4::IDENTITY, 0)).collect();
    while let Some((node, parent, depth)) = stack.pop() {
        let element = || node_element(&node);
        if depth > nodes {
            return Err(gerr(element(), "the node hierarchy has a cycle".into()));
        }
        let world = parent * local_matrix(&node).ok_or_else(|| gerr(element(), "transform is not finite".into()))?;
        if let Some(mesh) = node.mesh() {
            check_size(instances.len() as u64 + 1, 0, 0).map_err(|msg| gerr(element(), msg))?;
            instances.push((mesh.index(), world));
        }
        if node.skin().is_some() {
            w.warn_once("gltf-skin", || format!("{}: {}: skins are not supported; the bind pose is used", file.display(), element()));
        }
        if let Some(cam) = node.camera() {
            match cam.projection() {
                ::gltf::camera::Projection::Perspective(p) => {
                    let name = node.name().or(cam.name()).map_or_else(|| format!("camera {}", cam.index()), str::to_owned);
                    if let Some(a) = p.aspect_ratio().filter(|a| !(a.is_finite() && *a > 0.0)) {
                        w.warn(format!(
                            "{}: {}, camera {} \"{name}\": aspect ratio {a} is not positive; ignored (the image is 1920x1080 unless --width/--height say otherwise)",
                            file.display(),
                            element(),
                            cam.index()
                        ));
                    }
                    cameras.push(Camera::from_gltf(name, world, p.yfov(), p.aspect_ratio()));
                }
                ::gltf::camera::Projection::Orthographic(_) => w.warn_once("gltf-ortho", || {
                    format!("{}: {}: orthographic cameras are not supported; skipped", file.display(), element())
                }),
            }
        }
        let children: Vec<Node> = node.children().collect();
        stack.extend(children.into_iter().rev().map(|c| (c, world, depth + 1)));
    }

    // Each instanced mesh, read once.
    let mut meshes: Vec<Option<Vec<Prim>>> = (0..doc.meshes().len()).map(|_| None).collect();
    let mut used_default = false;
    for &(m, _) in &instances {
        if meshes[m].is_none() {
            let mesh = doc.meshes().nth(m).ok_or_else(|| gerr(format!("mesh {m}"), "does not exist".into()))?;
            let prims = read_mesh(file, &mesh, buffers, default_material, uv_maps, w)?;
            used_default |= prims.iter().any(|p| p.material == default_material);
            meshes[m] = Some(prims);
        }
    }
    let prims_of = |m: usize| meshes[m].as_deref().unwrap_or(&[]);
    let with_normals = instances.iter().any(|&(m, _)| prims_of(m).iter().any(|p| p.normals.is_some()));
    let with_uvs = instances.iter().any(|&(m, _)| prims_of(m).iter().any(|p| p.uvs.is_some()));
    let (mut verts, mut tris) = (0u64, 0u64);
    for &(m, _) in &instances {
        for p in prims_of(m) {
            verts += p.positions.len() as u64;
            tris += p.triangles.len() as u64;
        }
    }
    check_size(instances.len() as u64, tris, verts).map_err(|msg| gerr("scene".into(), msg))?;
    let (verts, tris) = (verts as usize, tris as usize);
    // Tangents from the file where every part has them (else all are generated from the UVs).
    let with_tangents = instances.iter().all(|&(m, _)| prims_of(m).iter().all(|p| p.tangents.is_some()));
    let mut b = Builder::new(with_normals, with_uvs);
    if with_tangents && with_uvs {
        b = b.with_tangents();
    }
    b.reserve(verts, tris);
    for &(m, world) in &instances {
        let xf = (world != Mat4::IDENTITY).then(|| Transform::new(world));
        for p in prims_of(m) {
            let part = Part {
                positions: &p.positions,
                normals: p.normals.as_deref(),
                uvs: p.uvs.as_deref(),
                tangents: p.tangents.as_deref(),
                triangles: &p.triangles,
                material: p.material,
            };
            b.push(&part, xf.as_ref());
        }
    }
    Ok((b, cameras, used_default))
}

/// The flattened scene's size against the limits, before it is allocated.
fn check_size(instances: u64, tris: u64, verts: u64) -> Result<(), String> {
    if instances > MAX_INSTANCES {
        return Err(format!("{} mesh instances, over the limit of {}", thousands(instances), thousands(MAX_INSTANCES)));
    }
    if tris > MAX_TRIANGLES || verts > 3 * MAX_TRIANGLES {
        return Err(format!(
            "{} instances of its meshes make {} triangles ({} vertices), over the limit of {} triangles",
            thousands(instances),
            thousands(tris),
            thousands(verts),
            thousands(MAX_TRIANGLES)
        ));
    }
    Ok(())
}

/// The node's local matrix; `None` if not finite. Rotations are normalised (exporters write
/// quaternions that are only nearly unit length).
/// The root nodes of the scene loaded: the default scene's, else the first scene's, else
/// every node that is no node's child.
fn scene_roots(doc: &Document) -> Vec<Node<'_>> {
    match doc.default_scene().or_else(|| doc.scenes().next()) {
        Some(scene) => scene.nodes().collect(),
        None => {
            let mut is_child = vec![false; doc.nodes().len()];
            for n in doc.nodes() {
                for c in n.children() {
                    is_child[c.index()] = true;
                }
            }
            doc.nodes().filter(|n| !is_child[n.index()]).collect()
        }
    }
}

fn local_matrix(node: &Node) -> Option<Mat4> {
    let m = match node.transform() {
        ::gltf::scene::Transform::Matrix { matrix } => Mat4::from_cols_array_2d(&matrix),
        ::gltf::scene::Transform::Decomposed { translation, rotation, scale } => {
            let q = Quat::from_array(rotation);
            let q = if q.length_squared() > 0.0 { q.normalize() } else { Quat::IDENTITY };
            Mat4::from_scale_rotation_translation(Vec3::from(scale), q, Vec3::from(translation))
        }
    };
    m.is_finite().then_some(m)
}

fn read_mesh(
    file: &Path,
    mesh: &::gltf::Mesh,
    buffers: &[Vec<u8>],
    default_material: u32,
    uv_maps: &[uv_map::UvMap],
    w: &mut Warnings,
) -> Result<Vec<Prim>, SceneError> {
    let mesh_name = mesh.name().map_or(String::new(), |n| format!(" \"{}\"", crate::text::quote(n)));
    let mut out = Vec::new();
    for (pi, prim) in mesh.primitives().enumerate() {
        let element = format!("mesh {}{mesh_name}, primitive {pi}", mesh.index());
        let mode = prim.mode();
        if !matches!(mode, Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan) {
            w.warn_once(&format!("gltf-mode-{mode:?}"), || {
                format!("{}: {element}: {mode:?} primitives are not rendered; skipped", file.display())
            });
            continue;
        }
        let read_err = |acc: &::gltf::Accessor, what: &str, e: AccessorError| match e {
            AccessorError::Unsupported(what_) => SceneError::Unsupported {
                file: file.to_path_buf(),
                element: format!("{element}, accessor {} ({what})", acc.index()),
                what: what_,
            },
            AccessorError::Bad(msg) => {
                SceneError::Gltf { file: file.to_path_buf(), element: format!("{element}, accessor {} ({what})", acc.index()), msg }
            }
        };
        let Some(pos_acc) = prim.get(&Semantic::Positions) else {
            w.warn(format!("{}: {element}: no POSITION attribute; skipped", file.display()));
            continue;
        };
        let positions = read_vec3(&pos_acc, buffers, Attribute::Position).map_err(|e| read_err(&pos_acc, "POSITION", e))?;
        let same_count = |acc: &::gltf::Accessor, what: &str| {
            if acc.count() != positions.len() {
                Err(read_err(acc, what, AccessorError::Bad(format!("{} elements, but POSITION has {}", acc.count(), positions.len()))))
            } else {
                Ok(())
            }
        };
        let normals = match prim.get(&Semantic::Normals) {
            Some(acc) => {
                same_count(&acc, "NORMAL")?;
                Some(read_vec3(&acc, buffers, Attribute::Normal).map_err(|e| read_err(&acc, "NORMAL", e))?)
            }
            None => None,
        };
        // The material's texture coordinate set and transform (uv_map.rs), baked in.
        let material = prim.material().index().map_or(default_material, |i| i as u32);
        let map = uv_maps.get(material as usize).copied().unwrap_or_default();
        let mut set = map.tex_coord;
        if set != 0 && prim.get(&Semantic::TexCoords(set)).is_none() {
            w.warn(format!("{}: {element}: its material reads TEXCOORD_{set}, which it lacks; TEXCOORD_0 is used", file.display()));
            set = 0;
        }
        let uvs = match prim.get(&Semantic::TexCoords(set)) {
            Some(acc) => {
                let what = format!("TEXCOORD_{set}");
                same_count(&acc, &what)?;
                let uvs = read_uv(&acc, buffers).map_err(|e| read_err(&acc, &what, e))?;
                Some(if map.transform == glam::Mat3::IDENTITY { uvs } else { uvs.into_iter().map(|uv| map.apply(uv)).collect() })
            }
            None => None,
        };
        let tangents = match prim.get(&Semantic::Tangents) {
            Some(acc) if normals.is_some() => {
                same_count(&acc, "TANGENT")?;
                Some(read_vec4(&acc, buffers).map_err(|e| read_err(&acc, "TANGENT", e))?)
            }
            _ => None,
        };
        for (semantic, _) in prim.attributes() {
            match semantic {
                Semantic::Colors(_) => {
                    w.warn_once("gltf-colors", || format!("{}: {element}: vertex colours are not supported; ignored", file.display()))
                }
                Semantic::Joints(_) | Semantic::Weights(_) => {
                    w.warn_once("gltf-skin", || format!("{}: {element}: skinning is not supported; the bind pose is used", file.display()))
                }
                _ => {}
            }
        }
        if prim.morph_targets().len() > 0 {
            w.warn_once("gltf-morph", || format!("{}: {element}: morph targets are not supported; the base shape is used", file.display()));
        }
        let indices: Vec<u32> = match prim.indices() {
            Some(acc) => read_indices(&acc, buffers, positions.len()).map_err(|e| read_err(&acc, "indices", e))?,
            None => (0..positions.len() as u32).collect(),
        };
        let triangles = assemble(mode, &indices);
        if mode == Mode::Triangles && indices.len() % 3 != 0 {
            w.warn(format!(
                "{}: {element}: {} indices is not a multiple of 3; the last {} ignored",
                file.display(),
                indices.len(),
                indices.len() % 3
            ));
        }
        out.push(Prim { positions, normals, uvs, tangents, triangles, material });
    }
    Ok(out)
}

/// Triangles of a triangle list, strip or fan (glTF 2.0 §3.7.2.1 orders).
fn assemble(mode: Mode, idx: &[u32]) -> Vec<[u32; 3]> {
    match mode {
        Mode::TriangleStrip => (0..idx.len().saturating_sub(2))
            .map(|i| if i % 2 == 0 { [idx[i], idx[i + 1], idx[i + 2]] } else { [idx[i + 1], idx[i], idx[i + 2]] })
            .collect(),
        Mode::TriangleFan => (1..idx.len().saturating_sub(1)).map(|i| [idx[i], idx[i + 1], idx[0]]).collect(),
        _ => idx.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strips_and_fans_keep_the_winding() {
        assert_eq!(assemble(Mode::Triangles, &[0, 1, 2, 3, 4, 5, 6]), vec![[0, 1, 2], [3, 4, 5]]);
        assert_eq!(assemble(Mode::TriangleStrip, &[0, 1, 2, 3]), vec![[0, 1, 2], [2, 1, 3]]);
        assert_eq!(assemble(Mode::TriangleFan, &[0, 1, 2, 3]), vec![[1, 2, 0], [2, 3, 0]]);
        assert!(assemble(Mode::TriangleStrip, &[0, 1]).is_empty());
    }

    #[test]
    fn size_limits() {
        assert!(check_size(1000, 1 << 20, 1 << 20).is_ok());
        let e = check_size(1 << 20, 1 << 40, 1 << 41).unwrap_err();
        assert!(e.contains("1,099,511,627,776 triangles") && e.contains("limit of 268,435,456"), "{e}");
        let e = check_size(1 << 30, 1 << 30, 1 << 30).unwrap_err();
        assert!(e.contains("1,073,741,824 mesh instances, over the limit of 16,777,216"), "{e}");
    }
}
