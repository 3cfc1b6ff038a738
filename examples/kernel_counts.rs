//! A driver for instruction counts that do not depend on machine noise:
//! `valgrind --tool=callgrind target/release/examples/kernel_counts KERNEL N REPS`.
//! `benches/callgrind.sh` runs it for every kernel and prints instructions per pixel.

use phong_approx::fast::{phong_rsqrt_f32, FastSpan};
use std::hint::black_box;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let usage = "usage: kernel_counts KERNEL N REPS";
    let (Some(kernel), Some(n), Some(reps)) = (args.get(1), args.get(2), args.get(3)) else {
        eprintln!("{usage}");
        std::process::exit(2);
    };
    let (Ok(n), Ok(reps)) = (n.parse::<u32>(), reps.parse::<u32>()) else {
        eprintln!("{usage}: N and REPS are whole numbers");
        std::process::exit(2);
    };
    if n == 0 {
        eprintln!("{usage}: N must be at least 1");
        std::process::exit(2);
    }
    let k: fn(&FastSpan<f32>, &mut [f32]) = match kernel.as_str() {
        "gouraud_serial" => FastSpan::<f32>::gouraud_serial,
        "gouraud_fast" => FastSpan::<f32>::gouraud,
        "euler_fast" => FastSpan::<f32>::euler,
        "corrected_euler_serial" => FastSpan::<f32>::corrected_euler_serial,
        "corrected_euler_fast" => FastSpan::<f32>::corrected_euler,
        "duff_serial" => FastSpan::<f32>::duff_serial,
        "phong_fast" => FastSpan::<f32>::phong,
        "phong_rsqrt_simd" => phong_rsqrt_f32,
        "symmetric_phong_fast" => FastSpan::<f32>::symmetric_phong,
        "none" => |_, _| {},
        other => {
            eprintln!("unknown kernel '{other}'");
            std::process::exit(2);
        }
    };
    let (na, nb, l) = (
        [0.343f32, 0.1, 0.934],
        [0.52, -0.05, 0.853],
        [-0.408, 0.408, 0.816],
    );
    let mut out = vec![0f32; n as usize + 1];
    for _ in 0..reps {
        let s = FastSpan::<f32>::new(black_box(na), black_box(nb), black_box(l), n);
        k(&s, &mut out);
        black_box(&out);
    }
}
