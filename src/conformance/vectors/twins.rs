//! The CSV twins of a vector file: the expectations (`SET.csv`) and the inputs with
//! their nearest floats (`SET-inputs.csv`).

use super::*;

/// The CSV twin of a vector file: one row per case, method and pixel:
/// `set,case,method,kind,n,pixel,value,level` (`kind` is `diffuse` or `specular`).
pub fn to_csv(file: &VectorFile) -> String {
    /// A line of the CSV twin.
    #[derive(Serialize)]
    struct Row<'a> {
        set: &'a str,
        case: &'a str,
        method: &'a str,
        kind: &'a str,
        n: u32,
        pixel: usize,
        value: &'a str,
        level: u8,
    }
    let mut rows = Vec::new();
    for c in &file.cases {
        let parts = std::iter::once(("diffuse", &c.expected))
            .chain(c.specular.iter().map(|sp| ("specular", &sp.expected)));
        for (kind, exp) in parts {
            for (m, e) in exp {
                for (i, (v, l)) in e.values.iter().zip(&e.levels).enumerate() {
                    rows.push(Row {
                        set: &file.set,
                        case: &c.id,
                        method: m,
                        kind,
                        n: c.n,
                        pixel: i,
                        value: v,
                        level: *l,
                    });
                }
            }
        }
    }
    crate::table::csv(rows)
}

/// The names of the inputs CSV's twelve input columns (`h_*` for the specular half
/// vector), in order.
const INPUT_COLUMNS: [&str; 12] = [
    "na_x", "na_y", "na_z", "nb_x", "nb_y", "nb_z", "l_x", "l_y", "l_z", "h_x", "h_y", "h_z",
];

/// The inputs of every case as CSV, for readers in any language: `case,n`, the twelve
/// inputs as exact fractions (`na_x … l_z, h_x, h_y, h_z`), `s`, then the nearest
/// `f32` of each input as its bit pattern (`na_x_f32 … h_z_f32`, `0x` and 8 hex
/// digits) and the nearest `f64` likewise (`na_x_f64 … h_z_f64`, 16 hex digits), so a
/// C harness reads floats with `strtoul` and `memcpy` and parses no fraction. The
/// cells of H and s are empty where a case has no specular part.
///
/// # Panics
/// If a case's float forms do not parse (the file was not validated).
pub fn inputs_csv(file: &VectorFile) -> String {
    let mut w = csv::Writer::from_writer(Vec::new());
    let mut head = vec!["case".to_string(), "n".to_string()];
    head.extend(INPUT_COLUMNS.map(String::from));
    head.push("s".into());
    for suffix in ["_f32", "_f64"] {
        head.extend(INPUT_COLUMNS.map(|c| format!("{c}{suffix}")));
    }
    w.write_record(&head).expect("writing to memory");
    for c in &file.cases {
        let h = c.specular.as_ref().map(|sp| &sp.h);
        let inputs: [Option<&VectorInput>; 4] = [Some(&c.na), Some(&c.nb), Some(&c.l), h];
        let cells = |pick: &dyn Fn(&VectorInput, usize) -> String| -> Vec<String> {
            inputs
                .iter()
                .flat_map(|v| (0..3).map(move |k| v.map_or(String::new(), |v| pick(v, k))))
                .collect()
        };
        let mut row = vec![c.id.clone(), c.n.to_string()];
        row.extend(cells(&|v, k| v.exact[k].clone()));
        row.push(
            c.specular
                .as_ref()
                .map_or(String::new(), |sp| sp.s.to_string()),
        );
        row.extend(cells(&|v, k| {
            let x: f32 = v.f32[k].parse().expect("a validated f32 input");
            format!("0x{:08x}", x.to_bits())
        }));
        row.extend(cells(&|v, k| {
            let x: f64 = v.f64[k].parse().expect("a validated f64 input");
            format!("0x{:016x}", x.to_bits())
        }));
        w.write_record(&row).expect("writing to memory");
    }
    String::from_utf8(w.into_inner().expect("writing to memory")).expect("the cells are UTF-8")
}
