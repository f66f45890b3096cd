//! Why a scene could not be loaded. Every variant names the file, and the line (OBJ, MTL) or
//! the element (glTF: mesh, primitive, accessor, node, ...), so a user can find the fault.

use std::path::{Path, PathBuf};

/// A scene that cannot be used. Degenerate triangles, unsupported-but-ignorable features and
/// (unless `strict`) missing material libraries or textures are *warnings*, not errors.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    #[error("{}: cannot read: {source}", shown(file))]
    Io {
        file: PathBuf,
        #[source]
        source: std::io::Error,
    },
    /// A malformed OBJ or MTL line (1-based line number).
    #[error("{}:{line}: {msg}", shown(file))]
    Syntax { file: PathBuf, line: usize, msg: String },
    /// A file the parser rejected as a whole (no line number known).
    #[error("{}: {msg}", shown(file))]
    Parse { file: PathBuf, msg: String },
    /// A glTF element that cannot be read; `element` says which (e.g. `mesh 2 "Roof",
    /// primitive 0, accessor 7 (POSITION)`).
    #[error("{}: {element}: {msg}", shown(file))]
    Gltf { file: PathBuf, element: String, msg: String },
    /// A feature the loader cannot read and cannot skip (Draco, sparse accessors, ...).
    #[error("{}: {element}: {what} is not supported", shown(file))]
    Unsupported { file: PathBuf, element: String, what: String },
    /// With `strict`: a referenced file (material library, texture) does not exist.
    #[error("{}:{line}: {what} '{}' not found (looked for {})", shown(file), name, shown(missing))]
    Missing { file: PathBuf, line: usize, what: &'static str, name: String, missing: PathBuf },
    /// With `strict`: a glTF image that does not exist, or an image that cannot be decoded.
    /// `at` says where it was referenced (`room.mtl:7`, `scene.gltf: image 3 "wall"`).
    #[error("{}: {msg}", crate::text::sanitize(at))]
    Texture { file: PathBuf, at: String, msg: String },
    /// With `strict`: `usemtl` names a material no material library defines.
    #[error("{}:{line}: unknown material '{name}'", shown(file))]
    UnknownMaterial { file: PathBuf, line: usize, name: String },
    /// Nothing to render.
    #[error("{}: the scene has no triangles{}", shown(file), if *dropped > 0 { format!(" (all {dropped} were degenerate)") } else { String::new() })]
    Empty { file: PathBuf, dropped: usize },
    #[error("{}: unknown scene format (expected .obj, .gltf or .glb)", shown(file))]
    UnknownFormat { file: PathBuf },
    /// A camera that cannot form an image (eye == target, up parallel to the view, ...).
    #[error("camera '{name}': {msg}")]
    Camera { name: String, msg: String },
}

impl SceneError {
    /// The file the error is about (for `Camera`, none).
    pub fn file(&self) -> Option<&Path> {
        match self {
            SceneError::Io { file, .. }
            | SceneError::Syntax { file, .. }
            | SceneError::Parse { file, .. }
            | SceneError::Gltf { file, .. }
            | SceneError::Unsupported { file, .. }
            | SceneError::Missing { file, .. }
            | SceneError::Texture { file, .. }
            | SceneError::UnknownMaterial { file, .. }
            | SceneError::Empty { file, .. }
            | SceneError::UnknownFormat { file } => Some(file),
            SceneError::Camera { .. } => None,
        }
    }

    /// The 1-based line of an OBJ/MTL error, where there is one.
    pub fn line(&self) -> Option<usize> {
        match self {
            SceneError::Syntax { line, .. } | SceneError::Missing { line, .. } | SceneError::UnknownMaterial { line, .. } => Some(*line),
            _ => None,
        }
    }

    /// A line error; its message quotes the line, so it is escaped and truncated here.
    pub(crate) fn syntax(file: &Path, line: usize, msg: impl Into<String>) -> Self {
        SceneError::Syntax { file: file.to_path_buf(), line, msg: crate::text::sanitize(&msg.into()) }
    }

    pub(crate) fn io(file: &Path, source: std::io::Error) -> Self {
        SceneError::Io { file: file.to_path_buf(), source }
    }
}

/// A file's path as a message shows it: control characters escaped (`text::path`), since a path
/// can come from the scene itself (a material library or texture named by an `mtllib` or
/// `map_Kd` statement with control characters or a NUL in it) and the message must stay one
/// readable line.
fn shown(file: &Path) -> String {
    crate::text::path(file)
}
