//! An analytic clear sky baked into an environment map (`--sky`): A. J. Preetham, P. Shirley
//! and B. Smits, "A Practical Analytic Model for Daylight", SIGGRAPH 1999.
//!
//! Each of luminance Y and chromaticity x, y follows Perez et al.'s all-weather model (the
//! paper's eq. 3), normalised by its value at the zenith:
//!
//! ```text
//! F(theta, gamma) = (1 + A exp(B / cos theta)) (1 + C exp(D gamma) + E cos^2 gamma)
//! Y(theta, gamma) = Y_z F(theta, gamma) / F(0, theta_s)
//! ```
//!
//! theta is the view direction's angle from the zenith, gamma its angle to the sun, theta_s
//! the sun's zenith angle. A..E are linear in the turbidity T (Appendix A.2), the zenith
//! luminance Y_z (kcd/m^2) and chromaticities x_z, y_z are the paper's fits (Appendix A.2).
//! xyY becomes CIE XYZ and then linear Rec. 709 RGB (D65). Luminance is turned into the
//! renderer's radiance at 683 lm/W (so with `scale=1` the zenith of a clear noon sky is about
//! 10, and a matching sun of 100 klux is `--sun "...;146,146,146"`), times `scale`.
//!
//! The model holds above the horizon only; below it the map shows a Lambertian ground of
//! albedo `albedo` lit by the sky (and the sun, where `--sun` gives its irradiance): radiance
//! albedo / pi times the irradiance on a horizontal surface.

use super::env::Environment;
use glam::{DVec3, Vec3};
use std::f64::consts::PI;

/// What `--sky` asked for: `"turbidity=T;albedo=A;scale=S;sun=X,Y,Z"`, any subset.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SkySpec {
    /// Atmospheric turbidity (2: very clear, 3: clear, 6: hazy), in [1.7, 10].
    pub turbidity: f64,
    /// Ground albedo below the horizon, in [0, 1].
    pub albedo: f64,
    /// Multiplies the radiance.
    pub scale: f64,
    /// Direction toward the sun (else `--sun`'s).
    pub sun: Option<Vec3>,
}

impl Default for SkySpec {
    fn default() -> Self {
        SkySpec { turbidity: 3.0, albedo: 0.3, scale: 1.0, sun: None }
    }
}

impl std::str::FromStr for SkySpec {
    type Err = String;
    fn from_str(s: &str) -> Result<SkySpec, String> {
        let mut spec = SkySpec::default();
        let usage = |what: &str| {
            format!(
                "--sky '{}': {what} (expected \"turbidity=T;albedo=A;scale=S;sun=X,Y,Z\", any of them: T in [1.7, 10], A in [0, 1], S >= 0)",
                crate::text::quote(s)
            )
        };
        for item in s.split(';').map(str::trim).filter(|i| !i.is_empty()) {
            let (key, value) = item.split_once('=').ok_or_else(|| usage(&format!("'{}' is not KEY=VALUE", crate::text::quote(item))))?;
            let number = || value.trim().parse::<f64>().ok().filter(|v| v.is_finite());
            match key.trim() {
                "turbidity" => spec.turbidity = number().filter(|t| (1.7..=10.0).contains(t)).ok_or_else(|| usage("bad turbidity"))?,
                "albedo" => spec.albedo = number().filter(|a| (0.0..=1.0).contains(a)).ok_or_else(|| usage("bad albedo"))?,
                "scale" => spec.scale = number().filter(|a| *a >= 0.0).ok_or_else(|| usage("bad scale"))?,
                "sun" => {
                    let v = super::parse_vec3(value).map_err(|_| usage("bad sun direction"))?;
                    spec.sun = Some(v.try_normalize().ok_or_else(|| usage("the sun direction is zero"))?);
                }
                other => return Err(usage(&format!("unknown key '{}'", crate::text::quote(other)))),
            }
        }
        Ok(spec)
    }
}

/// Perez et al.'s coefficients A..E for one quantity, linear in turbidity: (slope, offset).
type Perez = [(f64, f64); 5];

/// Preetham et al. 1999, Appendix A.2: the distribution coefficients of Y, x and y.
const PEREZ_Y: Perez = [(0.1787, -1.4630), (-0.3554, 0.4275), (-0.0227, 5.3251), (0.1206, -2.5771), (-0.0670, 0.3703)];
const PEREZ_X: Perez = [(-0.0193, -0.2592), (-0.0665, 0.0008), (-0.0004, 0.2125), (-0.0641, -0.8989), (-0.0033, 0.0452)];
const PEREZ_YC: Perez = [(-0.0167, -0.2608), (-0.0950, 0.0092), (-0.0079, 0.2102), (-0.0441, -1.6537), (-0.0109, 0.0529)];

/// Zenith chromaticity fits (Appendix A.2): rows for T^2, T, 1; columns for theta_s^3,
/// theta_s^2, theta_s, 1.
const ZENITH_X: [[f64; 4]; 3] =
    [[0.00166, -0.00375, 0.00209, 0.0], [-0.02903, 0.06377, -0.03202, 0.00394], [0.11693, -0.21196, 0.06052, 0.25886]];
const ZENITH_Y: [[f64; 4]; 3] =
    [[0.00275, -0.00610, 0.00317, 0.0], [-0.04214, 0.08970, -0.04153, 0.00516], [0.15346, -0.26756, 0.06670, 0.26688]];

/// Luminous efficacy that turns luminance (cd/m^2) into the renderer's radiance.
const LUMENS_PER_WATT: f64 = 683.0;

/// The sky of Preetham et al. for one sun position and turbidity.
#[derive(Clone, Copy, Debug)]
pub struct Preetham {
    /// A..E of Y, x and y at this turbidity.
    coeffs: [[f64; 5]; 3],
    /// Zenith values (Y in kcd/m^2, x, y).
    zenith: [f64; 3],
    sun: DVec3,
    theta_s: f64,
}

impl Preetham {
    /// The sky for unit direction `sun` toward the sun (above the horizon) and `turbidity`.
    pub fn new(sun: Vec3, turbidity: f64) -> Preetham {
        let sun = sun.as_dvec3().normalize();
        let theta_s = sun.y.clamp(-1.0, 1.0).acos();
        let t = turbidity;
        let line = |p: &Perez| p.map(|(a, b)| a * t + b);
        let chi = (4.0 / 9.0 - t / 120.0) * (PI - 2.0 * theta_s);
        let y_z = (4.0453 * t - 4.9710) * chi.tan() - 0.2155 * t + 2.4192;
        let poly = |m: &[[f64; 4]; 3]| {
            let th = [theta_s.powi(3), theta_s * theta_s, theta_s, 1.0];
            let row = |r: &[f64; 4]| r.iter().zip(th).map(|(c, x)| c * x).sum::<f64>();
            t * t * row(&m[0]) + t * row(&m[1]) + row(&m[2])
        };
        Preetham {
            coeffs: [line(&PEREZ_Y), line(&PEREZ_X), line(&PEREZ_YC)],
            zenith: [y_z, poly(&ZENITH_X), poly(&ZENITH_Y)],
            sun,
            theta_s,
        }
    }

    /// Perez et al.'s distribution F(theta, gamma) with coefficients `c`.
    fn perez(c: &[f64; 5], cos_theta: f64, gamma: f64) -> f64 {
        let cos_g = gamma.cos();
        (1.0 + c[0] * (c[1] / cos_theta).exp()) * (1.0 + c[2] * (c[3] * gamma).exp() + c[4] * cos_g * cos_g)
    }

    /// CIE xyY (Y in kcd/m^2) seen looking along unit `w` (above the horizon: w.y > 0).
    pub fn xyy(&self, w: Vec3) -> [f64; 3] {
        let w = w.as_dvec3().normalize();
        let cos_theta = w.y.max(1e-4);
        let gamma = w.dot(self.sun).clamp(-1.0, 1.0).acos();
        let mut out = [0.0; 3];
        for (k, c) in self.coeffs.iter().enumerate() {
            out[k] = self.zenith[k] * Self::perez(c, cos_theta, gamma) / Self::perez(c, 1.0, self.theta_s);
        }
        [out[1], out[2], out[0]]
    }

    /// Linear Rec. 709 radiance seen looking along `w` (above the horizon), at 683 lm/W.
    pub fn radiance(&self, w: Vec3) -> DVec3 {
        let [x, y, lum] = self.xyy(w);
        let lum = lum * 1000.0 / LUMENS_PER_WATT;
        let xyz = DVec3::new(x * lum / y, lum, (1.0 - x - y) * lum / y);
        // CIE XYZ to linear sRGB / Rec. 709 primaries, D65 white (IEC 61966-2-1).
        DVec3::new(
            3.2406 * xyz.x - 1.5372 * xyz.y - 0.4986 * xyz.z,
            -0.9689 * xyz.x + 1.8758 * xyz.y + 0.0415 * xyz.z,
            0.0557 * xyz.x - 0.2040 * xyz.y + 1.0570 * xyz.z,
        )
    }
}

impl Environment {
    /// `spec`'s sky as a `width` x `height` map (texel centres; conventions of `env.rs`,
    /// turned by `rotate_deg` so that the sky stays fixed to `sun` whatever `--env-rotate`),
    /// with ground below the horizon lit by the sky and by `sun_irradiance` (a sun of that
    /// irradiance, facing it, in direction `sun`).
    pub fn preetham_sky(spec: &SkySpec, sun: Vec3, sun_irradiance: Vec3, rotate_deg: f32, width: u32, height: u32) -> Environment {
        let sky = Preetham::new(sun, spec.turbidity);
        let dir = |col: u32, row: u32| {
            let theta = PI * (row as f64 + 0.5) / height as f64;
            let a = 2.0 * PI * (col as f64 + 0.5) / width as f64 - PI - (rotate_deg as f64).to_radians();
            Vec3::new((theta.sin() * a.sin()) as f32, theta.cos() as f32, (-theta.sin() * a.cos()) as f32)
        };
        let mut texels = vec![Vec3::ZERO; (width * height) as usize];
        let mut e_sky = DVec3::ZERO;
        for row in 0..height {
            let omega = 2.0 * PI / width as f64 * ((PI * row as f64 / height as f64).cos() - (PI * (row + 1) as f64 / height as f64).cos());
            for col in 0..width {
                let w = dir(col, row);
                if w.y > 0.0 {
                    let l = sky.radiance(w).max(DVec3::ZERO) * spec.scale;
                    e_sky += l * w.y as f64 * omega;
                    texels[(row * width + col) as usize] = l.as_vec3();
                }
            }
        }
        let e_sun = sun_irradiance.as_dvec3() * sun.normalize().y.max(0.0) as f64;
        let ground = ((e_sky + e_sun) * (spec.albedo / PI)).as_vec3();
        for row in 0..height {
            for col in 0..width {
                if dir(col, row).y <= 0.0 {
                    texels[(row * width + col) as usize] = ground;
                }
            }
        }
        let source = format!("sky turbidity={};albedo={};scale={}", spec.turbidity, spec.albedo, spec.scale);
        Environment { rotate_deg, ..Environment::from_texels(&source, width, height, texels) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spec_parses() {
        assert_eq!("".parse::<SkySpec>().unwrap(), SkySpec::default());
        let s: SkySpec = "turbidity=5; albedo=0.1;sun=0,2,0".parse().unwrap();
        assert_eq!((s.turbidity, s.albedo, s.sun), (5.0, 0.1, Some(Vec3::Y)));
        for bad in ["turbidity=1", "turbidity=11", "albedo=2", "sun=0,0,0", "haze=3", "turbidity", "scale=-1", "turbidity=nan"] {
            let e = bad.parse::<SkySpec>().unwrap_err();
            assert!(e.contains("--sky"), "{bad}: {e}");
        }
    }

    /// The map's lookup (`Environment::radiance`) sees, at a texel's centre, the sky of that
    /// direction: baking inverts the lookup, rotation included.
    #[test]
    fn bake_inverts_the_lookup() {
        let sun = Vec3::new(0.4, 0.7, -0.3).normalize();
        let spec = SkySpec::default();
        for rotate in [0.0, 37.0] {
            let env = Environment::preetham_sky(&spec, sun, Vec3::ZERO, rotate, 64, 32);
            let sky = Preetham::new(sun, spec.turbidity);
            let w = Vec3::new(0.2, 0.5, 0.6).normalize();
            let got = env.radiance(w);
            let want = sky.radiance(w).as_vec3();
            // Within the change of the sky across one texel.
            assert!((got - want).abs().max_element() < 0.05 * want.max_element(), "rotate {rotate}: {got} vs {want}");
        }
    }
}
