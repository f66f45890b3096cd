//! `bidir info SCENE`: what a scene holds and what it will cost, without a GPU.

use bidir::scene::{fmt_vec, Camera};

use super::scene_args::SceneArgs;

use bidir::limits::thousands;

fn bytes(n: u64) -> String {
    const UNITS: [&str; 4] = ["B", "KiB", "MiB", "GiB"];
    let mut v = n as f64;
    let mut u = 0;
    while v >= 1024.0 && u < UNITS.len() - 1 {
        v /= 1024.0;
        u += 1;
    }
    if u == 0 {
        format!("{n} B")
    } else {
        format!("{v:.1} {}", UNITS[u])
    }
}

/// Everything but the name.
fn camera_details(c: &Camera) -> String {
    format!(
        "eye {} target {} up {} fov_y {}° {}x{}",
        fmt_vec(c.eye),
        fmt_vec(c.target),
        fmt_vec(c.up),
        (c.fov_y_deg * 1e4).round() / 1e4,
        c.width,
        c.height
    )
}

pub fn run(args: &SceneArgs) -> anyhow::Result<()> {
    let l = args.load()?;
    let s = &l.scene;
    let yes_no = |b: bool| if b { "yes" } else { "no" };
    println!("scene:        {}", s.source);
    let t = l.load_time.as_secs_f64();
    let t = if t < 1.0 { format!("{:.1} ms", t * 1e3) } else { format!("{t:.2} s") };
    println!("load time:    {t}");
    println!("triangles:    {} ({} degenerate dropped)", thousands(s.triangle_count() as u64), s.dropped_degenerate);
    println!(
        "vertices:     {} (normals: {}, uvs: {})",
        thousands(s.vertex_count() as u64),
        yes_no(s.normals.is_some()),
        yes_no(s.uvs.is_some())
    );
    let m = s.material_counts();
    println!(
        "materials:    {} ({} with a diffuse part, {} mirror, {} glass, {} glossy (GGX), {} emissive, {} alpha-masked, {} blended, {} textured)",
        m.total, m.diffuse, m.mirror, m.glass, m.glossy, m.emissive, m.alpha_masked, m.blended, m.textured
    );
    // Materials by kind and the features each uses, most common first.
    let mut kinds: Vec<(String, usize, &str)> = Vec::new();
    for m in &s.materials {
        let d = m.describe();
        match kinds.iter_mut().find(|k| k.0 == d) {
            Some(k) => k.1 += 1,
            None => kinds.push((d, 1, &m.name)),
        }
    }
    kinds.sort_by_key(|k| std::cmp::Reverse(k.1));
    for (d, n, first) in &kinds {
        println!("  {n} x {d} (e.g. \"{first}\")");
    }
    let emitters = s.emitters();
    if emitters.is_empty() {
        println!("emitters:     none");
    } else {
        let (power, lum) = s.total_emitted_power();
        println!(
            "emitters:     {} triangles, power (pi * area * Le) ({:.4e}, {:.4e}, {:.4e}), luminance {:.4e}",
            thousands(emitters.len() as u64),
            power.x,
            power.y,
            power.z,
            lum
        );
    }
    for l in &s.punctual_lights {
        println!(
            "  punctual {:?} \"{}\": position {} direction {} intensity {}",
            l.kind,
            l.name,
            fmt_vec(l.position),
            fmt_vec(l.direction),
            fmt_vec(l.intensity)
        );
    }
    if let Some(e) = &s.environment {
        println!("environment:  {} ({}x{}, scale {}, rotated {} deg)", e.source, e.width, e.height, e.scale, e.rotate_deg);
    }
    for (quad, name) in args.added_lights() {
        println!("  added {name}: --quad-light \"{quad}\" (area {:.4}, front {})", quad.area(), fmt_vec(quad.front()));
    }
    let srgb = s.textures.iter().filter(|t| t.srgb).count();
    println!("textures:     {} ({} sRGB, {} linear), {}", s.textures.len(), srgb, s.textures.len() - srgb, bytes(s.texture_bytes()));
    let b = s.bounds();
    println!("bounds:       min {} max {} (size {})", fmt_vec(b.min), fmt_vec(b.max), fmt_vec(b.diagonal()));
    println!("cameras:      {}", s.cameras.len());
    for (i, c) in s.cameras.iter().enumerate() {
        println!("  [{i}] {}: {}", c.name, camera_details(c));
    }
    let from = match l.camera_index {
        Some(i) => format!("[{i}] {}", s.cameras[i].name),
        None => "framing (the scene has no camera)".to_owned(),
    };
    let flags = if args.has_camera_flags() { ", with flags" } else { "" };
    println!("camera used:  {from}{flags}: {}", camera_details(&l.camera));
    println!("warnings:     {}", l.warnings.len());
    for w in &l.warnings {
        println!("  - {w}");
    }
    let g = s.gpu_bytes_estimate();
    println!(
        "GPU estimate: {} (positions {}, normals {}, uvs {}, triangles {}, material ids {}, materials {}, textures {}) + BVH",
        bytes(g.total()),
        bytes(g.positions),
        bytes(g.normals),
        bytes(g.uvs),
        bytes(g.triangles),
        bytes(g.material_ids),
        bytes(g.materials),
        bytes(g.textures)
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn number_formats() {
        assert_eq!(thousands(262087), "262,087");
        assert_eq!(thousands(32), "32");
        assert_eq!(thousands(1000), "1,000");
        assert_eq!(bytes(1000), "1000 B");
        assert_eq!(bytes(3 << 20), "3.0 MiB");
    }
}
