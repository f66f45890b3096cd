//! A validating pass over an OBJ file before tobj parses it.
//!
//! tobj's errors carry no line number, and some input makes it misbehave (an index of 0 or
//! past the end overflows in its arithmetic; an indented `usemtl` becomes a material named
//! "usemtl x"; `l` polylines of three points become triangles). So every line is checked
//! here first — numbers finite, indices in range, faces of three or more vertices — and an
//! error names the file and line. Lines tobj would misread are rewritten (indentation
//! removed, `l` blanked), keeping the line count; tobj then parses the result.

use std::path::Path;

use super::warnings::Warnings;
use super::SceneError;

/// What the pass learnt.
#[derive(Debug, Default)]
pub(crate) struct ObjCheck {
    /// `mtllib` statements in file order: (line, the file name(s) after the keyword).
    pub mtllibs: Vec<(usize, String)>,
    /// `usemtl` statements: (line, material name).
    pub usemtls: Vec<(usize, String)>,
    /// The text tobj should parse, when lines had to be rewritten.
    pub rewritten: Option<String>,
    pub positions: usize,
    pub texcoords: usize,
    pub normals: usize,
    pub faces: usize,
}

/// Statements bidir ignores silently: grouping and smoothing carry no rendering data for
/// it, `vp`/free-form geometry is warned about below instead.
const SILENT: &[&str] = &["o", "g", "s", "mg"];

pub(crate) fn check(file: &Path, text: &str, w: &mut Warnings) -> Result<ObjCheck, SceneError> {
    let mut c = ObjCheck::default();
    let mut out: Option<String> = None;
    // Whether vertices carry colours (`v x y z r g b`): tobj needs all or none.
    let mut colours: Option<(bool, usize)> = None;
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let err = |msg: String| SceneError::syntax(file, line, msg);
        let mut words = raw.split_whitespace();
        let Some(key) = words.next() else {
            push_line(&mut out, raw);
            continue;
        };
        let rest: Vec<&str> = words.collect();
        // The line as tobj should see it, when `raw` would mislead it.
        let mut rewrite: Option<String> = None;
        match key {
            k if k.starts_with('#') => {}
            "v" => {
                let n = numbers(&rest, &err)?;
                let pos_ok = match n.len() {
                    3 | 6 => true,
                    4 => {
                        if n[3] == 0.0 {
                            return Err(err("vertex weight w is 0".into()));
                        }
                        n[..3].iter().all(|x| (x / n[3]).is_finite())
                    }
                    k => return Err(err(format!("a vertex needs 3 coordinates (plus w, or r g b); found {k} numbers"))),
                };
                if !pos_ok {
                    return Err(err("vertex coordinate is not finite".into()));
                }
                let has_colour = n.len() == 6;
                match colours {
                    None => colours = Some((has_colour, line)),
                    Some((first, first_line)) if first != has_colour => {
                        return Err(err(format!(
                            "vertex colours on only some vertices (line {first_line} {}, this line {}): not supported",
                            if first { "has them" } else { "has none" },
                            if has_colour { "has them" } else { "has none" }
                        )))
                    }
                    _ => {}
                }
                c.positions += 1;
            }
            "vt" => {
                let n = numbers(&rest, &err)?;
                if !(2..=3).contains(&n.len()) {
                    return Err(err(format!("a texture coordinate needs 2 numbers (u v); found {}", n.len())));
                }
                c.texcoords += 1;
            }
            "vn" => {
                let n = numbers(&rest, &err)?;
                if n.len() != 3 {
                    return Err(err(format!("a normal needs 3 numbers; found {}", n.len())));
                }
                c.normals += 1;
            }
            "f" => {
                if rest.len() < 3 {
                    return Err(err(format!("a face needs at least 3 vertices; found {}", rest.len())));
                }
                for r in &rest {
                    check_ref(r, &c, &err)?;
                }
                c.faces += 1;
            }
            "l" | "p" => {
                w.warn_once("obj-lines", || format!("{}:{line}: points and lines (`{key}`) are not rendered; ignored", file.display()));
                rewrite = Some(String::new());
            }
            "mtllib" | "usemtl" => {
                let name = raw.trim().get(key.len()..).unwrap_or("").trim();
                if name.is_empty() {
                    return Err(err(format!("`{key}` needs a name")));
                }
                if key == "mtllib" {
                    c.mtllibs.push((line, name.to_owned()));
                } else {
                    c.usemtls.push((line, name.to_owned()));
                }
                // tobj splits at the first space of the untrimmed line.
                let canonical = format!("{key} {name}");
                if raw != canonical {
                    rewrite = Some(canonical);
                }
            }
            k if SILENT.contains(&k) => {
                if raw.starts_with(char::is_whitespace) {
                    rewrite = Some(raw.trim_start().to_owned());
                }
            }
            k => w.warn_once(&format!("obj-key-{k}"), || format!("{}:{line}: unsupported OBJ statement `{k}` ignored", file.display())),
        }
        if rewrite.is_some() && out.is_none() {
            out = Some(text.lines().take(i).flat_map(|l| [l, "\n"]).collect());
        }
        push_line(&mut out, rewrite.as_deref().unwrap_or(raw));
    }
    c.rewritten = out;
    Ok(c)
}

fn push_line(out: &mut Option<String>, line: &str) {
    if let Some(o) = out {
        o.push_str(line);
        o.push('\n');
    }
}

fn numbers(words: &[&str], err: &dyn Fn(String) -> SceneError) -> Result<Vec<f32>, SceneError> {
    words
        .iter()
        .map(|w| match w.parse::<f32>() {
            Ok(x) if x.is_finite() => Ok(x),
            Ok(_) => Err(err(format!("'{}' is not a finite number", crate::text::quote(w)))),
            Err(_) => Err(err(format!("'{}' is not a number", crate::text::quote(w)))),
        })
        .collect()
}

/// One `v`, `v/vt`, `v//vn` or `v/vt/vn` reference, against the counts seen so far
/// (negative indices count back from the last one).
fn check_ref(r: &str, c: &ObjCheck, err: &dyn Fn(String) -> SceneError) -> Result<(), SceneError> {
    let parts: Vec<&str> = r.split('/').collect();
    if parts.len() > 3 || parts[0].is_empty() {
        return Err(err(format!("'{}' is not a face vertex (v, v/vt, v//vn or v/vt/vn)", crate::text::quote(r))));
    }
    let kinds =
        [("vertex", "vertices", c.positions), ("texture coordinate", "texture coordinates", c.texcoords), ("normal", "normals", c.normals)];
    for (part, (what, whats, count)) in parts.iter().zip(kinds) {
        if part.is_empty() {
            continue;
        }
        let Ok(x) = part.parse::<i64>() else {
            return Err(err(format!("'{r}': '{part}' is not an index")));
        };
        let ok = match x {
            0 => return Err(err(format!("'{r}': {what} index 0 is invalid (OBJ indices start at 1)"))),
            x if x > 0 => x as u64 <= count as u64,
            x => x.unsigned_abs() <= count as u64,
        };
        if !ok {
            return Err(err(format!("'{r}': {what} index {x} out of range ({count} {whats} so far)")));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(text: &str) -> Result<ObjCheck, SceneError> {
        check(Path::new("t.obj"), text, &mut Warnings::default())
    }

    fn line_of(text: &str) -> (usize, String) {
        let e = run(text).unwrap_err();
        (e.line().unwrap(), e.to_string())
    }

    #[test]
    fn accepts_valid_statements() {
        let c = run("# c\nv 0 0 0\nv 1 0 0 1\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\nf -3 -2 -1\nf 1//1 2//1 3//1\n").unwrap();
        assert_eq!((c.positions, c.texcoords, c.normals, c.faces), (3, 1, 1, 3));
        assert!(c.rewritten.is_none());
    }

    #[test]
    fn errors_name_the_line() {
        assert_eq!(line_of("v 0 0 0\nv 1 x 0\n").0, 2);
        assert_eq!(line_of("v 0 0 nan\n").0, 1);
        assert_eq!(line_of("\n\nv 1e39 0 0\n").0, 3);
        assert_eq!(line_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n").0, 4);
        assert_eq!(line_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n").0, 4);
        assert_eq!(line_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n").0, 4);
        assert_eq!(line_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/1 3/1\n").0, 4);
        assert_eq!(line_of("v 0 0 0\nv 1 0 0\nf 1 2\n").0, 3);
        assert_eq!(line_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n").0, 4);
        assert_eq!(line_of("v 0 0 0 1 1 1\nv 1 0 0\n").0, 2);
        assert_eq!(line_of("usemtl\n").0, 1);
        let (_, msg) = line_of("v 0 0 0\nf 1 2 3\n");
        assert_eq!(msg, "t.obj:2: '2': vertex index 2 out of range (1 vertices so far)");
    }

    #[test]
    fn rewrites_what_tobj_would_misread() {
        let text = "mtllib a.mtl\n  usemtl  red\nv 0 0 0\nl 1 1 1\n\tg x\n";
        let c = run(text).unwrap();
        assert_eq!(c.usemtls, vec![(2, "red".to_owned())]);
        assert_eq!(c.rewritten.as_deref(), Some("mtllib a.mtl\nusemtl red\nv 0 0 0\n\ng x\n"));
    }
}
