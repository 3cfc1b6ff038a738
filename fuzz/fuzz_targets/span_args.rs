//! Fuzzes what `span` does with its arguments: three vectors and a step count read
//! exactly, set up as a span (checked and normalized), shaded by a method in `f64`
//! and exactly: any input must give values or a typed error, never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use phong_approx::parse::parse_vec3;
use phong_approx::{BigRational, Method, Span};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let mut parts = text.split(';');
    let (Some(na), Some(nb), Some(l), Some(n)) = (parts.next(), parts.next(), parts.next(), parts.next()) else {
        let _ = parse_vec3(text);
        return;
    };
    let (Ok(na), Ok(nb), Ok(l)) = (parse_vec3(na), parse_vec3(nb), parse_vec3(l)) else {
        return;
    };
    // Short spans only: the point is the parsing and the set-up, not the work.
    let Ok(n) = n.trim().parse::<u32>() else {
        return;
    };
    let n = n % 64;
    let m = Method::ALL[data.len() % Method::ALL.len()];
    if let Ok(s) = Span::<f64>::normalized(
        na.cast().unwrap(),
        nb.cast().unwrap(),
        l.cast().unwrap(),
        n,
    ) {
        let _ = m.values(&s);
    }
    if let Ok(s) = Span::<BigRational>::new(na, nb, l, n) {
        if m.is_rational() {
            let _ = m.values(&s);
        }
    }
});
