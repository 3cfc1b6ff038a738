//! How each bound is known, in words and tables made from the catalogue: the status
//! table of docs/conformance.md, the default (`ieee`) bounds table, `check --help`'s
//! summary.

use super::{profile_bound, proved, status, Profile, Status};
use crate::Format;

/// The columns of [`status_table`]: the profiles and formats with bounds.
/// (Fixed point's format is its profile's own: the float format is not read.)
const COLUMNS: [(&str, Profile, Format); 4] = [
    ("ieee, binary32", Profile::Ieee, Format::Binary32),
    ("ieee, binary64", Profile::Ieee, Format::Binary64),
    ("shader, binary32", Profile::Shader, Format::Binary32),
    (
        "fixed:M.F",
        Profile::Fixed {
            int_bits: 16,
            frac_bits: 16,
        },
        Format::Binary32,
    ),
];

/// How each method's bound is known under each profile, as a Markdown table made from
/// [`status`] (the one source of the labels: docs/conformance.md holds this table,
/// `tests/coverage.rs` checks it is the current one): a row per method with a bound
/// under some profile.
pub fn status_table() -> String {
    let mut s = String::from("| method |");
    for (name, ..) in COLUMNS {
        s += &format!(" {name} |");
    }
    s += "\n|---|";
    s += &"---|".repeat(COLUMNS.len());
    s += "\n";
    for m in crate::Method::ALL {
        let cells: Vec<Option<Status>> = COLUMNS
            .iter()
            .map(|&(_, p, format)| status(m, p, format))
            .collect();
        if cells.iter().all(Option::is_none) {
            continue;
        }
        s += &format!("| `{}` |", m.name());
        for c in cells {
            let label = c.map_or("none".to_string(), |c| markdown(&c));
            s += &format!(" {label} |");
        }
        s += "\n";
    }
    s
}

/// A status's label in Markdown: [`Status::label`] with the theorem's and the graphs'
/// names as code.
fn markdown(st: &Status) -> String {
    // "the graph `a`" or "the graphs `a`, `b`".
    let named = |graphs: &[&str]| {
        let names: Vec<String> = graphs.iter().map(|g| format!("`{g}`")).collect();
        let noun = if names.len() == 1 { "graph" } else { "graphs" };
        format!("the {noun} {}", names.join(", "))
    };
    match st {
        Status::Proved(t) => format!("proved (`{t}`)"),
        Status::PerPixel(t, graphs, also) => format!(
            "proved (`{t}`; per pixel the smallest with {} on {})",
            super::and_list(
                &super::graph_theorems(also)
                    .iter()
                    .map(|g| format!("`{g}`"))
                    .collect::<Vec<_>>()
            ),
            named(graphs)
        ),
        Status::Graphs(t, graphs, also) => format!(
            "proved (`graph_sound` on {}, composed by `{t}`{})",
            named(graphs),
            also.map_or(String::new(), |a| format!(" and `{a}`"))
        ),
    }
}

/// A profile's bound for `method` in `format`, in words: the
/// proved forms `(α·n + β)·u` (the largest applies), or the section of the derivation
/// or composition for the bounds that depend on the span's `q_min` too.
pub fn formula(method: crate::Method, profile: Profile, format: Format) -> Option<String> {
    use crate::method::FloatBound;
    // A method that picks between two (its row's `picks`) takes the larger of their
    // bounds; the other bounds composed from theorems read the span's q_min, as the
    // derived ones.
    if let FloatBound::Composed { section, .. } = method.info().profiles.float {
        status(method, profile, format)?;
        return Some(match method.picks() {
            Some([a, b]) => format!("the larger of the bounds of {a} and {b}"),
            None => format!("from n and q_min ({section})"),
        });
    }
    if let FloatBound::Graphs { section, .. } = method.info().profiles.float {
        status(method, profile, format)?;
        return Some(format!("per pixel from the case's own inputs ({section})"));
    }
    match status(method, profile, format)? {
        Status::Graphs(..) => None,
        Status::Proved(_) | Status::PerPixel(..) => {
            let mut forms: Vec<String> = proved(method, profile, format)?
                .iter()
                .map(|f| {
                    if f.alpha == 0.0 {
                        format!("{}·u", f.beta)
                    } else {
                        format!("({}·n + {})·u", f.alpha, f.beta)
                    }
                })
                .collect();
            forms.dedup();
            Some(if forms.len() == 1 {
                forms.remove(0)
            } else {
                format!("max({})", forms.join(", "))
            })
        }
    }
}

/// The bounds `check` applies by default — the `ieee` profile's, in binary32 and
/// binary64 — as a Markdown table made from [`formula`], [`profile_bound`] and
/// [`status`] (docs/conformance.md §3 holds it, `tests/coverage.rs` checks it is the
/// current one), with each bound's value in units of `u` on two spans: `n = 8`,
/// `q_min = 1` and `n = 256`, `q_min = 1/4`.
pub fn ieee_table() -> String {
    let spans = [(8u32, 1.0f64), (256, 0.25)];
    let mut s = String::from(
        "| method | `ieee` bound on the error at each pixel | binary32, n = 8, q_min = 1 | binary32, n = 256, q_min = 1/4 | binary64, n = 256, q_min = 1/4 | status (binary32) |\n|---|---|---|---|---|---|\n",
    );
    let (b32, b64) = (Format::Binary32, Format::Binary64);
    for m in crate::Method::ALL {
        let Some(f) = formula(m, Profile::Ieee, b32) else {
            continue;
        };
        let at = |n: u32, q: f64, format: Format| {
            let none = match status(m, Profile::Ieee, format) {
                Some(Status::Graphs(..)) => "per case",
                _ => "none",
            };
            profile_bound(m, Profile::Ieee, n, q, format).map_or(none.to_string(), |b| {
                // In units of u, rounded up to 4 significant digits.
                let x = b / format.u();
                let d = (3 - x.log10().floor() as i32).max(0) as usize;
                let e = 10f64.powi(-(d as i32));
                format!("{:.d$}·u", (x / e).ceil() * e)
            })
        };
        let label = status(m, Profile::Ieee, b32).map_or(String::new(), |st| markdown(&st));
        s += &format!(
            "| `{}` | {f} | {} | {} | {} | {label} |\n",
            m.name(),
            at(spans[0].0, spans[0].1, b32),
            at(spans[1].0, spans[1].1, b32),
            at(spans[1].0, spans[1].1, b64),
        );
    }
    s
}

/// One line per profile naming the methods whose bound is proved (the `--profile`
/// help of `check`, from [`status`]).
pub fn status_summary() -> String {
    let mut parts = Vec::new();
    for (name, p, format) in COLUMNS {
        let proved: Vec<String> = crate::Method::ALL
            .into_iter()
            .filter(|&m| status(m, p, format).is_some())
            .map(|m| m.name().into_owned())
            .collect();
        parts.push(format!("{name}: proved for {}", list(&proved)));
    }
    parts.join("; ")
}

fn list(names: &[String]) -> String {
    if names.is_empty() {
        "none".into()
    } else {
        names.join(", ")
    }
}
