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

/// A VEC3 of floats (POSITION, NORMAL); NaN or Inf is an error.
pub(super) fn read_vec3(acc: &Accessor, buffers: &[Vec<u8>]) -> Result<Vec<Vec3>> {
    let (d, stride, count, _) = view(acc, buffers, Dimensions::Vec3, &[DataType::F32])?;
    let mut out = Vec::with_capacity(count);
    for i in 0..count {
        let o = i * stride;
        let v = Vec3::new(f32_at(d, o), f32_at(d, o + 4), f32_at(d, o + 8));
        if !v.is_finite() {
            return bad(format!("element {i} is not finite ({v})"));
        }
        out.push(v);
    }
    Ok(out)
}

/// A VEC4 of floats (TANGENT: xyz and the handedness w); NaN or Inf is an error.
pub(super) fn read_vec4(acc: &Accessor, buffers: &[Vec<u8>]) -> Result<Vec<Vec4>> {
    let (d, stride, count, _) = view(acc, buffers, Dimensions::Vec4, &[DataType::F32])?;
    let mut out = Vec::with_capacity(count);
    for i in 0..count {
        let o = i * stride;
        let v = Vec4::new(f32_at(d, o), f32_at(d, o + 4), f32_at(d, o + 8), f32_at(d, o + 12));
        if !v.is_finite() {
            return bad(format!("element {i} is not finite ({v})"));
        }
        out.push(v);
    }
    Ok(out)
}

/// TEXCOORD_n: floats, or normalised unsigned bytes/shorts.
pub(super) fn read_uv(acc: &Accessor, buffers: &[Vec<u8>]) -> Result<Vec<Vec2>> {
    let (d, stride, count, ty) = view(acc, buffers, Dimensions::Vec2, &[DataType::F32, DataType::U8, DataType::U16])?;
    if ty != DataType::F32 && !acc.normalized() {
        return bad(format!("integer texture coordinates ({ty:?}) must be normalized"));
    }
    let mut out = Vec::with_capacity(count);
    for i in 0..count {
        let o = i * stride;
        let uv = match ty {
            DataType::U8 => Vec2::new(d[o] as f32, d[o + 1] as f32) / 255.0,
            DataType::U16 => {
                Vec2::new(u16::from_le_bytes([d[o], d[o + 1]]) as f32, u16::from_le_bytes([d[o + 2], d[o + 3]]) as f32) / 65535.0
            }
            _ => Vec2::new(f32_at(d, o), f32_at(d, o + 4)),
        };
        if !uv.is_finite() {
            return bad(format!("element {i} is not finite ({uv})"));
        }
        out.push(uv);
    }
    Ok(out)
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
