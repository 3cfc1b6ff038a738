//! `phong-approx vectors`: write the test vector files.

use super::output::OutDir;
use super::BadValue;
use super::CliError;
use clap::Args;
use phong_approx::conformance::integrity::sha256_hex;
use phong_approx::conformance::shown;
use phong_approx::conformance::vectors::{generate, inputs_csv, schema, to_csv, SETS};
use std::path::{Path, PathBuf};

/// Arguments of `phong-approx vectors`.
#[derive(Args, Debug)]
pub struct VectorsArgs {
    /// Where to write: a `.json` file for one set (its CSV twins are written beside it),
    /// or a folder (the sets with their CSV twins, `schema.json`, and with every set
    /// their digests `SHA256SUMS`). Without it, the JSON of one set goes to stdout.
    #[arg(long, value_name = "PATH")]
    pub out: Option<PathBuf>,
    /// typical, edge, paper, or all (the default).
    #[arg(long, value_name = "NAME", default_value = "all", value_parser = set_name)]
    pub set: String,
    /// Replace files that phong-approx did not write.
    #[arg(long)]
    pub force: bool,
}

/// The JSON Schema of the sets, written beside them in a folder.
const SCHEMA: &str = "schema.json";
/// The SHA-256 of every set, written beside them when all are written: the digests
/// `check` trusts (embedded from `vectors/SHA256SUMS`).
const SUMS: &str = "SHA256SUMS";

/// `--set`: one of the published sets, or `all`.
fn set_name(s: &str) -> Result<String, BadValue> {
    if s == "all" || SETS.contains(&s) {
        Ok(s.to_string())
    } else {
        Err(BadValue::from(format!(
            "unknown set '{}' (expected typical, edge, paper or all)",
            shown(s)
        )))
    }
}

/// The three files of `set` written next to `json`: `NAME.json`, `NAME.csv` (expected
/// values) and `NAME-inputs.csv`.
fn names(set: &str, json: &Path) -> [String; 3] {
    let stem = json.file_stem().and_then(|s| s.to_str()).unwrap_or(set);
    [
        format!("{stem}.json"),
        format!("{stem}.csv"),
        format!("{stem}-inputs.csv"),
    ]
}

/// Writes the three files of `set` into `out`; returns the JSON's file name and text.
fn write_set(set: &str, json: &Path, out: &OutDir) -> Result<(String, String), CliError> {
    let file = generate(set).map_err(|e| CliError::arg("--set", e))?;
    let text = serde_json::to_string_pretty(&file).expect("plain data") + "\n";
    let [j, c, i] = names(set, json);
    out.write(&j, &text)?;
    out.write(&c, &to_csv(&file))?;
    out.write(&i, &inputs_csv(&file))?;
    Ok((j, text))
}

/// Runs `phong-approx vectors`.
///
/// # Errors
/// A [`CliError`] for an unknown set or an unwritable path.
pub fn run(a: &VectorsArgs) -> Result<(), CliError> {
    let sets: Vec<&str> = match a.set.as_str() {
        "all" => SETS.to_vec(),
        s => SETS.iter().copied().filter(|&t| t == s).collect(),
    };
    match &a.out {
        None if sets.len() == 1 => {
            let file = generate(sets[0]).map_err(|e| CliError::arg("--set", e))?;
            outln!(
                "{}",
                serde_json::to_string_pretty(&file).expect("plain data")
            )?;
        }
        None => {
            return Err(CliError::arg(
                "--out",
                "writing all sets needs a folder (--out DIR), or pick one with --set",
            ))
        }
        Some(p) if sets.len() == 1 && p.extension().is_some_and(|e| e == "json") => {
            let dir = p
                .parent()
                .filter(|d| !d.as_os_str().is_empty())
                .unwrap_or(Path::new("."));
            let out = OutDir::open(dir, a.force, "--out")?;
            out.check_all(names(sets[0], p).iter().map(String::as_str))?;
            write_set(sets[0], p, &out)?;
            out.commit()?;
        }
        Some(dir) => {
            let out = OutDir::open(dir, a.force, "--out")?;
            let all: Vec<[String; 3]> = sets
                .iter()
                .map(|s| names(s, &dir.join(format!("{s}.json"))))
                .collect();
            // Every set: their digests too, in `sha256sum -c`'s format.
            let sums = (sets.len() == SETS.len()).then_some(SUMS);
            out.check_all(
                all.iter()
                    .flatten()
                    .map(String::as_str)
                    .chain([SCHEMA])
                    .chain(sums),
            )?;
            // Generating the exact expectations of every set takes seconds.
            let bar = indicatif::ProgressBar::new(sets.len() as u64);
            bar.set_style(
                indicatif::ProgressStyle::with_template(
                    "{spinner} vector set {pos}/{len} {elapsed}",
                )
                .expect("template"),
            );
            bar.enable_steady_tick(std::time::Duration::from_millis(200));
            let mut digests = String::new();
            for s in sets {
                let (name, text) = write_set(s, &dir.join(format!("{s}.json")), &out)?;
                digests += &format!("{}  {name}\n", sha256_hex(text.as_bytes()));
                bar.inc(1);
            }
            bar.finish_and_clear();
            out.write(SCHEMA, &schema())?;
            if let Some(sums) = sums {
                out.write(sums, &digests)?;
            }
            out.commit()?;
        }
    }
    Ok(())
}
