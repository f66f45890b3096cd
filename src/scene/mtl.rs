//! MTL material libraries, parsed here (not by tobj) so every value is checked with its line
//! number and the thesis' extra keys are read where they are written:
//!
//! ```text
//! newmtl FloorMaterial
//!     Kd 0.6 0.6 0.6
//!     Ke 0.0 0.0 0.0
//!     map_Kd floor_d.tga
//!     emissivity 0.0
//!     reflectivity 0.0
//!     refractivity 0.0
//!     IOR 1.0
//! ```
//!
//! How a library becomes a [`Material`] (keys are matched case-insensitively):
//! - `Kd` → albedo (linear RGB; default 0.8 grey), multiplied by `map_Kd` (sRGB) if given.
//! - `Ke` → emitted radiance. `emissivity e` (thesis) is a scalar emission strength: when
//!   `Ke` is absent or zero and `e > 0`, the emission is `e · Kd` — the surface glows in its
//!   own colour. A non-zero `Ke` wins over `emissivity`.
//! - `reflectivity` / `refractivity` (thesis) are the fractions of perfect mirror and smooth
//!   dielectric; the rest is diffuse. When neither key is present they come from the standard
//!   keys: `illum 3` or `5` → mirror (reflectivity 1), `illum 7` → glass (refractivity 1),
//!   else a dissolve `d < 1` (or `Tr > 0`) → refractivity `1 - d` (a partly transparent
//!   surface approximated by the dielectric; warned once). Values are clamped to [0, 1], and
//!   scaled down together if they sum above 1 (warned).
//! - `IOR` (thesis) → index of refraction, else `Ni`, else 1.5.
//! - PBR keys (Blender's exporter): `Pr` roughness and `Pm` metallic (in [0, 1]), `map_Pr` /
//!   `map_Pm` (linear; grey level). A thesis mirror (`reflectivity`, `illum 3/5`) stays one, made
//!   a rough GGX conductor with F = 1 (alpha = Pr²) by `Pr > 0` (or `map_Pr`); a thesis glass
//!   (`refractivity`, `illum 7`, `d < 1`) likewise becomes a rough dielectric (Walter et al.
//!   2007, the thesis' IOR, exact Fresnel); without a mirror or glass any of these keys makes the material glTF's metallic-roughness model with base colour
//!   `Kd` (roughness `Pr`, default 1 as in glTF; metallic `Pm`, default 0).
//! - `norm` → tangent-space normal map (linear; `map_Bump` is a height map: not supported).
//! - `map_Ke` (sRGB) scales the emission (`Ke`, or 1 when `Ke` is absent).
//! - `map_d` → alpha mask (cut-out at 0.5): the texture's alpha, or its grey level when it
//!   has no alpha channel. Texture options (`-s 1 1 1` ...) are skipped with a warning.

use std::path::Path;

use glam::Vec3;

use super::texture::Role;
use super::warnings::Warnings;
use super::{AlphaMask, Material, MaterialModel, SceneError};

/// One `newmtl` block as written.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct MtlEntry {
    pub name: String,
    pub line: usize,
    pub kd: Option<Vec3>,
    pub ke: Option<Vec3>,
    pub ni: Option<f32>,
    pub d: Option<f32>,
    pub illum: Option<u32>,
    /// (line, file name)
    pub map_kd: Option<(usize, String)>,
    pub map_d: Option<(usize, String)>,
    pub emissivity: Option<f32>,
    pub reflectivity: Option<f32>,
    pub refractivity: Option<f32>,
    pub ior: Option<f32>,
    pub pr: Option<f32>,
    pub pm: Option<f32>,
    pub map_pr: Option<(usize, String)>,
    pub map_ke: Option<(usize, String)>,
    pub norm: Option<(usize, String)>,
    pub map_pm: Option<(usize, String)>,
    /// Clear coat weight and roughness (the PBR extension's `Pc`, `Pcr`, which Blender writes
    /// for the Principled BSDF's coat).
    pub pc: Option<f32>,
    pub pcr: Option<f32>,
}

/// Keys read but not part of the material model: ignored without a word.
const IGNORED: &[&str] = &["ka", "ks", "ns", "tf", "sharpness", "map_ka"];
/// Texture maps the model cannot use: one warning per key.
const UNSUPPORTED_MAPS: &[&str] = &["map_ks", "map_ns", "map_bump", "bump", "disp", "decal", "refl", "map_refl"];

pub(crate) fn parse(file: &Path, text: &str, w: &mut Warnings) -> Result<Vec<MtlEntry>, SceneError> {
    let mut out: Vec<MtlEntry> = Vec::new();
    for (i, raw) in text.strip_prefix('\u{feff}').unwrap_or(text).lines().enumerate() {
        let line = i + 1;
        let err = |msg: String| SceneError::syntax(file, line, msg);
        let trimmed = raw.trim();
        let mut words = trimmed.split_whitespace();
        let Some(key) = words.next() else { continue };
        if key.starts_with('#') {
            continue;
        }
        let args: Vec<&str> = words.collect();
        let key_lc = key.to_ascii_lowercase();
        if key_lc == "newmtl" {
            let name = trimmed[key.len()..].trim();
            if name.is_empty() {
                return Err(err("`newmtl` needs a name".into()));
            }
            out.push(MtlEntry { name: name.to_owned(), line, ..Default::default() });
            continue;
        }
        let Some(m) = out.last_mut() else {
            w.warn_once("mtl-before-newmtl", || format!("{}:{line}: `{key}` before any `newmtl` ignored", file.display()));
            continue;
        };
        match key_lc.as_str() {
            "kd" => m.kd = Some(colour(&args, &err)?),
            "ke" => m.ke = Some(colour(&args, &err)?),
            "ni" => {
                let v = scalar(&args, &err)?;
                if v > 0.0 {
                    m.ni = Some(v);
                } else {
                    w.warn(format!("{}:{line}: Ni {v} is not a refractive index; ignored", file.display()));
                }
            }
            "d" | "tr" => {
                // `d -halo 0.5`: the halo form has no meaning here; read its number.
                let args: Vec<&str> = args.iter().copied().filter(|a| *a != "-halo").collect();
                let v = scalar(&args, &err)?;
                let d = if key_lc == "d" { v } else { 1.0 - v };
                if !(0.0..=1.0).contains(&d) {
                    return Err(err(format!("`{key} {v}`: dissolve must be in [0, 1]")));
                }
                // `d` wins over `Tr` whatever their order.
                if key_lc == "d" || m.d.is_none() {
                    m.d = Some(d);
                }
            }
            "illum" => {
                m.illum = Some(match args.as_slice() {
                    [v] => v.parse().map_err(|_| err(format!("illum '{}' is not a whole number", crate::text::quote(v))))?,
                    _ => return Err(err("`illum` needs one whole number".into())),
                })
            }
            "map_kd" => m.map_kd = Some((line, texture_name(file, line, &args, w, &err)?)),
            "map_d" => m.map_d = Some((line, texture_name(file, line, &args, w, &err)?)),
            "norm" => m.norm = Some((line, texture_name(file, line, &args, w, &err)?)),
            "map_ke" => m.map_ke = Some((line, texture_name(file, line, &args, w, &err)?)),
            "map_pr" => m.map_pr = Some((line, texture_name(file, line, &args, w, &err)?)),
            "map_pm" => m.map_pm = Some((line, texture_name(file, line, &args, w, &err)?)),
            "pr" | "pm" | "pc" | "pcr" => {
                let v = scalar(&args, &err)?;
                if !(0.0..=1.0).contains(&v) {
                    return Err(err(format!("`{key} {v}` must be in [0, 1]")));
                }
                let slot = match key_lc.as_str() {
                    "pr" => &mut m.pr,
                    "pm" => &mut m.pm,
                    "pc" => &mut m.pc,
                    _ => &mut m.pcr,
                };
                *slot = Some(v);
            }
            "emissivity" => m.emissivity = Some(scalar(&args, &err)?),
            "reflectivity" => m.reflectivity = Some(scalar(&args, &err)?),
            "refractivity" => m.refractivity = Some(scalar(&args, &err)?),
            "ior" => {
                let v = scalar(&args, &err)?;
                if v <= 0.0 {
                    return Err(err(format!("IOR {v} must be positive")));
                }
                m.ior = Some(v);
            }
            k if IGNORED.contains(&k) => {}
            k if UNSUPPORTED_MAPS.contains(&k) => w.warn_once(&format!("mtl-map-{k}"), || {
                format!("{}:{line}: `{key}` is not supported (bidir has no bump, specular or displacement maps); ignored", file.display())
            }),
            _ => w.warn_once(&format!("mtl-key-{key_lc}"), || format!("{}:{line}: unknown MTL key `{key}` ignored", file.display())),
        }
    }
    Ok(out)
}

fn number(s: &str, err: &dyn Fn(String) -> SceneError) -> Result<f32, SceneError> {
    match s.parse::<f32>() {
        Ok(x) if x.is_finite() => Ok(x),
        Ok(_) => Err(err(format!("'{}' is not a finite number", crate::text::quote(s)))),
        Err(_) => Err(err(format!("'{}' is not a number", crate::text::quote(s)))),
    }
}

fn scalar(args: &[&str], err: &dyn Fn(String) -> SceneError) -> Result<f32, SceneError> {
    match args {
        [v] => number(v, err),
        _ => Err(err(format!("expected one number, found {} values", args.len()))),
    }
}

/// `r g b`, or `r` alone meaning grey (as the MTL specification allows).
fn colour(args: &[&str], err: &dyn Fn(String) -> SceneError) -> Result<Vec3, SceneError> {
    let c = match args {
        [r] => Vec3::splat(number(r, err)?),
        [r, g, b] => Vec3::new(number(r, err)?, number(g, err)?, number(b, err)?),
        [first, ..] if first.eq_ignore_ascii_case("spectral") || first.eq_ignore_ascii_case("xyz") => {
            return Err(err(format!("`{first}` colours are not supported; give linear RGB")))
        }
        _ => return Err(err(format!("expected 3 numbers (r g b), found {} values", args.len()))),
    };
    if c.min_element() < 0.0 {
        return Err(err("colour components must not be negative".into()));
    }
    Ok(c)
}

/// The file name of a `map_*` statement, after its options (`-s 1 1 1`, `-bm 0.5`, ...).
fn texture_name(
    file: &Path,
    line: usize,
    args: &[&str],
    w: &mut Warnings,
    err: &dyn Fn(String) -> SceneError,
) -> Result<String, SceneError> {
    let mut i = 0;
    while i < args.len() && args[i].starts_with('-') && args.len() - i > 1 {
        let opt = args[i];
        i += 1;
        let max = match opt {
            "-o" | "-s" | "-t" => 3,
            "-mm" => 2,
            _ => 1,
        };
        let mut taken = 0;
        while taken < max && i < args.len() - 1 && (taken == 0 || args[i].parse::<f32>().is_ok()) {
            i += 1;
            taken += 1;
        }
        w.warn_once("mtl-texture-options", || format!("{}:{line}: texture option `{opt}` ignored", file.display()));
    }
    let name = args[i.min(args.len())..].join(" ");
    if name.is_empty() {
        return Err(err("texture statement needs a file name".into()));
    }
    Ok(name)
}

/// Turns an entry into a material. `texture(name, line, role)` requests a texture (relative
/// to the library) and returns its provisional index, or `None` if textures are unavailable.
pub(crate) fn to_material(
    e: &MtlEntry,
    file: &Path,
    w: &mut Warnings,
    texture: &mut dyn FnMut(&str, usize, Role, &mut Warnings) -> Option<u32>,
) -> Material {
    let at = |line: usize| format!("{}:{line}", file.display());
    let albedo = e.kd.unwrap_or(Material::default().albedo);
    let emission = match (e.ke, e.emissivity) {
        (Some(ke), _) if ke.max_element() > 0.0 => ke,
        (_, Some(s)) if s > 0.0 => s * albedo,
        (_, Some(s)) if s < 0.0 => {
            w.warn(format!("{}: material '{}': negative emissivity {s} ignored", at(e.line), e.name));
            Vec3::ZERO
        }
        _ => Vec3::ZERO,
    };
    let (mut refl, mut refr) = if e.reflectivity.is_some() || e.refractivity.is_some() {
        (e.reflectivity.unwrap_or(0.0), e.refractivity.unwrap_or(0.0))
    } else {
        match e.illum {
            Some(3) | Some(5) => (1.0, 0.0),
            Some(7) => (0.0, 1.0),
            _ => match e.d {
                Some(d) if d < 1.0 => {
                    w.warn_once("mtl-dissolve", || {
                        format!("{}: material '{}': dissolve d = {d} approximated as refractivity {}", at(e.line), e.name, 1.0 - d)
                    });
                    (0.0, 1.0 - d)
                }
                _ => (0.0, 0.0),
            },
        }
    };
    if !(0.0..=1.0).contains(&refl) || !(0.0..=1.0).contains(&refr) {
        w.warn(format!("{}: material '{}': reflectivity {refl} / refractivity {refr} clamped to [0, 1]", at(e.line), e.name));
        refl = refl.clamp(0.0, 1.0);
        refr = refr.clamp(0.0, 1.0);
    }
    if refl + refr > 1.0 {
        w.warn(format!("{}: material '{}': reflectivity {refl} + refractivity {refr} exceed 1; scaled to sum to 1", at(e.line), e.name));
        let s = refl + refr;
        refl /= s;
        refr /= s;
    }
    let albedo_texture = e.map_kd.as_ref().and_then(|(line, name)| texture(name, *line, Role::Colour, w));
    let alpha =
        e.map_d.as_ref().and_then(|(line, name)| texture(name, *line, Role::Opacity, w)).map(|t| AlphaMask { texture: t, cutoff: 0.5 });
    // `map_Ke` scales Ke (1 where Ke is absent, as Blender writes both).
    let emission_texture = e.map_ke.as_ref().and_then(|(line, name)| texture(name, *line, Role::Colour, w));
    let emission = match (emission_texture, e.ke) {
        (Some(_), None) if emission == Vec3::ZERO => Vec3::ONE,
        _ => emission,
    };
    let roughness_texture = e.map_pr.as_ref().and_then(|(line, name)| texture(name, *line, Role::Linear, w));
    let metallic_texture = e.map_pm.as_ref().and_then(|(line, name)| texture(name, *line, Role::Linear, w));
    // A thesis mirror or glass stays one (rough where Pr or map_Pr says so: a GGX conductor
    // with F = 1, a rough dielectric with the thesis' IOR); otherwise the PBR keys make the
    // metallic-roughness model.
    let thesis = refl > 0.0 || refr > 0.0;
    let coat = e.pc.filter(|&c| c > 0.0);
    let pbr = !thesis && (e.pr.is_some() || e.pm.is_some() || roughness_texture.is_some() || metallic_texture.is_some() || coat.is_some());
    if thesis && coat.is_some() {
        w.warn(format!("{}: material '{}': Pc (clear coat) on a thesis mirror or glass is ignored", at(e.line), e.name));
    }
    let (model, roughness, metallic) = if pbr {
        (MaterialModel::MetalRough, e.pr.unwrap_or(1.0), e.pm.unwrap_or(0.0))
    } else if thesis && roughness_texture.is_some() {
        (MaterialModel::Thesis, e.pr.unwrap_or(1.0), 0.0)
    } else {
        (MaterialModel::Thesis, if thesis { e.pr.unwrap_or(0.0) } else { 0.0 }, 0.0)
    };
    Material {
        name: e.name.clone(),
        albedo,
        albedo_texture,
        emission,
        emission_texture: if emission.max_element() > 0.0 { emission_texture } else { None },
        reflectivity: refl,
        refractivity: refr,
        ior: e.ior.or(e.ni).unwrap_or(Material::default().ior),
        alpha,
        blend: None,
        normal_texture: e.norm.as_ref().and_then(|(line, name)| texture(name, *line, Role::Linear, w)),
        normal_scale: 1.0,
        model,
        metallic,
        roughness,
        roughness_texture,
        metallic_texture: if pbr { metallic_texture } else { None },
        transmission_texture: None,
        absorption: Vec3::ZERO,
        specular: 1.0,
        specular_colour: Vec3::ONE,
        specular_texture: None,
        specular_colour_texture: None,
        clearcoat: if pbr { coat.unwrap_or(0.0) } else { 0.0 },
        clearcoat_roughness: if pbr { e.pcr.unwrap_or(0.0) } else { 0.0 },
        clearcoat_texture: None,
        clearcoat_roughness_texture: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_ok(text: &str) -> (Vec<MtlEntry>, Vec<String>) {
        let mut w = Warnings::default();
        let e = parse(Path::new("m.mtl"), text, &mut w).unwrap();
        (e, w.into_vec())
    }

    fn material(text: &str) -> Material {
        let (e, _) = parse_ok(text);
        let mut next = 0;
        to_material(&e[0], Path::new("m.mtl"), &mut Warnings::default(), &mut |_, _, _, _| {
            next += 1;
            Some(next - 1)
        })
    }

    #[test]
    fn pbr_keys_make_rough_mirrors_or_the_metal_rough_model() {
        // Pr on a thesis mirror: a rough conductor with F = 1, the rest unchanged.
        let m = material("newmtl R\nKd 0.5 0.5 0.5\nreflectivity 0.6\nPr 0.3\n");
        assert_eq!((m.model, m.reflectivity, m.roughness, m.metallic), (MaterialModel::Thesis, 0.6, 0.3, 0.0));
        assert!(m.is_glossy() && !m.has_mirror());
        // Pr on a thesis glass: a rough dielectric with the thesis' IOR.
        let m = material("newmtl G\nKd 0.5 0.5 0.5\nrefractivity 1\nIOR 1.7\nPr 0.4\n");
        assert_eq!((m.model, m.refractivity, m.ior, m.roughness), (MaterialModel::Thesis, 1.0, 1.7, 0.4));
        assert!(m.has_rough_glass() && m.describe().contains("rough glass"), "{}", m.describe());
        let m = material("newmtl S\nillum 7\n");
        assert!(!m.has_rough_glass() && m.describe().contains("glass"));
        // Pr 0 keeps the perfect mirror.
        let m = material("newmtl M\nillum 3\nPr 0\n");
        assert!(m.has_mirror() && !m.is_glossy());
        // Blender's keys without the thesis mirror: glTF's model, base colour Kd.
        let m = material("newmtl P\nKd 0.8 0.2 0.1\nPr 0.4\nPm 1\nmap_Pr r.png\nmap_Pm m.png\n");
        assert_eq!((m.model, m.roughness, m.metallic, m.reflectivity), (MaterialModel::MetalRough, 0.4, 1.0, 0.0));
        assert_eq!((m.roughness_texture, m.metallic_texture), (Some(0), Some(1)));
        // Roughness defaults to glTF's 1 when only Pm is given; values outside [0, 1] are errors.
        assert_eq!(material("newmtl Q\nPm 0.5\n").roughness, 1.0);
        let mut w = Warnings::default();
        assert!(parse(Path::new("m.mtl"), "newmtl X\nPr 1.5\n", &mut w).unwrap_err().to_string().contains("m.mtl:2"));
        // Blender's coat: Pc and Pcr make a clear coat over glTF's model (Pc alone makes the
        // model glTF's), and are out of range above 1; on a thesis mirror they are ignored.
        let m = material("newmtl C\nKd 0.8 0.1 0.1\nPr 0.5\nPc 1\nPcr 0.03\n");
        assert_eq!((m.model, m.clearcoat, m.clearcoat_roughness), (MaterialModel::MetalRough, 1.0, 0.03));
        assert!(m.has_clearcoat() && m.describe().contains("clear coat"), "{}", m.describe());
        let m = material("newmtl D\nPc 0.5\n");
        assert_eq!((m.model, m.clearcoat, m.roughness), (MaterialModel::MetalRough, 0.5, 1.0));
        assert!(!material("newmtl E\nillum 3\nPc 1\n").has_clearcoat());
        assert!(!material("newmtl F\nPc 0\nPcr 0.2\n").has_clearcoat());
        assert!(parse(Path::new("m.mtl"), "newmtl X\nPcr 2\n", &mut w).unwrap_err().to_string().contains("`Pcr 2` must be in [0, 1]"));
    }

    #[test]
    fn describe_names_model_lobes_and_maps() {
        let m = material("newmtl H\nKd 0.5 0.5 0.5\nreflectivity 0.3\nrefractivity 0.2\nmap_Kd a.png\n");
        assert_eq!(m.describe(), "thesis: diffuse, mirror, glass, base colour map");
        let m = material("newmtl R\nreflectivity 1\nPr 0.2\n");
        assert_eq!(m.describe(), "thesis: rough mirror (GGX, F = 1)");
        let m = material("newmtl P\nPm 1\nPr 0.5\nmap_Pr r.png\nKe 1 1 1\nmap_Ke e.png\nnorm n.png\n");
        assert_eq!(m.describe(), "metal-rough: GGX, emissive, roughness map, normal map, emission map");
    }

    #[test]
    fn thesis_keys() {
        let m = material(
            "newmtl Floor\n  Kd 0.6 0.5 0.4\n  Ke 0 0 0\n  map_Kd floor_d.tga\n  emissivity 2.0\n  reflectivity 0.25\n  refractivity 0.5\n  IOR 1.33\n",
        );
        assert_eq!(m.name, "Floor");
        assert_eq!(m.albedo, Vec3::new(0.6, 0.5, 0.4));
        assert_eq!(m.emission, 2.0 * Vec3::new(0.6, 0.5, 0.4));
        assert_eq!((m.reflectivity, m.refractivity, m.ior), (0.25, 0.5, 1.33));
        assert_eq!(m.albedo_texture, Some(0));
    }

    #[test]
    fn ke_wins_over_emissivity_and_illum_maps_to_mirror_and_glass() {
        assert_eq!(material("newmtl L\nKd 1 1 1\nKe 17 12 4\nemissivity 3\n").emission, Vec3::new(17.0, 12.0, 4.0));
        let mirror = material("newmtl M\nillum 3\n");
        assert_eq!((mirror.reflectivity, mirror.refractivity), (1.0, 0.0));
        let glass = material("newmtl G\nillum 7\nNi 1.33\n");
        assert_eq!((glass.reflectivity, glass.refractivity, glass.ior), (0.0, 1.0, 1.33));
        // Explicit thesis keys win over illum.
        let m = material("newmtl X\nillum 7\nrefractivity 0.0\n");
        assert_eq!(m.refractivity, 0.0);
        let d = material("newmtl D\nd 0.25\n");
        assert_eq!(d.refractivity, 0.75);
        let tr = material("newmtl T\nTr 0.25\n");
        assert_eq!(tr.refractivity, 0.25);
    }

    #[test]
    fn fractions_are_clamped_and_normalised() {
        let m = material("newmtl X\nreflectivity 0.75\nrefractivity 0.75\n");
        assert_eq!((m.reflectivity, m.refractivity), (0.5, 0.5));
        let m = material("newmtl X\nreflectivity 1.5\n");
        assert_eq!(m.reflectivity, 1.0);
    }

    #[test]
    fn map_d_is_an_alpha_mask_and_options_are_skipped() {
        let (e, w) = parse_ok("newmtl A\nmap_Kd -s 1 1 1 -bm 0.5 leaf diffuse.png\nmap_d leaf_alpha.png\n");
        assert_eq!(e[0].map_kd, Some((2, "leaf diffuse.png".to_owned())));
        assert_eq!(w.len(), 1, "{w:?}");
        let m = material("newmtl A\nmap_d a.png\n");
        assert_eq!(m.alpha, Some(AlphaMask { texture: 0, cutoff: 0.5 }));
    }

    #[test]
    fn bad_values_name_the_line() {
        for (text, line) in [
            ("newmtl A\nKd 0.5 0.5\n", 2),
            ("newmtl A\n\nKd nan 0 0\n", 3),
            ("newmtl A\nreflectivity high\n", 2),
            ("newmtl A\nIOR 0\n", 2),
            ("newmtl\n", 1),
            ("newmtl A\nillum 2.5\n", 2),
            ("newmtl A\nd 1.5\n", 2),
            ("newmtl A\nKe -1 0 0\n", 2),
            ("newmtl A\nmap_Kd\n", 2),
        ] {
            let e = parse(Path::new("m.mtl"), text, &mut Warnings::default()).unwrap_err();
            assert_eq!(e.line(), Some(line), "{text:?}: {e}");
            assert!(e.to_string().starts_with(&format!("m.mtl:{line}: ")), "{e}");
        }
    }
}
