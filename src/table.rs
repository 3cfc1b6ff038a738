//! Tables as data: CSV from rows that derive `Serialize` (through `csv::Writer`, so
//! quoting is the crate's, not ours), and Markdown from rows of cells (one helper
//! for every report's tables).

#[cfg(feature = "csv")]
use serde::Serialize;

/// The CSV of `rows`: a header from the row type's field names, then one line per
/// row.
///
/// # Panics
/// Never for the plain row structs of this crate (strings and integers); a row type
/// that `csv` cannot write (a nested sequence) is a bug, and panics naming it.
#[cfg(feature = "csv")]
pub fn csv<R: Serialize>(rows: impl IntoIterator<Item = R>) -> String {
    let mut w = csv::Writer::from_writer(Vec::new());
    for r in rows {
        w.serialize(r).expect("a flat row of strings and numbers");
    }
    let bytes = w.into_inner().expect("writing to memory");
    String::from_utf8(bytes).expect("the cells are UTF-8")
}

/// How a Markdown column is aligned.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Align {
    /// `---`.
    Left,
    /// `---:`.
    Right,
}

/// A Markdown table: the header, the alignment rule, one line per row; every line
/// `| a | b |` and ending in a newline. `align` has one entry per column.
pub fn markdown<S: AsRef<str>>(head: &[S], align: &[Align], rows: &[Vec<String>]) -> String {
    let mut s = String::new();
    let line = |s: &mut String, cells: &mut dyn Iterator<Item = &str>| {
        s.push('|');
        for c in cells {
            s.push(' ');
            s.push_str(c);
            s.push_str(" |");
        }
        s.push('\n');
    };
    line(&mut s, &mut head.iter().map(AsRef::as_ref));
    s.push('|');
    for a in align {
        s.push_str(match a {
            Align::Left => "---|",
            Align::Right => "---:|",
        });
    }
    s.push('\n');
    for r in rows {
        line(&mut s, &mut r.iter().map(String::as_str));
    }
    s
}

// The tests read and write CSV.
#[cfg(all(test, feature = "csv"))]
mod tests {
    use super::*;

    #[derive(Serialize)]
    struct Row<'a> {
        method: &'a str,
        n: u32,
        value: String,
    }

    #[test]
    fn csv_has_the_field_names_and_quotes_where_needed() {
        let s = csv([
            Row {
                method: "gouraud",
                n: 4,
                value: "0.5".into(),
            },
            Row {
                method: "angular, tabled",
                n: 1,
                value: "1".into(),
            },
        ]);
        assert_eq!(
            s,
            "method,n,value\ngouraud,4,0.5\n\"angular, tabled\",1,1\n"
        );
    }

    #[test]
    fn markdown_lines_up_header_rule_and_rows() {
        let s = markdown(
            &["method", "n"],
            &[Align::Left, Align::Right],
            &[vec!["phong".into(), "3".into()]],
        );
        assert_eq!(s, "| method | n |\n|---|---:|\n| phong | 3 |\n");
    }
}
