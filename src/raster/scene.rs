//! The scene of the experiment: image size, projection, light, rotation per frame.

use super::mesh::Mesh;
use super::scan::ScreenVertex;
use glam::{Mat3, Vec3 as G3};

/// The fixed scene of the experiment.
#[derive(Clone, Debug)]
pub struct Scene {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Pixels per world unit of the orthographic projection.
    pub scale: f32,
    /// Unit light direction (towards the light), in view space.
    pub light: G3,
    /// Unit view direction (towards the viewer): +z.
    pub view: G3,
    /// Diffuse coefficient `K_d` (intensity = `K_d·N·L`).
    pub kd: f32,
    /// Rotation per frame about x, y and z, in degrees.
    pub rates_deg: G3,
}

impl Scene {
    /// The default scene for a `width × height` image: light from the upper left
    /// front, `normalize(−1, 1, 2)`; `K_d = 1`; rotation 1.8°, 1.1° and 0.7° per frame
    /// about x, y and z; a scale that fits a torus of outer radius `outer` with 5 %
    /// margin.
    pub fn new(width: u32, height: u32, outer: f32) -> Scene {
        let scale = 0.95 * 0.5 * (width.min(height) as f32) / outer;
        Scene {
            width,
            height,
            scale,
            light: G3::new(-1.0, 1.0, 2.0).normalize(),
            view: G3::Z,
            kd: 1.0,
            rates_deg: G3::new(1.8, 1.1, 0.7),
        }
    }

    /// The rotation of frame `f`: about x, then y, then z.
    pub fn rotation(&self, f: u32) -> Mat3 {
        let a = self.rates_deg * (f as f32).to_radians();
        Mat3::from_rotation_z(a.z) * Mat3::from_rotation_y(a.y) * Mat3::from_rotation_x(a.x)
    }

    /// The half vector `H = normalize(L + V)` for specular light.
    pub fn half(&self) -> G3 {
        (self.light + self.view).normalize()
    }
}

/// The mesh's vertices rotated by `rot` and projected orthographically into `scene`'s
/// image, with their rotated normals and vertex (Gouraud) intensities.
pub fn project(mesh: &Mesh, scene: &Scene, rot: &Mat3) -> Vec<ScreenVertex> {
    let (cx, cy) = (scene.width as f32 / 2.0, scene.height as f32 / 2.0);
    mesh.positions
        .iter()
        .zip(&mesh.normals)
        .map(|(p, n)| {
            let p = *rot * *p;
            let n = *rot * *n;
            ScreenVertex {
                x: cx + scene.scale * p.x,
                y: cy - scene.scale * p.y,
                z: p.z,
                normal: n,
                intensity: n.dot(scene.light),
            }
        })
        .collect()
}
