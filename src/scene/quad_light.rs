//! Emissive parallelograms added to a loaded scene: generic `--quad-light` flags and the
//! `--sponza-sun-sky` preset (the thesis' modified Sponza, section 5.2.2: Crytek Sponza has no
//! emitters, so a small, very bright "sun" and a large, dim blue "sky" are placed above the
//! atrium's open roof, and light reaches most of the building only past occluders).
//!
//! A quad is given by a corner `c`, two edges `e1`, `e2` and a radiance. Its corners are `c`,
//! `c + e1`, `c + e1 + e2`, `c + e2`; it becomes two triangles, (c, c+e1, c+e1+e2) and
//! (c, c+e1+e2, c+e2), both counter-clockwise seen from its front, so it emits along
//! `e1 × e2` only (bidir's emitters are one-sided). Each quad gets a material of its own,
//! emissive and black (a sun or a sky reflects nothing).

use glam::{Vec2, Vec3};

use super::{Material, Scene};

/// Why a `--quad-light` value or a quad is not usable.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum QuadLightError {
    #[error("expected CORNER;EDGE1;EDGE2;R,G,B (four x,y,z groups separated by ';'), got '{0}'")]
    Groups(String),
    #[error("{what}: {msg}")]
    Number { what: &'static str, msg: String },
    #[error("edges {e1} and {e2} are parallel or zero: the quad has no area")]
    NoArea { e1: String, e2: String },
    #[error("radiance {0} must be >= 0 in every channel and > 0 in one")]
    Radiance(String),
    #[error("corner and edges must be finite")]
    NotFinite,
    #[error("radiance {0:e} is too large (limit {max:e} per channel, and pi x area x radiance must be finite)", max = crate::limits::MAX_RADIANCE)]
    RadianceTooLarge(f32),
}

/// An emissive parallelogram (see the module documentation for the conventions).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuadLight {
    pub corner: Vec3,
    pub edge1: Vec3,
    pub edge2: Vec3,
    /// Emitted radiance, linear RGB, from the front face.
    pub radiance: Vec3,
}

impl QuadLight {
    /// Checks the quad: finite, non-zero area, radiance >= 0 with one channel > 0.
    pub fn new(corner: Vec3, edge1: Vec3, edge2: Vec3, radiance: Vec3) -> Result<QuadLight, QuadLightError> {
        let q = QuadLight { corner, edge1, edge2, radiance };
        if !(corner.is_finite() && edge1.is_finite() && edge2.is_finite()) {
            return Err(QuadLightError::NotFinite);
        }
        // Relative test: parallel edges of any length, and zero-length ones, have no area.
        let cross = edge1.cross(edge2).length();
        if !(cross.is_finite() && cross > 1e-6 * edge1.length() * edge2.length() && cross > 0.0) {
            return Err(QuadLightError::NoArea { e1: fmt3(edge1), e2: fmt3(edge2) });
        }
        if !(radiance.is_finite() && radiance.min_element() >= 0.0 && radiance.max_element() > 0.0) {
            return Err(QuadLightError::Radiance(fmt3(radiance)));
        }
        let power = std::f32::consts::PI * cross * radiance.max_element();
        if radiance.max_element() > crate::limits::MAX_RADIANCE || !power.is_finite() {
            return Err(QuadLightError::RadianceTooLarge(radiance.max_element()));
        }
        Ok(q)
    }

    /// A `size` x `size` square centred on `center`, emitting along `normal` (any length).
    pub fn facing(center: Vec3, normal: Vec3, size: f32, radiance: Vec3) -> Result<QuadLight, QuadLightError> {
        let n = normal.normalize_or_zero();
        let helper = if n.x.abs() < 0.9 { Vec3::X } else { Vec3::Y };
        let u = (helper - n * helper.dot(n)).normalize_or_zero();
        // u × (n × u) = n for unit, orthogonal n and u: the front faces `normal`.
        let (e1, e2) = (size * u, size * n.cross(u));
        QuadLight::new(center - 0.5 * (e1 + e2), e1, e2, radiance)
    }

    /// Unit normal of the emitting (front) face.
    pub fn front(&self) -> Vec3 {
        self.edge1.cross(self.edge2).normalize()
    }

    pub fn area(&self) -> f32 {
        self.edge1.cross(self.edge2).length()
    }

    /// The preset `--sponza-sun-sky`, for Crytek Sponza as in `scenes/sponza` (Y up, bounds
    /// (-26.84, 2.28, -16.48) .. (24.18, 23.62, 14.90)). Its atrium is open to the sky over
    /// x in [-14.2, 11.4], z in [-3.7, 2.2] (narrowest, 15.5 to 21.5 high; roof top 23.6), the
    /// courtyard floor is at y = 4, the ground-floor arcades' columns stand at z = -4 and 2.5.
    ///
    /// - Sun: a 2 x 2 square at y = 38, about 37 units from the courtyard floor, in direction
    ///   (0.4, 1, 0.2) (24 degrees from the zenith, from +x and +z): through the narrow opening
    ///   it lights a band of the courtyard floor that crosses the -z arcade's columns, so
    ///   their shadows and the light beyond them are "light entering past an occluder"; the
    ///   +z half of the courtyard, both galleries and the far end lie in its shadow. Radiance
    ///   4000 x (1, 0.92, 0.8) gives the sunlit floor an irradiance of about 10.
    /// - Sky: a dim blue 117 x 87 rectangle at y = 40, facing down, above the sun so the sun
    ///   is not hidden behind it, wide enough that about 98 % of the rays leaving the building
    ///   through the opening (sampled from inside) meet it.
    pub fn sponza_sun_sky() -> [QuadLight; 2] {
        let sun_dir = Vec3::new(0.4, 1.0, 0.2).normalize();
        let aim = Vec3::new(-2.0, 4.0, -3.0);
        let sun_center = aim + sun_dir * ((38.0 - aim.y) / sun_dir.y);
        let sun = QuadLight::facing(sun_center, -sun_dir, 2.0, 4000.0 * Vec3::new(1.0, 0.92, 0.8));
        let sky =
            QuadLight::new(Vec3::new(-60.0, 40.0, -45.0), Vec3::new(117.0, 0.0, 0.0), Vec3::new(0.0, 0.0, 87.0), Vec3::new(0.25, 0.4, 0.8));
        [sun.expect("the sun preset is valid (tested)"), sky.expect("the sky preset is valid (tested)")]
    }
}

impl std::fmt::Display for QuadLight {
    /// The `--quad-light` syntax, so a quad prints as the flag value that makes it.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{};{};{};{}", fmt3(self.corner), fmt3(self.edge1), fmt3(self.edge2), fmt3(self.radiance))
    }
}

impl std::str::FromStr for QuadLight {
    type Err = QuadLightError;
    /// `CX,CY,CZ;E1X,E1Y,E1Z;E2X,E2Y,E2Z;R,G,B`.
    fn from_str(s: &str) -> Result<QuadLight, QuadLightError> {
        let groups: Vec<&str> = s.split(';').collect();
        if groups.len() != 4 {
            return Err(QuadLightError::Groups(s.to_owned()));
        }
        let names = ["corner", "edge1", "edge2", "radiance"];
        let mut v = [Vec3::ZERO; 4];
        for ((out, g), what) in v.iter_mut().zip(&groups).zip(names) {
            *out = parse_vec3(g).map_err(|msg| QuadLightError::Number { what, msg })?;
        }
        QuadLight::new(v[0], v[1], v[2], v[3])
    }
}

/// `x,y,z`, e.g. `278,273,-800`: three finite numbers (the CLI's vector syntax).
pub fn parse_vec3(s: &str) -> Result<Vec3, String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != 3 {
        return Err(format!("expected three numbers separated by commas (like 278,273,-800), got '{s}'"));
    }
    let mut v = [0.0f32; 3];
    for (out, p) in v.iter_mut().zip(&parts) {
        *out = p.parse::<f32>().ok().filter(|x| x.is_finite()).ok_or_else(|| format!("'{p}' in '{s}' is not a finite number"))?;
    }
    Ok(Vec3::from_array(v))
}

fn fmt3(v: Vec3) -> String {
    format!("{},{},{}", v.x, v.y, v.z)
}

impl Scene {
    /// Appends `quad` as two emissive triangles with a new material called `name`. New
    /// vertices get the quad's front normal where the scene has normals and UV (0, 0) where
    /// it has UVs, keeping those all-or-nothing. `quad` is taken as valid: make it with
    /// [`QuadLight::new`] or parse it, which check it.
    pub fn add_quad_light(&mut self, quad: &QuadLight, name: &str) {
        let base = self.positions.len() as u32;
        let c = quad.corner;
        self.positions.extend([c, c + quad.edge1, c + quad.edge1 + quad.edge2, c + quad.edge2]);
        if let Some(n) = &mut self.normals {
            n.extend([quad.front(); 4]);
        }
        if let Some(uv) = &mut self.uvs {
            uv.extend([Vec2::ZERO; 4]);
        }
        if let Some(t) = &mut self.tangents {
            t.extend([quad.edge1.normalize_or_zero().extend(1.0); 4]);
        }
        let material = self.materials.len() as u32;
        self.materials.push(Material { name: name.to_owned(), albedo: Vec3::ZERO, emission: quad.radiance, ..Material::default() });
        self.triangles.extend([[base, base + 1, base + 2], [base, base + 2, base + 3]]);
        self.material_ids.extend([material; 2]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f32::consts::PI;

    fn quad(s: &str) -> Result<QuadLight, QuadLightError> {
        s.parse()
    }

    #[test]
    fn parses_and_prints_the_flag_syntax() {
        let q = quad("1,2,3; 4,0,0 ;0,0,-2;10,5,0").unwrap();
        assert_eq!(
            q,
            QuadLight {
                corner: Vec3::new(1.0, 2.0, 3.0),
                edge1: Vec3::X * 4.0,
                edge2: Vec3::Z * -2.0,
                radiance: Vec3::new(10.0, 5.0, 0.0)
            }
        );
        assert_eq!(quad(&q.to_string()).unwrap(), q);
        // e1 = +x, e2 = -z: e1 x e2 = +y.
        assert_eq!(q.front(), Vec3::Y);
        assert_eq!(q.area(), 8.0);
    }

    #[test]
    fn bad_values_say_what_is_wrong() {
        let e = |s: &str| quad(s).unwrap_err().to_string();
        assert!(e("1,2,3;4,0,0;0,0,1").contains("four x,y,z groups"), "{}", e("1,2,3;4,0,0;0,0,1"));
        assert!(e("1,2,3;4,0,0;0,0,1;1,1,1;2,2,2").contains("got '1,2,3;4,0,0;0,0,1;1,1,1;2,2,2'"));
        assert_eq!(e("1,2;4,0,0;0,0,1;1,1,1"), "corner: expected three numbers separated by commas (like 278,273,-800), got '1,2'");
        assert_eq!(e("0,0,0;4,0,0;0,x,1;1,1,1"), "edge2: 'x' in '0,x,1' is not a finite number");
        assert!(e("0,0,0;4,0,0;0,0,1;1,nan,1").starts_with("radiance: 'nan'"));
        assert!(e("0,0,0;4,0,0;8,0,0;1,1,1").contains("parallel or zero"));
        assert!(e("0,0,0;0,0,0;0,0,1;1,1,1").contains("parallel or zero"));
        assert!(e("0,0,0;1,0,0;0,0,1;1,-1,1").contains("must be >= 0"));
        assert!(e("0,0,0;1,0,0;0,0,1;0,0,0").contains("> 0 in one"));
    }

    #[test]
    fn quads_add_emitters_with_their_power_and_facing() {
        let mut s = Scene::builtin_cornell_box();
        let (tris, mats, emitters) = (s.triangle_count(), s.materials.len(), s.emitters().len());
        let (p0, _) = s.total_emitted_power();
        let a = quad("0,600,0;0,0,100;50,0,0;2,3,4").unwrap(); // (0,0,1) x (1,0,0) = +y: faces up
        let b = quad("0,700,0;50,0,0;0,0,100;1,1,1").unwrap(); // faces down
        s.add_quad_light(&a, "a");
        s.add_quad_light(&b, "b");
        assert_eq!(s.triangle_count(), tris + 4);
        assert_eq!(s.materials.len(), mats + 2);
        let e = s.emitters();
        assert_eq!(e.len(), emitters + 4);
        for (q, name, tris) in [(a, "a", &e[emitters..emitters + 2]), (b, "b", &e[emitters + 2..])] {
            let power: Vec3 = tris.iter().map(|t| t.power).sum();
            let want = PI * 5000.0 * q.radiance;
            assert!((power - want).abs().max_element() < 1e-3 * want.max_element(), "{name}: {power} vs {want}");
            for t in tris {
                let m = s.material_of(t.triangle as usize);
                assert_eq!((m.name.as_str(), m.emission, m.albedo), (name, q.radiance, Vec3::ZERO));
                let [p0, p1, p2] = s.triangle_vertices(t.triangle as usize);
                let n = (p1 - p0).cross(p2 - p0).normalize();
                assert!((n - q.front()).length() < 1e-6, "{name}: triangle faces {n}, not {}", q.front());
            }
        }
        assert_eq!(a.front(), Vec3::Y);
        assert_eq!(b.front(), Vec3::NEG_Y);
        let (p1, _) = s.total_emitted_power();
        assert!((p1 - p0 - PI * 5000.0 * Vec3::new(3.0, 4.0, 5.0)).abs().max_element() < 1.0);
    }

    #[test]
    fn normals_and_uvs_stay_all_or_nothing() {
        let mut s = Scene::builtin_cornell_box();
        s.normals = Some(vec![Vec3::Y; s.positions.len()]);
        s.uvs = Some(vec![Vec2::ZERO; s.positions.len()]);
        let q = QuadLight::facing(Vec3::ZERO, Vec3::new(1.0, -1.0, 0.0), 3.0, Vec3::ONE).unwrap();
        s.add_quad_light(&q, "q");
        assert_eq!(s.normals.as_ref().unwrap().len(), s.positions.len());
        assert_eq!(s.uvs.as_ref().unwrap().len(), s.positions.len());
        assert_eq!(*s.normals.as_ref().unwrap().last().unwrap(), q.front());
    }

    #[test]
    fn facing_builds_a_square_toward_its_normal() {
        for n in [Vec3::X, Vec3::NEG_Y, Vec3::new(0.3, -1.0, 0.2), Vec3::new(-5.0, 0.1, 0.0)] {
            let q = QuadLight::facing(Vec3::new(1.0, 2.0, 3.0), n, 2.0, Vec3::ONE).unwrap();
            assert!((q.front() - n.normalize()).length() < 1e-5, "{n}: {}", q.front());
            assert!((q.area() - 4.0).abs() < 1e-4 && q.edge1.dot(q.edge2).abs() < 1e-5);
            assert!((q.corner + 0.5 * (q.edge1 + q.edge2) - Vec3::new(1.0, 2.0, 3.0)).length() < 1e-5);
        }
        assert!(QuadLight::facing(Vec3::ZERO, Vec3::ZERO, 1.0, Vec3::ONE).is_err());
        assert_eq!(QuadLight::new(Vec3::NAN, Vec3::X, Vec3::Z, Vec3::ONE), Err(QuadLightError::NotFinite));
    }

    #[test]
    fn sponza_preset_places_a_sun_below_a_sky_above_the_roof() {
        let [sun, sky] = QuadLight::sponza_sun_sky();
        const ROOF: f32 = 23.62;
        // The sky faces down, covers the atrium opening and lies above everything else.
        assert_eq!(sky.front(), Vec3::NEG_Y);
        let (lo, hi) = (sky.corner, sky.corner + sky.edge1 + sky.edge2);
        assert!(lo.x < -26.84 && hi.x > 24.18 && lo.z < -16.48 && hi.z > 14.90 && lo.y > ROOF);
        // The sun: small, far brighter than the sky, below the sky, above the roof, facing
        // down at an angle and toward the atrium.
        let corners = [sun.corner, sun.corner + sun.edge1, sun.corner + sun.edge2, sun.corner + sun.edge1 + sun.edge2];
        assert!(corners.iter().all(|c| c.y > ROOF + 10.0 && c.y < sky.corner.y));
        assert!(sun.area() < 0.01 * sky.area());
        assert!(sun.radiance.min_element() > 1000.0 * sky.radiance.max_element());
        let tilt = sun.front().dot(Vec3::NEG_Y).acos().to_degrees();
        assert!((15.0..35.0).contains(&tilt), "sun tilted {tilt} degrees from straight down");
        // Its central ray reaches the courtyard floor (y = 4) inside the courtyard.
        let c = sun.corner + 0.5 * (sun.edge1 + sun.edge2);
        let floor = c + sun.front() * ((4.0 - c.y) / sun.front().y);
        assert!((-14.0..11.0).contains(&floor.x) && (-4.5..2.5).contains(&floor.z), "{floor}");
        // Sky blue, sun yellowish white.
        assert!(sky.radiance.z > sky.radiance.y && sky.radiance.y > sky.radiance.x);
        assert!(sun.radiance.x >= sun.radiance.y && sun.radiance.y >= sun.radiance.z);
    }
}
