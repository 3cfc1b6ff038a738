//! One row of the paper's quads shaded by every column of [`super::COLUMNS`]: in `f32`
//! ([`shade_row`]), what Table 1 needs of it ([`RowExtra`]), and its exact levels for
//! the exact mode ([`exact_row`]).

use super::*;

fn vec3(v: G3) -> Vec3<f32> {
    Vec3::new(v.x, v.y, v.z)
}

/// What one row's span produces for every column.
pub(super) struct RowShade {
    pub(super) levels: Vec<Vec<u8>>,
    pub(super) specular: Vec<Vec<f32>>,
}

/// Shades a row's span with every column in `f32`, through the one row shader
/// ([`crate::raster::shader::shade_row`]): the span methods on the row's unit edge
/// normals, classic vertex Gouraud from the row's vertex intensities. `None` if the
/// normals are unusable (zero after interpolation).
pub(super) fn shade_row(
    scene: &Scene,
    row: &Row,
    prep: &Prepared<f32>,
    want_specular: bool,
) -> Option<(RowShade, RowExtra)> {
    let na = row.left.normal.try_normalize()?;
    let nb = row.right.normal.try_normalize()?;
    let n = (row.x_last - row.x_first) as u32;
    let kd = scene.kd;
    // One pixel: its normal is the edge normal, every method gives p_a.
    let span_to = |dir: G3| -> Option<Option<Span<f32>>> {
        match n {
            0 => Some(None),
            _ => Span::new(vec3(na), vec3(nb), vec3(dir), n).ok().map(Some),
        }
    };
    let span = span_to(scene.light)?;
    let mut out = vec![Vec::new(); COLUMNS.len()];
    let (a, b) = (row.left.intensity, row.right.intensity);
    // COLUMNS holds span methods and vertex Gouraud only
    // (`columns_are_span_methods_and_vertex_gouraud`).
    let choice = crate::raster::shader::shade_row(
        span.as_ref(),
        &na.dot(scene.light),
        prep,
        &COLUMNS,
        index,
        &mut out,
        &mut |sh, o| {
            debug_assert_eq!(sh, Shader::VertexGouraud);
            // Classic Gouraud: the vertex intensities, interpolated down the polygon's
            // edges and along the row.
            if n == 0 {
                o[0] = a;
            } else {
                for (i, o) in o.iter_mut().enumerate() {
                    *o = a + (b - a) * (i as f32 / n as f32);
                }
            }
            Some(())
        },
    )?;
    let levels: Vec<Vec<u8>> = out
        .iter()
        .map(|v| v.iter().map(|v| level(&(kd * v))).collect())
        .collect();
    let mut specular = vec![Vec::new(); COLUMNS.len()];
    if want_specular {
        let half = scene.half();
        let p_a = na.dot(half);
        let span_h = span_to(half)?;
        crate::raster::shader::shade_row(
            span_h.as_ref(),
            &p_a,
            prep,
            &COLUMNS,
            index,
            &mut specular,
            &mut |_, o| {
                // Classic Gouraud of N·H: vertex values are not kept per vertex here,
                // so the span's edge values (exact) are interpolated.
                match &span_h {
                    None => o[0] = p_a,
                    Some(s) => {
                        Method::Gouraud.run(s, prep, o).ok()?;
                    }
                }
                Some(())
            },
        )?;
        for v in specular.iter_mut().flatten() {
            *v = v.max(0.0);
        }
    }
    let extra = match span {
        None => RowExtra::single(),
        Some(span) => RowExtra {
            single: false,
            decision: choice.unwrap_or(Choice::CorrectedEuler),
            text_same: truncated_difference_is_zero(&out[index(PHONG)], &out[index(GOURAUD)], kd),
            span: Some(span),
        },
    };
    Some((RowShade { levels, specular }, extra))
}

/// The paper's text criterion of Table 1 on one row: "the difference of Phong and
/// Gouraud intensities was multiplied with 255 and then truncated" is zero at every
/// pixel, `trunc(255·K_d·(Ph_i − G_i)) = 0`, i.e. `|255·K_d·(Ph_i − G_i)| < 1`.
/// (Equal 8-bit levels imply it; it does not imply equal levels.)
pub fn truncated_difference_is_zero(phong: &[f32], gouraud: &[f32], kd: f32) -> bool {
    phong
        .iter()
        .zip(gouraud)
        .all(|(p, g)| (255.0 * kd * (p - g)).abs() < 1.0)
}

/// What Table 1 and the exact mode need of a row beyond its levels.
pub(super) struct RowExtra {
    pub(super) single: bool,
    pub(super) decision: Choice,
    /// The text's criterion of Table 1 (see [`RowStats::truncated_difference_zero`]).
    pub(super) text_same: bool,
    pub(super) span: Option<Span<f32>>,
}

impl RowExtra {
    fn single() -> Self {
        RowExtra {
            single: true,
            decision: Choice::Gouraud,
            text_same: true,
            span: None,
        }
    }
}

/// Exact levels of a row's span for every span column, for the exact mode: the same
/// span, its `f32` inputs converted exactly (they are within 2^-17 of unit length).
pub(super) fn exact_row(
    span: &Span<f32>,
    prep: &Prepared<BigRational>,
    got: &[Vec<u8>],
    check: &mut ExactCheck,
) {
    let tol = BigRational::new(1.into(), (1u64 << 16).into());
    let (Some(na), Some(nb), Some(l)) = (span.na.cast(), span.nb.cast(), span.l.cast()) else {
        return;
    };
    let Ok(exact) = Span::<BigRational>::with_tolerance(na, nb, l, span.n, &tol) else {
        return;
    };
    let cols = COLUMNS.len();
    if check.mismatches.is_empty() {
        check.mismatches = vec![0; cols];
        check.explained = vec![0; cols];
    }
    check.pixels += u64::from(span.n) + 1;
    let mut out = vec![BigRational::from_i64(0); span.len()];
    let kd = &prep.kd;
    let u = f32::unit_roundoff();
    // The one q_min of the bounds (`Span::q_min`, rounded down in `Shape::of`).
    let q_min = crate::tolerance::Shape::of(&exact).q_min;
    for (c, col) in COLUMNS.iter().enumerate() {
        let Shader::Span(m) = col else { continue };
        // Phong-valued methods' levels come from p and q alone (no exact run needed).
        if !m.is_phong_valued() && m.run(&exact, prep, &mut out).is_err() {
            return;
        }
        // Phong-valued pixels: the exact level of p/√q (for q ≈ 1 edges the span's E
        // is within 2^-16 of 1; p/√q is still what the f32 code computes).
        let values: &[BigRational] = if m.is_phong_valued() { &[] } else { &out };
        let levels = m.exact_levels(&exact, values, kd);
        // Without a derived bound, no mismatch counts as explained.
        let bound = crate::tolerance::bound(*m, exact.n, q_min, u)
            .map_or(-1.0, |b| b * 255.0 + 8.0 * u * 255.0);
        for (i, (&g, e)) in got[c].iter().zip(&levels).enumerate() {
            // A level the exact run cannot decide is not counted either way.
            if e.is_some_and(|e| e != g) {
                check.mismatches[c] += 1;
                // Distance of the exact scaled value from the nearest level boundary.
                let v = if m.is_phong_valued() {
                    use crate::scalar::Real;
                    (exact.p_at(i as u32) / exact.q_at(i as u32).sqrt()).to_f64()
                } else {
                    out[i].to_f64()
                } * 255.0;
                if (v - v.round()).abs() <= bound {
                    check.explained[c] += 1;
                }
            }
        }
    }
}
