//! The comparison's tables as CSV: Table 2 per torus, the precision study, the spans
//! study.

use super::*;

/// `table2_extended.csv`: per torus and shader of [`COLUMNS`], the diffuse and
/// the specular deviations (`diffuse`, `specular10`, …): mean (6 decimals), max,
/// pixels.
pub fn table2_csv(tori: &[CompareResult]) -> String {
    /// A line of `table2_extended.csv`.
    #[derive(Serialize)]
    struct Row {
        polygons: u32,
        method: String,
        term: String,
        mean: String,
        max: u32,
        pixels: u64,
    }
    let mut rows = Vec::new();
    for t in tori {
        for (c, sh) in COLUMNS.iter().enumerate() {
            let terms = std::iter::once(("diffuse".to_string(), &t.stats.diffuse[c])).chain(
                SHININESS
                    .iter()
                    .enumerate()
                    .map(|(k, sv)| (format!("specular{sv}"), &t.stats.specular[k][c])),
            );
            for (term, d) in terms {
                rows.push(Row {
                    polygons: t.polygons,
                    method: sh.label().into_owned(),
                    term,
                    mean: format!("{:.6}", d.mean()),
                    max: d.max,
                    pixels: d.pixels,
                });
            }
        }
    }
    crate::table::csv(rows)
}

/// `precision.csv`: per precision and shader, the deviations from per-pixel Phong in
/// `f64` and from the same shader in `f64` (mean with 6 decimals, max), the pixels,
/// the failed rows and all rows.
pub fn precision_csv(p: &[(Arithmetic, PrecisionStats)]) -> String {
    /// A line of `precision.csv`.
    #[derive(Serialize)]
    struct Row {
        precision: String,
        method: String,
        mean_vs_phong: String,
        max_vs_phong: u32,
        mean_vs_f64: String,
        max_vs_f64: u32,
        pixels: u64,
        failed_rows: u64,
        rows: u64,
    }
    crate::table::csv(p.iter().flat_map(|(name, st)| {
        COLUMNS.iter().enumerate().map(move |(c, sh)| {
            let (a, b) = (&st.vs_phong[c], &st.vs_f64[c]);
            Row {
                precision: name.to_string(),
                method: sh.label().into_owned(),
                mean_vs_phong: format!("{:.6}", a.mean()),
                max_vs_phong: a.max,
                mean_vs_f64: format!("{:.6}", b.mean()),
                max_vs_f64: b.max,
                pixels: a.pixels,
                failed_rows: st.failed_rows[c],
                rows: st.rows,
            }
        })
    }))
}

/// `longest_span.csv`: per span shader, precision and length of [`SPAN_LENGTHS`], the
/// largest error in 8-bit levels (6 decimals), or `fails`.
pub fn spans_csv(spans: &[SpanRow]) -> String {
    /// A line of `longest_span.csv`.
    #[derive(Serialize)]
    struct Row {
        method: String,
        precision: String,
        n: u32,
        max_error_levels: String,
    }
    let mut rows = Vec::new();
    for (sh, per) in spans {
        for (p, e) in per {
            for (n, v) in SPAN_LENGTHS.iter().zip(e) {
                rows.push(Row {
                    method: sh.name().into_owned(),
                    precision: p.to_string(),
                    n: *n,
                    max_error_levels: v.map_or("fails".to_string(), |v| format!("{v:.6}")),
                });
            }
        }
    }
    crate::table::csv(rows)
}
