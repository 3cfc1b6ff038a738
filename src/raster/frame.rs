//! The one frame loop, shared by `reproduce` ([`crate::studies::render`]), `compare`
//! ([`crate::studies::compare`]) and the frame bench: project → cull → scan → shade → depth.
//! What a row is shaded with, and what a visible pixel keeps, is the caller's
//! [`Shading`]; the statistics over the visible pixels are [`super::stats`].

use super::mesh::Mesh;
use super::scan::{rows, Row, ScreenVertex};
use super::scene::{project, Scene};
use glam::{Mat3, Vec3 as G3};

/// How the mesh's quads are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Split {
    /// As the paper's quads (Tables 1–2: edge crossings of the quad).
    Quads,
    /// Each quad as two triangles, split along the diagonal from its first to its
    /// third vertex (the comparison: Bishop–Weimer's and Seiler's methods are defined
    /// over a triangle's affine normal field).
    Triangles,
}

/// A front-facing polygon of a frame, projected.
#[derive(Clone, Debug)]
pub struct Polygon {
    /// The projected vertices: four for a quad, three for a triangle.
    pub v: Vec<ScreenVertex>,
}

impl Polygon {
    /// The centroid of the vertices in screen coordinates, in `f64` (every polygon
    /// method takes its coordinates relative to it).
    pub fn centre(&self) -> (f64, f64) {
        let k = self.v.len() as f64;
        let x = self.v.iter().map(|s| f64::from(s.x)).sum::<f64>() / k;
        let y = self.v.iter().map(|s| f64::from(s.y)).sum::<f64>() / k;
        (x, y)
    }

    /// Depth at pixel `i` of `row`: on a triangle, its plane at the pixel centre
    /// (barycentric, in `f64`); on a quad, linear along the row between the edge
    /// crossings.
    pub fn depth(&self, row: &Row, i: usize) -> f32 {
        if self.v.len() == 3 {
            let x = f64::from(row.x_first) + i as f64 + 0.5;
            plane_z(&self.v, x, f64::from(row.y) + 0.5)
        } else {
            let n = row.x_last - row.x_first;
            let t = if n == 0 { 0.0 } else { i as f32 / n as f32 };
            row.left.z + t * (row.right.z - row.left.z)
        }
    }
}

/// Whether quad `q` of `mesh`, rotated by `rot`, faces the viewer (+z): the one
/// back-face test, on the face normal from the rotated positions' diagonals.
pub fn is_front(mesh: &Mesh, rot: &Mat3, q: &[u32; 4]) -> bool {
    let p: [G3; 4] = q.map(|i| *rot * mesh.positions[i as usize]);
    (p[2] - p[0]).cross(p[3] - p[1]).z > 0.0
}

/// Frame `f` of `mesh` in `scene`, projected and culled: the front-facing polygons.
pub fn polygons(mesh: &Mesh, scene: &Scene, f: u32, split: Split) -> Vec<Polygon> {
    let rot = scene.rotation(f);
    let verts = project(mesh, scene, &rot);
    let mut out = Vec::new();
    for q in &mesh.quads {
        if !is_front(mesh, &rot, q) {
            continue;
        }
        let vs = |t: &[u32]| Polygon {
            v: t.iter().map(|&i| verts[i as usize]).collect(),
        };
        match split {
            Split::Quads => out.push(vs(q)),
            Split::Triangles => {
                out.push(vs(&[q[0], q[1], q[2]]));
                out.push(vs(&[q[0], q[2], q[3]]));
            }
        }
    }
    out
}

/// What a frame is shaded with.
pub trait Shading {
    /// What one row's shading produces.
    type Row;
    /// Called once per polygon before its rows; `false` skips the polygon.
    fn polygon(&mut self, _k: usize, _poly: &Polygon) -> bool {
        true
    }
    /// Shades `row` of polygon `k`; `None` drops the row (nothing is drawn).
    fn row(&mut self, k: usize, poly: &Polygon, row: &Row) -> Option<Self::Row>;
    /// Keeps pixel `i` of a shaded row at image index `pixel`, which it won the depth
    /// test of.
    fn store(&mut self, row: &Self::Row, i: usize, pixel: usize);
}

/// Draws `polys` into a `width × height` depth buffer: scan conversion
/// ([`super::scan::rows`]), [`Shading::row`] per row, and per pixel the depth test
/// (nearer, larger `z`, wins) before [`Shading::store`]. Returns how many times each
/// pixel was written before the depth test.
pub fn draw<S: Shading>(width: u32, height: u32, polys: &[Polygon], s: &mut S) -> Vec<u32> {
    let npix = (width * height) as usize;
    let mut depth = vec![f32::NEG_INFINITY; npix];
    let mut writes = vec![0u32; npix];
    for (k, poly) in polys.iter().enumerate() {
        if !s.polygon(k, poly) {
            continue;
        }
        rows(&poly.v, width, height, |row| {
            let Some(shaded) = s.row(k, poly, &row) else {
                return;
            };
            for (i, x) in (row.x_first..=row.x_last).enumerate() {
                let idx = (row.y as u32 * width + x as u32) as usize;
                writes[idx] += 1;
                let z = poly.depth(&row, i);
                if z > depth[idx] {
                    depth[idx] = z;
                    s.store(&shaded, i, idx);
                }
            }
        });
    }
    writes
}

/// Depth at `(x, y)` on the plane of triangle `v` (barycentric, in `f64`).
fn plane_z(v: &[ScreenVertex], x: f64, y: f64) -> f32 {
    let (x0, y0) = (f64::from(v[0].x), f64::from(v[0].y));
    let (x1, y1) = (f64::from(v[1].x), f64::from(v[1].y));
    let (x2, y2) = (f64::from(v[2].x), f64::from(v[2].y));
    let det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    if det == 0.0 {
        return v[0].z;
    }
    let l1 = ((x - x0) * (y2 - y0) - (x2 - x0) * (y - y0)) / det;
    let l2 = ((x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)) / det;
    let z = f64::from(v[0].z) * (1.0 - l1 - l2) + f64::from(v[1].z) * l1 + f64::from(v[2].z) * l2;
    z as f32
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raster::mesh::{torus, NormalMode};

    struct Count(u64);
    impl Shading for Count {
        type Row = ();
        fn row(&mut self, _: usize, _: &Polygon, _: &Row) -> Option<()> {
            Some(())
        }
        fn store(&mut self, _: &(), _: usize, _: usize) {
            self.0 += 1;
        }
    }

    /// Culling keeps about half the quads; triangles cover the same pixels as their
    /// quads; every visible pixel is written at least once.
    #[test]
    fn cull_split_and_draw() {
        let mesh = torus(24, 12, 1.0, 0.4, NormalMode::Analytic);
        let scene = Scene::new(64, 64, 1.4);
        let quads = polygons(&mesh, &scene, 3, Split::Quads);
        let tris = polygons(&mesh, &scene, 3, Split::Triangles);
        assert_eq!(tris.len(), 2 * quads.len());
        assert!(quads.len() > mesh.quads.len() / 4 && quads.len() < mesh.quads.len());
        let (mut a, mut b) = (Count(0), Count(0));
        let wa = draw(64, 64, &quads, &mut a);
        let wb = draw(64, 64, &tris, &mut b);
        let cov = |w: &[u32]| w.iter().filter(|&&n| n > 0).count();
        assert_eq!(cov(&wa), cov(&wb));
        assert!(a.0 >= cov(&wa) as u64 && cov(&wa) > 500);
    }
}
