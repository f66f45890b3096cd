//! Buffers and image locations of a glTF file: the GLB binary chunk, `data:` URIs (base64,
//! decoded by the `gltf` crate) and relative file URIs (percent-decoded here: the crate's own
//! decoder panics on malformed escapes).

use std::path::{Path, PathBuf};

use ::gltf::Document;

use crate::scene::SceneError;

/// Where a URI points.
pub(super) enum Uri {
    Data(Vec<u8>),
    File(PathBuf),
}

/// Resolves `uri` against the directory of the glTF file.
pub(super) fn resolve(uri: &str, base: &Path) -> Result<Uri, String> {
    if uri.starts_with("data:") {
        let data = ::gltf::buffer::Data::from_source(::gltf::buffer::Source::Uri(uri), None).map_err(|e| format!("bad data URI: {e}"))?;
        return Ok(Uri::Data(data.0));
    }
    let path = if let Some(rest) = uri.strip_prefix("file://").or_else(|| uri.strip_prefix("file:")) {
        PathBuf::from(percent_decode(rest))
    } else if uri.contains("://") {
        return Err(format!("URI scheme of '{uri}' is not supported (only relative files and data: URIs)"));
    } else {
        base.join(percent_decode(uri))
    };
    Ok(Uri::File(path))
}

/// `%20` → space; a malformed escape is kept as written.
fn percent_decode(s: &str) -> String {
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        let hex = |c: u8| (c as char).to_digit(16);
        if b[i] == b'%' && i + 2 < b.len() {
            if let (Some(h), Some(l)) = (hex(b[i + 1]), hex(b[i + 2])) {
                out.push((h * 16 + l) as u8);
                i += 3;
                continue;
            }
        }
        out.push(b[i]);
        i += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// Every buffer's bytes, checked against its declared length. A buffer that cannot be read
/// is an error: the geometry in it cannot be loaded.
pub(super) fn load_buffers(file: &Path, doc: &Document, base: &Path, mut blob: Option<Vec<u8>>) -> Result<Vec<Vec<u8>>, SceneError> {
    let mut out = Vec::new();
    for buffer in doc.buffers() {
        let element = format!("buffer {}", buffer.index());
        let err = |msg: String| SceneError::Gltf { file: file.to_path_buf(), element: element.clone(), msg };
        let data = match buffer.source() {
            ::gltf::buffer::Source::Bin => blob.take().ok_or_else(|| err("refers to the GLB binary chunk, which is missing".into()))?,
            ::gltf::buffer::Source::Uri(uri) => match resolve(uri, base).map_err(&err)? {
                Uri::Data(d) => d,
                Uri::File(path) => std::fs::read(&path).map_err(|e| err(format!("cannot read '{uri}' ({}): {e}", path.display())))?,
            },
        };
        if data.len() < buffer.length() {
            return Err(err(format!("has {} bytes, the file declares {}", data.len(), buffer.length())));
        }
        out.push(data);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn percent_decoding() {
        assert_eq!(percent_decode("a%20b.png"), "a b.png");
        assert_eq!(percent_decode("100%"), "100%");
        assert_eq!(percent_decode("%zz%4"), "%zz%4");
        assert_eq!(percent_decode("%C3%A9"), "é");
    }

    #[test]
    fn uris() {
        let base = Path::new("/scenes");
        assert!(matches!(resolve("tex/a%20b.png", base), Ok(Uri::File(p)) if p == Path::new("/scenes/tex/a b.png")));
        assert!(matches!(resolve("data:application/octet-stream;base64,AAEC", base), Ok(Uri::Data(d)) if d[..3] == [0, 1, 2]));
        assert!(resolve("https://example.com/a.bin", base).is_err());
        assert!(resolve("data:application/octet-stream;base64,@@@", base).is_err());
    }
}
