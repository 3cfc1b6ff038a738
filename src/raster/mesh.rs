//! Torus meshes of quads, as in §5 of the paper.

use glam::Vec3;
use std::f32::consts::TAU;

/// How vertex normals are made.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NormalMode {
    /// The torus's analytic surface normal at each vertex (default).
    Analytic,
    /// The normalized average of the normals of the four faces around each vertex.
    Averaged,
}

/// A quad mesh: shared vertices, each quad a list of four vertex indices wound
/// counter-clockwise as seen from outside the surface.
#[derive(Clone, Debug)]
pub struct Mesh {
    /// Vertex positions.
    pub positions: Vec<Vec3>,
    /// Unit vertex normals.
    pub normals: Vec<Vec3>,
    /// Quads as vertex indices.
    pub quads: Vec<[u32; 4]>,
}

/// A torus around the z axis: `ring` segments around the main ring, `tube` segments
/// around the tube, major radius `big_r`, tube radius `small_r`; `ring × tube` quads.
///
/// The paper's tori have 288, 512, 800 and 1152 polygons; [`paper_tori`] gives the
/// segment counts used here.
pub fn torus(ring: u32, tube: u32, big_r: f32, small_r: f32, mode: NormalMode) -> Mesh {
    let mut positions = Vec::with_capacity((ring * tube) as usize);
    let mut normals = Vec::with_capacity((ring * tube) as usize);
    for i in 0..ring {
        let u = TAU * i as f32 / ring as f32;
        for j in 0..tube {
            let v = TAU * j as f32 / tube as f32;
            let n = Vec3::new(v.cos() * u.cos(), v.cos() * u.sin(), v.sin());
            let centre = Vec3::new(big_r * u.cos(), big_r * u.sin(), 0.0);
            positions.push(centre + small_r * n);
            normals.push(n);
        }
    }
    let idx = |i: u32, j: u32| (i % ring) * tube + (j % tube);
    let mut quads = Vec::with_capacity((ring * tube) as usize);
    for i in 0..ring {
        for j in 0..tube {
            // Counter-clockwise seen from outside: along u, then along v.
            quads.push([idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)]);
        }
    }
    let mut mesh = Mesh {
        positions,
        normals,
        quads,
    };
    if mode == NormalMode::Averaged {
        mesh.normals = averaged_normals(&mesh);
    }
    mesh
}

/// The normalized average of the face normals around each vertex.
pub fn averaged_normals(mesh: &Mesh) -> Vec<Vec3> {
    let mut acc = vec![Vec3::ZERO; mesh.positions.len()];
    for q in &mesh.quads {
        let p: Vec<Vec3> = q.iter().map(|&i| mesh.positions[i as usize]).collect();
        let face = (p[2] - p[0]).cross(p[3] - p[1]).normalize_or_zero();
        for &i in q {
            acc[i as usize] += face;
        }
    }
    acc.into_iter().map(Vec3::normalize_or_zero).collect()
}

/// The four tori of the paper as `(polygons, ring segments, tube segments)`: the
/// ring has twice as many segments as the tube, so the quads are close to square on
/// a torus whose tube is about a third of its major radius.
pub fn paper_tori() -> [(u32, u32, u32); 4] {
    [(288, 24, 12), (512, 32, 16), (800, 40, 20), (1152, 48, 24)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polygon_counts_and_unit_outward_normals() {
        for (polys, ring, tube) in paper_tori() {
            for mode in [NormalMode::Analytic, NormalMode::Averaged] {
                let m = torus(ring, tube, 1.0, 0.4, mode);
                assert_eq!(m.quads.len() as u32, polys);
                for (p, n) in m.positions.iter().zip(&m.normals) {
                    assert!((n.length() - 1.0).abs() < 1e-5);
                    // Outward: away from the tube's centre line.
                    let c = Vec3::new(p.x, p.y, 0.0).normalize() * 1.0;
                    assert!(n.dot(*p - c) > 0.0);
                }
                // Faces wound counter-clockwise seen from outside.
                for q in &m.quads {
                    let p: Vec<Vec3> = q.iter().map(|&i| m.positions[i as usize]).collect();
                    let face = (p[2] - p[0]).cross(p[3] - p[1]);
                    assert!(face.dot(m.normals[q[0] as usize]) > 0.0);
                }
            }
        }
    }
}
