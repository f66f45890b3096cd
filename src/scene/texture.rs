//! Texture decoding: every image a scene needs becomes an RGBA8 [`Texture`], decoded in
//! parallel (one worker per core, `std::thread::scope`) because decoding dominates load time
//! (Sponza: two dozen 1024² PNGs).
//!
//! Roles decide the encoding: colour (base colour, `map_Kd`) stays sRGB-encoded and is
//! flagged `srgb` so it is linearised when sampled (on the GPU: an `_SRGB` image format);
//! opacity (`map_d`) is data and linear — an image without an alpha channel gives its
//! luminance as alpha. Alpha is never sRGB-encoded, so an alpha mask may read a colour
//! texture's alpha directly. Float images (HDR) are linear and stored clamped to [0, 1].
//! Textures are not downsampled or capped: Sponza's 24 colour textures take 96 MiB.

use crate::limits::{thousands, MAX_TEXTURE_PIXELS};
use std::collections::HashMap;
use std::io::Cursor;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};

use image::{DynamicImage, ImageFormat, ImageReader};

use super::warnings::Warnings;
use super::{Material, SceneError, Texture};

/// The sRGB transfer function, inverted: an 8-bit sRGB-encoded value to linear [0, 1].
pub fn srgb_to_linear(v: u8) -> f32 {
    let c = v as f32 / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Role {
    /// sRGB colour (albedo).
    Colour,
    /// Linear opacity in alpha (alpha mask).
    Opacity,
    /// Linear data in every channel (metallic-roughness, `map_Pr`, `map_Pm`); a grey image
    /// gives its value in R, G and B.
    Linear,
}

pub(crate) enum Source<'a> {
    File(PathBuf),
    /// Bytes inside a glTF buffer, with the declared MIME type.
    Memory {
        bytes: &'a [u8],
        mime: Option<String>,
    },
    /// Bytes decoded from a `data:` URI.
    Owned {
        bytes: Vec<u8>,
        mime: Option<String>,
    },
}

/// One texture a material asked for.
pub(crate) struct Request<'a> {
    pub name: String,
    pub source: Source<'a>,
    pub role: Role,
    /// Where it was referenced, for messages: `room.mtl:7` or `Sponza.gltf: image 3 "x"`.
    pub at: String,
    /// The file the reference is in (for [`SceneError::file`]), and its line if textual.
    pub file: PathBuf,
    pub line: Option<usize>,
}

enum Failure {
    Missing(PathBuf),
    Bad(String),
}

/// Requests, de-duplicated by (key, role): a texture used by ten materials is decoded once.
#[derive(Default)]
pub(crate) struct Requests<'a> {
    list: Vec<Request<'a>>,
    index: HashMap<(String, Role), u32>,
}

impl<'a> Requests<'a> {
    /// The provisional index of the texture `key` in `role`; `make` builds the request the
    /// first time. Indices are final only after [`Requests::decode`] (failures are removed).
    pub fn request(&mut self, key: String, role: Role, make: impl FnOnce() -> Request<'a>) -> u32 {
        let list = &mut self.list;
        *self.index.entry((key, role)).or_insert_with(|| {
            list.push(make());
            (list.len() - 1) as u32
        })
    }

    /// Decodes every request in parallel. Failures are warnings (the material loses the
    /// texture) or, with `strict`, the first failure is the error.
    pub fn decode(self, strict: bool, w: &mut Warnings) -> Result<Decoded, SceneError> {
        let results = decode_all(&self.list);
        let mut textures = Vec::new();
        let mut remap = Vec::with_capacity(results.len());
        for (req, result) in self.list.iter().zip(results) {
            match result {
                Ok(t) => {
                    remap.push(Some(textures.len() as u32));
                    textures.push(t);
                }
                Err(f) => {
                    let (err, msg) = match f {
                        Failure::Missing(path) => (
                            match req.line {
                                Some(line) => SceneError::Missing {
                                    file: req.file.clone(),
                                    line,
                                    what: "texture",
                                    name: crate::text::quote(&req.name),
                                    missing: path.clone(),
                                },
                                None => SceneError::Texture {
                                    file: req.file.clone(),
                                    at: req.at.clone(),
                                    msg: format!(
                                        "image '{}' not found (looked for {})",
                                        crate::text::quote(&req.name),
                                        crate::text::path(&path)
                                    ),
                                },
                            },
                            format!("{}: texture '{}' not found (looked for {}); using none", req.at, req.name, path.display()),
                        ),
                        Failure::Bad(why) => (
                            SceneError::Texture {
                                file: req.file.clone(),
                                at: req.at.clone(),
                                msg: format!("cannot decode texture '{}': {}", crate::text::quote(&req.name), crate::text::sanitize(&why)),
                            },
                            format!("{}: cannot decode texture '{}': {why}; using none", req.at, req.name),
                        ),
                    };
                    if strict {
                        return Err(err);
                    }
                    w.warn(msg);
                    remap.push(None);
                }
            }
        }
        Ok(Decoded { textures, remap })
    }
}

/// Decoded textures and where each provisional index went.
pub(crate) struct Decoded {
    pub textures: Vec<Texture>,
    remap: Vec<Option<u32>>,
}

impl Decoded {
    /// Points materials at the final texture indices; a failed albedo texture leaves the
    /// colour alone, a failed alpha mask makes the material opaque.
    pub fn apply(&self, materials: &mut [Material]) {
        for m in materials {
            m.albedo_texture = m.albedo_texture.and_then(|t| self.remap[t as usize]);
            m.roughness_texture = m.roughness_texture.and_then(|t| self.remap[t as usize]);
            m.emission_texture = m.emission_texture.and_then(|t| self.remap[t as usize]);
            m.normal_texture = m.normal_texture.and_then(|t| self.remap[t as usize]);
            m.metallic_texture = m.metallic_texture.and_then(|t| self.remap[t as usize]);
            m.transmission_texture = m.transmission_texture.and_then(|t| self.remap[t as usize]);
            m.specular_texture = m.specular_texture.and_then(|t| self.remap[t as usize]);
            m.specular_colour_texture = m.specular_colour_texture.and_then(|t| self.remap[t as usize]);
            m.alpha = m.alpha.and_then(|a| self.remap[a.texture as usize].map(|t| super::AlphaMask { texture: t, ..a }));
        }
    }
}

fn decode_all(reqs: &[Request]) -> Vec<Result<Texture, Failure>> {
    let one = |r: &Request| {
        catch_unwind(AssertUnwindSafe(|| decode_request(r))).unwrap_or_else(|_| Err(Failure::Bad("the image decoder panicked".into())))
    };
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get()).min(reqs.len());
    if threads <= 1 {
        return reqs.iter().map(one).collect();
    }
    let next = AtomicUsize::new(0);
    let mut out: Vec<Option<Result<Texture, Failure>>> = (0..reqs.len()).map(|_| None).collect();
    std::thread::scope(|s| {
        let workers: Vec<_> = (0..threads)
            .map(|_| {
                s.spawn(|| {
                    let mut done = Vec::new();
                    loop {
                        let i = next.fetch_add(1, Ordering::Relaxed);
                        let Some(r) = reqs.get(i) else { break };
                        done.push((i, one(r)));
                    }
                    done
                })
            })
            .collect();
        for w in workers {
            // `one` catches decoder panics, so a worker cannot panic.
            if let Ok(done) = w.join() {
                for (i, r) in done {
                    out[i] = Some(r);
                }
            }
        }
    });
    out.into_iter().map(|r| r.unwrap_or_else(|| Err(Failure::Bad("not decoded".into())))).collect()
}

fn decode_request(r: &Request) -> Result<Texture, Failure> {
    let (bytes, hint);
    let data: &[u8] = match &r.source {
        Source::File(path) => {
            bytes = match std::fs::read(path) {
                Ok(b) => b,
                Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Err(Failure::Missing(path.clone())),
                Err(e) => return Err(Failure::Bad(e.to_string())),
            };
            hint = ImageFormat::from_path(path).ok();
            &bytes
        }
        Source::Memory { bytes, mime } => {
            hint = mime.as_deref().and_then(ImageFormat::from_mime_type);
            bytes
        }
        Source::Owned { bytes, mime } => {
            hint = mime.as_deref().and_then(ImageFormat::from_mime_type);
            bytes
        }
    };
    decode(data, hint, r.role, &r.name).map_err(Failure::Bad)
}

/// Decodes one image (format from its content, else from `hint`) into a texture for `role`.
pub(crate) fn decode(bytes: &[u8], hint: Option<ImageFormat>, role: Role, name: &str) -> Result<Texture, String> {
    let mut reader = ImageReader::new(Cursor::new(bytes));
    if let Some(f) = hint {
        reader.set_format(f);
    }
    let reader = reader.with_guessed_format().map_err(|e| e.to_string())?;
    let Some(format) = reader.format() else {
        return Err("unknown image format".into());
    };
    // The header's size first: decoding allocates what it claims.
    let (w, h) = ImageReader::with_format(Cursor::new(bytes), format).into_dimensions().map_err(|e| e.to_string())?;
    if w as u64 * h as u64 > MAX_TEXTURE_PIXELS {
        return Err(format!("{w}x{h} pixels is over the limit of {} pixels per texture", thousands(MAX_TEXTURE_PIXELS)));
    }
    let img = reader.decode().map_err(|e| e.to_string())?;
    let (width, height) = (img.width(), img.height());
    let is_float = matches!(img, DynamicImage::ImageRgb32F(_) | DynamicImage::ImageRgba32F(_));
    let (rgba8, srgb) = match role {
        Role::Colour => (img.into_rgba8().into_raw(), !is_float),
        Role::Opacity if img.color().has_alpha() => (img.into_rgba8().into_raw(), false),
        Role::Linear => (img.into_rgba8().into_raw(), false),
        Role::Opacity => {
            let luma = img.into_luma8().into_raw();
            (luma.iter().flat_map(|&l| [l, l, l, l]).collect(), false)
        }
    };
    Ok(Texture { name: name.to_owned(), width, height, rgba8, srgb })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn png(img: DynamicImage) -> Vec<u8> {
        let mut out = Vec::new();
        img.write_to(&mut Cursor::new(&mut out), ImageFormat::Png).unwrap();
        out
    }

    #[test]
    fn srgb_curve_endpoints_and_midpoint() {
        assert_eq!(srgb_to_linear(0), 0.0);
        assert!((srgb_to_linear(255) - 1.0).abs() < 1e-6);
        // sRGB 188 is about linear 0.5.
        assert!((srgb_to_linear(188) - 0.5).abs() < 0.005, "{}", srgb_to_linear(188));
    }

    #[test]
    fn colour_is_srgb_opacity_is_linear_with_luminance_alpha() {
        let grey = png(DynamicImage::ImageLuma8(image::GrayImage::from_raw(2, 1, vec![10, 200]).unwrap()));
        let c = decode(&grey, None, Role::Colour, "g").unwrap();
        assert!(c.srgb);
        assert_eq!(c.rgba8, vec![10, 10, 10, 255, 200, 200, 200, 255]);
        let o = decode(&grey, None, Role::Opacity, "g").unwrap();
        assert!(!o.srgb);
        assert_eq!(o.rgba8, vec![10, 10, 10, 10, 200, 200, 200, 200]);
        let rgba = png(DynamicImage::ImageRgba8(image::RgbaImage::from_raw(1, 1, vec![1, 2, 3, 4]).unwrap()));
        assert_eq!(decode(&rgba, None, Role::Opacity, "a").unwrap().rgba8, vec![1, 2, 3, 4]);
    }

    #[test]
    fn garbage_is_an_error_not_a_panic() {
        assert!(decode(b"definitely not an image", None, Role::Colour, "x").is_err());
        let mut p = png(DynamicImage::ImageRgb8(image::RgbImage::new(64, 64)));
        p.truncate(60);
        assert!(decode(&p, None, Role::Colour, "x").is_err());
    }

    #[test]
    fn huge_image_headers_are_refused_before_decoding() {
        // An 18-byte TGA header claiming 65535 x 65535 24-bit pixels, and no pixels.
        let mut tga = vec![0u8, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0];
        tga.extend(65535u16.to_le_bytes());
        tga.extend(65535u16.to_le_bytes());
        tga.extend([24, 0]);
        let e = decode(&tga, Some(ImageFormat::Tga), Role::Colour, "big").unwrap_err();
        assert!(e.contains("65535x65535 pixels is over the limit of 268,435,456 pixels"), "{e}");
    }

    #[test]
    fn requests_are_deduplicated_and_failures_removed() {
        let good = png(DynamicImage::ImageRgb8(image::RgbImage::new(3, 2)));
        let mut reqs = Requests::default();
        let mk = |name: &str, bytes: &'static [u8]| {
            let name = name.to_owned();
            move || Request {
                name,
                source: Source::Memory { bytes, mime: None },
                role: Role::Colour,
                at: "here".into(),
                file: "f".into(),
                line: None,
            }
        };
        let good: &'static [u8] = Box::leak(good.into_boxed_slice());
        let a = reqs.request("a".into(), Role::Colour, mk("a", b"bad"));
        let b = reqs.request("b".into(), Role::Colour, mk("b", good));
        assert_eq!(reqs.request("b".into(), Role::Colour, mk("b", good)), b);
        assert_ne!(a, b);
        let mut w = Warnings::default();
        let d = reqs.decode(false, &mut w).unwrap();
        assert_eq!(d.textures.len(), 1);
        assert_eq!((d.textures[0].width, d.textures[0].height), (3, 2));
        let mut mats =
            vec![Material { albedo_texture: Some(a), ..Default::default() }, Material { albedo_texture: Some(b), ..Default::default() }];
        d.apply(&mut mats);
        assert_eq!(mats[0].albedo_texture, None);
        assert_eq!(mats[1].albedo_texture, Some(0));
        let w = w.into_vec();
        assert_eq!(w.len(), 1);
        assert!(w[0].starts_with("here: cannot decode texture 'a'"), "{w:?}");
    }
}
