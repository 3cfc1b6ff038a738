//! The row set-ups against the exact field and against each other.

use super::*;

fn field() -> Field<f64> {
    Field::<f64>::new(
        [0.011, -0.004, 0.002],
        [0.003, 0.013, -0.001],
        [0.12, 0.07, 0.98],
        [-0.4, 0.4, 0.8f64.sqrt()],
    )
}

/// A batch gives the same bits as the rows one at a time, and `for_each_row`
/// hands every row over once, in order, whatever the count.
#[test]
fn a_batch_is_its_rows() {
    let f = Field::<f32>::new(
        [0.011, -0.004, 0.002],
        [0.003, 0.013, -0.001],
        [0.12, 0.07, 0.98],
        [-0.4, 0.4, 0.8f32.sqrt()],
    );
    let rows: Vec<(f32, f32, u32)> = (0..19)
        .map(|i| (-3.5 + 0.5 * i as f32, -4.5 + i as f32, i % 7))
        .collect();
    for count in [0, 1, 7, 8, 9, 16, 19] {
        let mut seen = Vec::new();
        f.for_each_row(rows[..count].iter().copied(), |r, row| {
            let (x, y, n) = rows[r];
            assert_eq!(*row, f.row(x, y, n), "row {r} of {count}");
            seen.push(r);
        });
        assert_eq!(seen, (0..count).collect::<Vec<_>>());
    }
}

/// A degenerate or non-finite triangle has no field; a proper one takes its vertex
/// normals at its vertices.
#[test]
fn from_triangle_refuses_bad_triangles() {
    let nrm = [[0.0, 0.0, 1.0], [0.6, 0.0, 0.8], [0.0, 0.6, 0.8]];
    let l = [0.0, 0.0, 1.0];
    for v in [
        [[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]],
        [[0.0, 0.0], [0.0, 0.0], [0.0, 3.0]],
        [[0.0, 0.0], [f64::NAN, 0.0], [0.0, 3.0]],
        [[0.0, 0.0], [f64::INFINITY, 0.0], [0.0, 3.0]],
    ] {
        assert!(Field::<f64>::from_triangle(v, nrm, l).is_none(), "{v:?}");
    }
    let v = [[0.0, 0.0], [4.0, 0.0], [0.0, 2.0]];
    let f = Field::<f64>::from_triangle(v, nrm, l).expect("a proper triangle");
    for (p, n) in v.iter().zip(nrm) {
        let u = f.at(p[0], p[1]);
        assert!((0..3).all(|j| (u[j] - n[j]).abs() < 1e-15), "{p:?}: {u:?}");
    }
}

/// Stepping reproduces the field, and a restart happens on time.
#[test]
fn stepping_follows_the_field() {
    let f = field();
    let mut e = EdgeStepper::<f64>::new(&f, -2.5, -6.5);
    for (k, dx) in [1.0, 0.0, -1.0, 2.0, 0.0, 1.0, -3.0, 1.0, 1.0, 0.0]
        .into_iter()
        .enumerate()
    {
        e.step(&f, dx);
        let d = f.start(e.x, e.y);
        assert!((e.start.q - d.q).abs() < 1e-14, "row {k}");
        assert!((e.start.s - d.s).abs() < 1e-14 && (e.start.g - d.g).abs() < 1e-14);
        assert!(e.since_restart < EdgeStepper::<f64>::RESTART);
    }
}

/// One-pixel rows give `N·L`, and every kernel fills exactly `n + 1` values.
#[test]
fn one_pixel_rows_and_lengths() {
    let f = field();
    let r = f.row(0.5, 0.5, 0);
    let u = f.at(0.5, 0.5);
    let nl = dot_f64(u, f.l) / dot_f64(u, u).sqrt();
    let mut out = [7.0; 3];
    r.corrected_euler(&mut out);
    assert!((out[0] - nl).abs() < 1e-15 && out[1] == 7.0);
    r.phong(&mut out);
    assert!((out[0] - nl).abs() < 1e-15 && out[1] == 7.0);
    r.gouraud(&mut out);
    assert!((out[0] - nl).abs() < 1e-15 && out[1] == 7.0);
}

fn dot_f64(u: [f64; 3], v: [f64; 3]) -> f64 {
    u[0] * v[0] + u[1] * v[1] + u[2] * v[2]
}
