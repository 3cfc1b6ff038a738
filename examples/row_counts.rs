//! A driver for instruction counts of the triangle methods of `benches/related.rs`:
//! `valgrind --tool=callgrind target/release/examples/row_counts METHOD S REPS`
//! shades the triangle with legs `S` with `METHOD` (a name of
//! `benches/common/triangle.rs`, or `none`) `REPS` times. `benches/callgrind.sh`
//! runs it for every method and prints instructions per pixel; `row_counts --list`
//! prints the names.

#[path = "../benches/common/triangle.rs"]
#[allow(dead_code)]
mod triangle;

use std::hint::black_box;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let names: Vec<&str> = triangle::METHODS
        .iter()
        .chain(&triangle::STAGES)
        .map(|(n, _)| *n)
        .collect();
    if args.get(1).map(String::as_str) == Some("--list") {
        for name in names {
            println!("{name}");
        }
        return;
    }
    let usage = "usage: row_counts METHOD S REPS";
    let (Some(method), Some(s), Some(reps)) = (args.get(1), args.get(2), args.get(3)) else {
        eprintln!("{usage}");
        std::process::exit(2);
    };
    let (Ok(s), Ok(reps)) = (s.parse::<u32>(), reps.parse::<u32>()) else {
        eprintln!("{usage}: S and REPS are whole numbers");
        std::process::exit(2);
    };
    let which = triangle::which(method);
    if !(1..=4096).contains(&s) || !(which.is_some() || method == "none") {
        eprintln!("{usage}: S in 1..=4096, METHOD one of {names:?} or none");
        std::process::exit(2);
    }
    let (normals, l) = triangle::inputs();
    let mut ctx = triangle::Ctx::new();
    let mut out = vec![0f32; s as usize + 1];
    for _ in 0..reps {
        if let Some(w) = which {
            triangle::shade(w, s, black_box(&normals), black_box(&l), &mut ctx, &mut out);
        }
        black_box(&out);
    }
}
