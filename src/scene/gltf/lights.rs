//! KHR_lights_punctual: the lights that nodes of the loaded scene reference, placed by their
//! world matrices (a light shines along its node's local -Z, as a camera looks).

use ::gltf::khr_lights_punctual::Kind;
use ::gltf::{Document, Node};
use glam::{Mat4, Vec3};

use super::local_matrix;
use crate::scene::{PunctualKind, PunctualLight};

/// Every punctual light under `roots` (the scene geometry() loaded; it has already rejected
/// cycles and non-finite transforms, which are skipped here).
pub fn punctual_lights(doc: &Document, roots: Vec<Node>) -> Vec<PunctualLight> {
    let mut lights = Vec::new();
    let mut stack: Vec<(Node, Mat4, usize)> = roots.into_iter().rev().map(|n| (n, Mat4::IDENTITY, 0)).collect();
    while let Some((node, parent, depth)) = stack.pop() {
        let Some(local) = local_matrix(&node) else {
            continue;
        };
        if depth > doc.nodes().len() {
            break;
        }
        let world = parent * local;
        if let Some(l) = node.light() {
            let kind = match l.kind() {
                Kind::Point => PunctualKind::Point,
                Kind::Directional => PunctualKind::Directional,
                Kind::Spot { inner_cone_angle, outer_cone_angle } => {
                    PunctualKind::Spot { inner: inner_cone_angle, outer: outer_cone_angle }
                }
            };
            let name = l.name().or(node.name()).map_or_else(|| format!("light {}", l.index()), str::to_owned);
            let direction = world.transform_vector3(-Vec3::Z).normalize_or_zero();
            lights.push(PunctualLight {
                name,
                kind,
                position: world.transform_point3(Vec3::ZERO),
                direction,
                intensity: Vec3::from(l.color()) * l.intensity(),
            });
        }
        stack.extend(node.children().map(|c| (c, world, depth + 1)).collect::<Vec<_>>().into_iter().rev());
    }
    lights
}
