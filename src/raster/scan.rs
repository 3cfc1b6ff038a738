//! Scan conversion of convex polygons.
//!
//! Fill convention: a pixel `(x, y)` is covered when its centre `(x + ½, y + ½)` is
//! inside the polygon, with the top-left rule on the boundary — a centre exactly on a
//! left edge or a top edge is inside, one on a right or bottom edge is not. Rows are
//! taken where `y_top ≤ y + ½ < y_bottom`, and on a row the pixels whose centre lies in
//! `[x_left, x_right)`. Two polygons that share an edge therefore never both cover a
//! pixel on it, and a mesh that tiles a region covers each pixel exactly once. Every
//! edge is evaluated from its endpoints in a fixed order (top endpoint first), so the
//! two polygons sharing it compute bit-identical crossings.

use glam::Vec3;

/// A projected vertex with the attributes interpolated along edges.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScreenVertex {
    /// Screen x in pixels (0 at the left border).
    pub x: f32,
    /// Screen y in pixels (0 at the top border, growing downwards).
    pub y: f32,
    /// Depth (larger is nearer the viewer).
    pub z: f32,
    /// The vertex normal (interpolated linearly along edges, normalized per row).
    pub normal: Vec3,
    /// The vertex intensity for classic Gouraud.
    pub intensity: f32,
}

/// The attributes where a row's centre line crosses an edge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EdgePoint {
    /// Crossing x.
    pub x: f32,
    /// Depth there.
    pub z: f32,
    /// The linearly interpolated (not yet normalized) normal.
    pub normal: Vec3,
    /// The linearly interpolated vertex intensity.
    pub intensity: f32,
}

/// One row of a polygon: pixels `x_first..=x_last` on row `y`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Row {
    /// Row index.
    pub y: i32,
    /// First covered pixel.
    pub x_first: i32,
    /// Last covered pixel (≥ `x_first`).
    pub x_last: i32,
    /// The left edge at this row.
    pub left: EdgePoint,
    /// The right edge at this row.
    pub right: EdgePoint,
}

fn crossing(a: &ScreenVertex, b: &ScreenVertex, yc: f32) -> Option<EdgePoint> {
    // Canonical order: top endpoint first (ties by x), so shared edges agree bitwise.
    let (lo, hi) = if (a.y, a.x) <= (b.y, b.x) {
        (a, b)
    } else {
        (b, a)
    };
    if !(lo.y <= yc && yc < hi.y) {
        return None;
    }
    let t = (yc - lo.y) / (hi.y - lo.y);
    Some(EdgePoint {
        x: lo.x + t * (hi.x - lo.x),
        z: lo.z + t * (hi.z - lo.z),
        normal: lo.normal + t * (hi.normal - lo.normal),
        intensity: lo.intensity + t * (hi.intensity - lo.intensity),
    })
}

/// Calls `emit` for every non-empty row of the convex polygon `poly`, clipped to a
/// `width × height` viewport (rows outside are skipped; a row's pixel range is
/// clipped but its edge attributes are those of the unclipped edges).
pub fn rows(poly: &[ScreenVertex], width: u32, height: u32, mut emit: impl FnMut(Row)) {
    if poly.len() < 3 {
        return;
    }
    let (mut ymin, mut ymax) = (f32::INFINITY, f32::NEG_INFINITY);
    for v in poly {
        ymin = ymin.min(v.y);
        ymax = ymax.max(v.y);
    }
    if !(ymin.is_finite() && ymax.is_finite()) {
        return;
    }
    let y0 = ((ymin - 0.5).ceil() as i64).max(0);
    let y1 = ((ymax - 0.5).ceil() as i64 - 1).min(i64::from(height) - 1);
    for y in y0..=y1 {
        let yc = y as f32 + 0.5;
        let mut left: Option<EdgePoint> = None;
        let mut right: Option<EdgePoint> = None;
        for k in 0..poly.len() {
            let Some(c) = crossing(&poly[k], &poly[(k + 1) % poly.len()], yc) else {
                continue;
            };
            if left.is_none_or(|l| c.x < l.x) {
                left = Some(c);
            }
            if right.is_none_or(|r| c.x > r.x) {
                right = Some(c);
            }
        }
        let (Some(left), Some(right)) = (left, right) else {
            continue;
        };
        let x_first = ((left.x - 0.5).ceil() as i64).max(0);
        let x_last = ((right.x - 0.5).ceil() as i64 - 1).min(i64::from(width) - 1);
        if x_last < x_first {
            continue;
        }
        emit(Row {
            y: y as i32,
            x_first: x_first as i32,
            x_last: x_last as i32,
            left,
            right,
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f32, y: f32) -> ScreenVertex {
        ScreenVertex {
            x,
            y,
            z: 0.0,
            normal: Vec3::Z,
            intensity: 0.0,
        }
    }

    fn coverage(polys: &[Vec<ScreenVertex>], w: u32, h: u32) -> Vec<u32> {
        let mut count = vec![0u32; (w * h) as usize];
        for p in polys {
            rows(p, w, h, |r| {
                for x in r.x_first..=r.x_last {
                    count[(r.y as u32 * w + x as u32) as usize] += 1;
                }
            });
        }
        count
    }

    #[test]
    fn unit_square_on_pixel_centres_follows_top_left_rule() {
        // Square from (1.5, 1.5) to (3.5, 3.5): centres on its left/top edges are in,
        // on its right/bottom edges out → pixels x, y ∈ {1, 2}.
        let sq = vec![v(1.5, 1.5), v(3.5, 1.5), v(3.5, 3.5), v(1.5, 3.5)];
        let c = coverage(&[sq], 6, 6);
        for y in 0..6 {
            for x in 0..6 {
                let want = u32::from((1..=2).contains(&x) && (1..=2).contains(&y));
                assert_eq!(c[y * 6 + x], want, "pixel ({x}, {y})");
            }
        }
    }

    #[test]
    fn a_jittered_grid_of_quads_and_triangles_covers_each_pixel_once() {
        // A 9×7 grid of jittered vertices (some exactly on pixel centres), split into
        // quads and triangles, tiling [8, 72] × [8, 56].
        let (gw, gh) = (9usize, 7usize);
        let mut pts = Vec::new();
        for j in 0..gh {
            for i in 0..gw {
                let border = i == 0 || j == 0 || i == gw - 1 || j == gh - 1;
                let jitter = if border {
                    0.0
                } else {
                    ((i * 7 + j * 13) % 11) as f32 * 0.37 - 1.8
                };
                let onc = if (i + j) % 3 == 0 && !border {
                    0.5 - (jitter.fract())
                } else {
                    0.0
                };
                pts.push(v(
                    8.0 + 8.0 * i as f32 + jitter + onc,
                    8.0 + 8.0 * j as f32 - jitter * 0.7,
                ));
            }
        }
        let at = |i: usize, j: usize| pts[j * gw + i];
        let mut polys = Vec::new();
        for j in 0..gh - 1 {
            for i in 0..gw - 1 {
                let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                if (i + j) % 2 == 0 {
                    polys.push(vec![a, b, c, d]);
                } else {
                    polys.push(vec![a, b, c]);
                    polys.push(vec![a, c, d]);
                }
            }
        }
        let (w, h) = (80u32, 64u32);
        let c = coverage(&polys, w, h);
        for y in 0..h {
            for x in 0..w {
                let (cx, cy) = (x as f32 + 0.5, y as f32 + 0.5);
                let inside = (8.0..72.0).contains(&cx) && (8.0..56.0).contains(&cy);
                let got = c[(y * w + x) as usize];
                assert_eq!(
                    got,
                    u32::from(inside),
                    "pixel ({x}, {y}) covered {got} times"
                );
            }
        }
    }

    #[test]
    fn shared_edges_get_identical_attributes() {
        let a = v(10.3, 2.2);
        let b = v(13.9, 30.7);
        let left = vec![v(1.0, 1.0), a, b, v(2.0, 31.0)];
        let right = vec![a, v(25.0, 3.0), v(24.0, 29.0), b];
        let mut l_right = Vec::new();
        let mut r_left = Vec::new();
        rows(&left, 40, 40, |r| l_right.push((r.y, r.right.x, r.x_last)));
        rows(&right, 40, 40, |r| r_left.push((r.y, r.left.x, r.x_first)));
        // Rows both polygons reach: the shared edge spans y ∈ [2.2, 30.7).
        let mut shared = 0;
        for (y1, x1, last) in &l_right {
            if let Some((_, x2, first)) = r_left.iter().find(|r| r.0 == *y1) {
                if (*y1 as f32 + 0.5) >= 2.2 && (*y1 as f32 + 0.5) < 30.7 {
                    assert_eq!(x1.to_bits(), x2.to_bits(), "row {y1}");
                    assert_eq!(last + 1, *first, "row {y1}: gap or overlap");
                    shared += 1;
                }
            }
        }
        assert!(shared >= 27, "{shared} shared rows");
    }
}
