//! `phong-approx vectors`: write the test vector files.

use super::CliError;
use clap::Args;
use phong_approx::conformance::vectors::{generate, inputs_csv, to_csv, SETS};
use std::fs;
use std::path::{Path, PathBuf};

/// Arguments of `phong-approx vectors`.
#[derive(Args, Debug)]
pub struct VectorsArgs {
    /// Where to write: a `.json` file for one set (its CSV twins are written beside it),
    /// or a folder for all sets. Without it, the JSON of one set goes to stdout.
    #[arg(long, value_name = "PATH")]
    pub out: Option<PathBuf>,
    /// typical, edge, paper, or all (the default).
    #[arg(long, value_name = "NAME", default_value = "all")]
    pub set: String,
}

fn write(path: &Path, text: &str) -> Result<(), CliError> {
    fs::write(path, text)
        .map_err(|e| CliError::arg("--out", format!("cannot write {}: {e}", path.display())))
}

/// Writes `NAME.json`, `NAME.csv` (expected values) and `NAME-inputs.csv` for `set`
/// next to `json`.
fn write_set(set: &str, json: &Path) -> Result<(), CliError> {
    let file = generate(set).map_err(|e| CliError::arg("--set", e))?;
    let text = serde_json::to_string_pretty(&file).expect("plain data") + "\n";
    write(json, &text)?;
    write(&json.with_extension("csv"), &to_csv(&file))?;
    let stem = json.file_stem().and_then(|s| s.to_str()).unwrap_or(set);
    write(
        &json.with_file_name(format!("{stem}-inputs.csv")),
        &inputs_csv(&file),
    )?;
    Ok(())
}

/// Runs `phong-approx vectors`.
///
/// # Errors
/// A [`CliError`] for an unknown set or an unwritable path.
pub fn run(a: &VectorsArgs) -> Result<(), CliError> {
    let sets: Vec<&str> = match a.set.as_str() {
        "all" => SETS.to_vec(),
        s if SETS.contains(&s) => vec![s],
        other => {
            return Err(CliError::arg(
                "--set",
                format!("unknown set '{other}' (expected typical, edge, paper or all)"),
            ))
        }
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
            if let Some(dir) = p.parent().filter(|d| !d.as_os_str().is_empty()) {
                fs::create_dir_all(dir).map_err(|e| {
                    CliError::arg("--out", format!("cannot create {}: {e}", dir.display()))
                })?;
            }
            write_set(sets[0], p)?;
        }
        Some(dir) => {
            fs::create_dir_all(dir).map_err(|e| {
                CliError::arg("--out", format!("cannot create {}: {e}", dir.display()))
            })?;
            for s in sets {
                write_set(s, &dir.join(format!("{s}.json")))?;
            }
        }
    }
    Ok(())
}
