//! Reading accessors: every type, count, stride and byte range is checked against the
//! buffers before a byte is read, so a malformed file is an error naming the accessor, never
//! an out-of-bounds panic (the `gltf` crate's own reader assumes a well-formed file). One
//! tight loop per attribute, straight into the output `Vec`.

use ::gltf::accessor::{Accessor, DataType, Dimensions};
use glam::{Vec2, Vec3, Vec4};

/// Why an accessor cannot be read; the caller adds which element it is.
pub(super) enum AccessorError {
    Unsupported(String),
    Bad(String),
}

type Result<T> = std::result::Result<T, AccessorError>;

fn bad<T>(msg: String) -> Result<T> {
    Err(AccessorError::Bad(msg))
}

/// The bytes of `acc`: (data starting at element 0, stride, count, component type).
fn view<'b>(acc: &Accessor, buffers: &'b [Vec<u8>], dims: Dimensions, types: &[DataType]) -> Result<(&'b [u8], usize, usize, DataType)> {
    if acc.sparse().is_some() {
        return Err(AccessorError::Unsupported("a sparse accessor".into()));
    }
    if acc.dimensions() != dims {
        return bad(format!("type is {:?}, expected {dims:?}", acc.dimensions()));
    }
    let ty = acc.data_type();
    if !types.contains(&ty) {
        return bad(format!("component type {ty:?} is not one of {types:?}"));
    }
    let Some(view) = acc.view() else {
        return Err(AccessorError::Unsupported("an accessor without a bufferView (Draco-compressed or sparse-only data)".into()));
    };
    let count = acc.count();
    if count == 0 {
        return Ok((&[], 0, 0, ty));
    }
    let elem = dims.multiplicity() * ty.size();
    let stride = view.stride().unwrap_or(elem);
    if stride < elem {
        return bad(format!("byteStride {stride} is smaller than an element ({elem} bytes)"));
    }
    let Some(buf) = buffers.get(view.buffer().index()) else {
        return bad(format!("buffer {} does not exist", view.buffer().index()));
    };
    let start = view.offset().checked_add(acc.offset());
    let span = (count - 1).checked_mul(stride).and_then(|s| s.checked_add(elem));
    let view_end = view.offset().checked_add(view.length());
    match (start, span, view_end) {
        (Some(start), Some(span), Some(view_end)) if start.checked_add(span).is_some_and(|end| end <= view_end && end <= buf.len()) => {
            Ok((&buf[start..start + span], stride, count, ty))
        }
        _ => bad(format!(
            "{count} elements of {elem} bytes (stride {stride}) from byte {} of bufferView {} run past its end ({} bytes, buffer of {})",
            acc.offset(),
            view.index(),
            view.length(),
            buf.len()
        )),
    }
}

fn f32_at(d: &[u8], o: usize) -> f32 {
    f32::from_le_bytes([d[o], d[o + 1], d[o + 2], d[o + 3]])
}

/// Which attribute a vector accessor holds: the component types glTF allows for it, the core
/// specification's (floats; normalised unsigned bytes and shorts for texture coordinates) and
/// KHR_mesh_quantization's (§ "Extending Mesh Attributes": every integer type for positions
/// and texture coordinates, normalised or not; normalised signed bytes and shorts for normals
/// and tangents).
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Attribute {
    Position,
    Normal,
    Tangent,
    TexCoord,
}

impl Attribute {
    fn dimensions(self) -> Dimensions {
        match self {
            Attribute::Position | Attribute::Normal => Dimensions::Vec3,
            Attribute::Tangent => Dimensions::Vec4,
            Attribute::TexCoord => Dimensions::Vec2,
        }
    }

    fn types(self) -> &'static [DataType] {
        match self {
            Attribute::Position | Attribute::TexCoord => &[DataType::F32, DataType::I8, DataType::U8, DataType::I16, DataType::U16],
            Attribute::Normal | Attribute::Tangent => &[DataType::F32, DataType::I8, DataType::I16],
        }
    }

    /// Whether integer components must be normalised (they are directions).
    fn needs_normalized(self) -> bool {
        matches!(self, Attribute::Normal | Attribute::Tangent)
    }
}

/// Component `k` of element data at byte `o` as a float: floats as they are, integers as
/// their value or, `normalized`, by glTF 2.0 §3.11's rule (unsigned c / (2^n - 1), signed
/// max(c / (2^(n-1) - 1), -1)).
fn component(d: &[u8], o: usize, k: usize, ty: DataType, normalized: bool) -> f32 {
    let (value, scale) = match ty {
        DataType::F32 => return f32_at(d, o + 4 * k),
        DataType::I8 => (d[o + k] as i8 as f32, 127.0),
        DataType::U8 => (d[o + k] as f32, 255.0),
        DataType::I16 => (i16::from_le_bytes([d[o + 2 * k], d[o + 2 * k + 1]]) as f32, 32767.0),
        DataType::U16 => (u16::from_le_bytes([d[o + 2 * k], d[o + 2 * k + 1]]) as f32, 65535.0),
        DataType::U32 => (u32::from_le_bytes([d[o + 4 * k], d[o + 4 * k + 1], d[o + 4 * k + 2], d[o + 4 * k + 3]]) as f32, u32::MAX as f32),
    };
    if normalized {
        (value / scale).max(-1.0)
    } else {
        value
    }
}

/// The elements of a vector accessor holding `attr` as floats (`N` components each, the
/// attribute's dimensions); NaN or Inf is an error.
fn read_vectors<const N: usize>(acc: &Accessor, buffers: &[Vec<u8>], attr: Attribute) -> Result<Vec<[f32; N]>> {
    debug_assert_eq!(attr.dimensions().multiplicity(), N);
    let (d, stride, count, ty) = view(acc, buffers, attr.dimensions(), attr.types())?;
    let normalized = acc.normalized();
    if ty != DataType::F32 && attr.needs_normalized() && !normalized {
        return bad(format!("integer directions ({ty:?}) must be normalized"));
    }
    let mut out = Vec::with_capacity(count);
    for i in 0..count {
        let o = i * stride;
        let v: [f32; N] = std::array::from_fn(|k| component(d, o, k, ty, normalized));
        if !v.iter().all(|x| x.is_finite()) {
            return bad(format!("element {i} is not finite ({v:?})"));
        }
        out.push(v);
    }
    Ok(out)
}

/// POSITION or NORMAL: floats, or KHR_mesh_quantization's integers.
pub(super) fn read_vec3(acc: &Accessor, buffers: &[Vec<u8>], attr: Attribute) -> Result<Vec<Vec3>> {
    debug_assert!(matches!(attr, Attribute::Position | Attribute::Normal));
    Ok(read_vectors::<3>(acc, buffers, attr)?.into_iter().map(Vec3::from_array).collect())
}

/// TANGENT (xyz and the handedness w): floats, or normalised signed bytes or shorts.
pub(super) fn read_vec4(acc: &Accessor, buffers: &[Vec<u8>]) -> Result<Vec<Vec4>> {
    Ok(read_vectors::<4>(acc, buffers, Attribute::Tangent)?.into_iter().map(Vec4::from_array).collect())
}

/// TEXCOORD_n: floats or integers (KHR_mesh_quantization; the core specification's
/// normalised unsigned bytes and shorts among them).
pub(super) fn read_uv(acc: &Accessor, buffers: &[Vec<u8>]) -> Result<Vec<Vec2>> {
    Ok(read_vectors::<2>(acc, buffers, Attribute::TexCoord)?.into_iter().map(Vec2::from_array).collect())
}

/// Indices, each checked against the primitive's vertex count.
pub(super) fn read_indices(acc: &Accessor, buffers: &[Vec<u8>], vertices: usize) -> Result<Vec<u32>> {
    let (d, stride, count, ty) = view(acc, buffers, Dimensions::Scalar, &[DataType::U8, DataType::U16, DataType::U32])?;
    let mut out = Vec::with_capacity(count);
    for i in 0..count {
        let o = i * stride;
        let v = match ty {
            DataType::U8 => d[o] as u32,
            DataType::U16 => u16::from_le_bytes([d[o], d[o + 1]]) as u32,
            _ => u32::from_le_bytes([d[o], d[o + 1], d[o + 2], d[o + 3]]),
        };
        if v as usize >= vertices {
            return bad(format!("index {v} (element {i}) is out of range: the primitive has {vertices} vertices"));
        }
        out.push(v);
    }
    Ok(out)
}
