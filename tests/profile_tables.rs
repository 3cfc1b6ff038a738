//! The profiles' tables (`src/tolerance/profile.rs`) against the theorems' statements
//! and the derivations.

use phong_approx::tolerance::profile::*;
use phong_approx::{Format, Method};

const F32: Format = Format::Binary32;
const F64: Format = Format::Binary64;
/// Euler's operation graphs, by name (docs/float.md §19.2).
const EULER_GRAPHS: &[&str] = &[
    "recurrence",
    "closed",
    "closed/half-coefficient",
    "closed/half-product",
];

#[test]
fn names_round_trip() {
    for p in Profile::ALL {
        assert_eq!(p.name().parse::<Profile>(), Ok(p));
    }
    assert!("gpu".parse::<Profile>().is_err());
    let q = Profile::Fixed {
        int_bits: 16,
        frac_bits: 16,
    };
    assert_eq!("fixed:16.16".parse::<Profile>(), Ok(q));
    assert_eq!(q.to_string(), "fixed:16.16");
    for bad in [
        "fixed:16",
        "fixed:0.16",
        "fixed:16.0",
        "fixed:a.b",
        "fixed:16.63",
        "fixed:3.60",
        "fixed:8.54",
        "fixed:1.52",
    ] {
        assert!(bad.parse::<Profile>().is_err(), "{bad}");
    }
}

#[test]
fn fixed_bounds_are_the_theorems_and_need_their_registers() {
    // h(1 + n + n(n−1)/2), h = 2^-17: at n = 4, 11·2^-17.
    let b = fixed_bound(Method::CorrectedEuler, 4, 1.0, 16, 16).unwrap();
    assert!((b / 2f64.powi(-17) - 11.0).abs() < 1e-9);
    let g = fixed_bound(Method::Gouraud, 4, 1.0, 16, 16).unwrap();
    assert!((g / 2f64.powi(-17) - 5.0).abs() < 1e-9);
    // Q3.f holds corrected Euler's values (|p| ≤ 2.5 < 4) but not its slope at
    // n = 1 (|t| ≤ 28); from n = 12 the slope is below 2.5 too.
    assert!(fixed_bound(Method::CorrectedEuler, 1, 1.0, 3, 16).is_none());
    assert!(fixed_bound(Method::CorrectedEuler, 1, 1.0, 6, 16).is_some());
    assert!(fixed_bound(Method::CorrectedEuler, 12, 1.0, 3, 16).is_some());
    assert!(fixed_bound(Method::Phong, 4, 1.0, 16, 16).is_none());
    // Euler as corrected Euler (|p| ≤ 5 needs Q4.f); the adaptive choice the larger of
    // its picks'; Duff's unit needs r = √(q_min − E_q) > 2h and reads q_min.
    let e = fixed_bound(Method::Euler, 4, 1.0, 16, 16).unwrap();
    assert!((e / 2f64.powi(-17) - 11.0).abs() < 1e-9);
    assert!(fixed_bound(Method::Euler, 12, 1.0, 3, 16).is_none());
    assert_eq!(fixed_bound(Method::Adaptive, 4, 1.0, 16, 16), Some(b));
    // n = 1: E_p = E_q = 2h = 2^-16, r = √(1 − 2^-16); the bound ≈ 2^-16·2.5 + 2^-16.
    let d = fixed_bound(Method::Duff, 1, 1.0, 16, 16).unwrap();
    assert!((d / 2f64.powi(-16) - 3.5).abs() < 1e-3, "{d}");
    assert!(
        fixed_bound(Method::Duff, 1, 1.0, 16, 16).unwrap()
            < fixed_bound(Method::Duff, 1, 0.5, 16, 16).unwrap()
    );
    assert!(fixed_bound(Method::Duff, 4096, 1e-3, 16, 16).is_none());
}

#[test]
fn proved_bounds_are_the_theorems() {
    let u32_ = f64::from(f32::EPSILON) / 2.0;
    let u64_ = f64::EPSILON / 2.0;
    // (1.0006·100 + 11.001)·u
    let g = proved_bound(Method::Gouraud, Profile::Ieee, 100, F32).unwrap();
    assert!((g / u32_ - 111.061).abs() < 1e-9);
    // Corrected Euler: the larger of the recurrence and the closed form.
    let c = proved_bound(Method::CorrectedEuler, Profile::Ieee, 1, F32).unwrap();
    assert!((c / u32_ - 59.61).abs() < 1e-9);
    let c = proved_bound(Method::CorrectedEuler, Profile::Ieee, 100, F64).unwrap();
    assert!((c / u64_ - 271.21).abs() < 1e-9);
    // binary32 stops at 4096; binary64 goes to 2^24; shader is binary32 only.
    assert!(proved_bound(Method::Gouraud, Profile::Ieee, 4097, F32).is_none());
    assert!(proved_bound(Method::Gouraud, Profile::Ieee, 1 << 24, F64).is_some());
    assert!(proved_bound(Method::Gouraud, Profile::Shader, 10, F64).is_none());
    assert!(proved_bound(Method::Phong, Profile::Ieee, 10, F32).is_none());
    assert!(proved_bound(Method::Gouraud, Profile::Ieee, 0, F32).is_none());
}

#[test]
fn euler_is_proved_under_ieee() {
    let u32_ = f64::from(f32::EPSILON) / 2.0;
    let u64_ = f64::EPSILON / 2.0;
    // The larger of the recurrence (5.55·n + 121.41) and the closed form (131.41).
    let e = proved_bound(Method::Euler, Profile::Ieee, 1, F32).unwrap();
    assert!((e / u32_ - 131.41).abs() < 1e-9);
    let e = proved_bound(Method::Euler, Profile::Ieee, 2, F32).unwrap();
    assert!((e / u32_ - 132.51).abs() < 1e-9);
    let e = proved_bound(Method::Euler, Profile::Ieee, 100, F64).unwrap();
    assert!((e / u64_ - 676.41).abs() < 1e-9);
    assert!(proved_bound(Method::Euler, Profile::Ieee, 4097, F32).is_none());
    assert!(proved_bound(Method::Euler, Profile::Ieee, 1 << 24, F64).is_some());
    assert!(proved_bound(Method::Euler, Profile::Ieee, (1 << 24) + 1, F64).is_none());
    assert_eq!(
        status(Method::Euler, Profile::Ieee, F32),
        Some(Status::PerPixel(
            "profile_ieee_euler_binary32",
            EULER_GRAPHS,
            &phong_approx::tolerance::profile::GRAPH_THEOREMS_READ
        ))
    );
    assert_eq!(
        status(Method::Euler, Profile::Ieee, F64),
        Some(Status::PerPixel(
            "profile_ieee_euler_binary64_large",
            EULER_GRAPHS,
            &phong_approx::tolerance::profile::GRAPH_THEOREMS_READ
        ))
    );
    // `check` applies exactly the theorems' bound.
    for (f, ns) in [
        (F32, vec![1, 2, 3, 255, 256, 4095, 4096]),
        (F64, vec![1, 2, 4096, 4097, 1 << 20, 1 << 24]),
    ] {
        for n in ns {
            let p = proved_bound(Method::Euler, Profile::Ieee, n, f).unwrap();
            assert_eq!(
                profile_bound(Method::Euler, Profile::Ieee, n, 1.0, f),
                Some(p)
            );
        }
    }
}

#[test]
fn shader_bounds_are_the_largest_of_every_form() {
    let u32_ = f64::from(f32::EPSILON) / 2.0;
    // Every shader theorem of each method, the `_recip` recurrence first.
    let theorems: [(Method, &[&str]); 3] = [
        (
            Method::Gouraud,
            &[
                "profile_shader_gouraud_recip_binary32",
                "profile_shader_gouraud_binary32",
            ],
        ),
        (
            Method::CorrectedEuler,
            &[
                "profile_shader_corrected_euler_recip_binary32",
                "profile_shader_corrected_euler_binary32",
                "profile_shader_corrected_euler_closed_binary32",
                "profile_shader_corrected_euler_closed_recip_binary32",
                "profile_shader_corrected_euler_closed_half_binary32",
                "profile_shader_corrected_euler_closed_half_recip_binary32",
            ],
        ),
        (
            Method::Euler,
            &[
                "profile_shader_euler_recip_binary32",
                "profile_shader_euler_binary32",
                "profile_shader_euler_closed_binary32",
                "profile_shader_euler_closed_recip_binary32",
                "profile_shader_euler_closed_half_binary32",
                "profile_shader_euler_closed_half_recip_binary32",
            ],
        ),
    ];
    for (m, names) in theorems {
        let forms = proved(m, Profile::Shader, F32).unwrap();
        let got: Vec<&str> = forms.iter().map(|f| f.theorem).collect();
        assert_eq!(got, names, "{m}");
        assert!(
            matches!(status(m, Profile::Shader, F32), Some(Status::PerPixel(t, _, also)) if t == names[0] && also == phong_approx::tolerance::profile::GRAPH_THEOREMS_READ),
            "{m}"
        );
        // The bound applied is never below any form's theorem, and is one of them.
        for n in 1..=4096 {
            let b = profile_bound(m, Profile::Shader, n, 1.0, F32).unwrap();
            assert_eq!(Some(b), proved_bound(m, Profile::Shader, n, F32));
            let each: Vec<f64> = forms.iter().map(|f| f.at(n, F32).unwrap()).collect();
            assert!(each.iter().all(|&x| x <= b), "{m} {n}");
            assert!(each.contains(&b), "{m} {n}");
        }
        assert!(profile_bound(m, Profile::Shader, 4097, 1.0, F32).is_none());
        assert!(proved(m, Profile::Shader, F64).is_none());
    }
    let at = |m, n| proved_bound(m, Profile::Shader, n, F32).unwrap() / u32_;
    // Gouraud: the `_recip` recurrence, (2.0012·n + 28.0014)·u.
    assert!((at(Method::Gouraud, 1) - 30.0026).abs() < 1e-9);
    assert!((at(Method::Gouraud, 100) - 228.1214).abs() < 1e-9);
    // Corrected Euler: the halved closed form through reciprocals (148.11) up to
    // n = 5, then the `_recip` recurrence (4.4·n + 124.31).
    assert!((at(Method::CorrectedEuler, 1) - 148.11).abs() < 1e-9);
    assert!((at(Method::CorrectedEuler, 5) - 148.11).abs() < 1e-9);
    assert!((at(Method::CorrectedEuler, 6) - 150.71).abs() < 1e-9);
    assert!((at(Method::CorrectedEuler, 100) - 564.31).abs() < 1e-9);
    // Plain Euler: 313.36 up to n = 2, then (11.1·n + 288.11).
    assert!((at(Method::Euler, 1) - 313.36).abs() < 1e-9);
    assert!((at(Method::Euler, 2) - 313.36).abs() < 1e-9);
    assert!((at(Method::Euler, 3) - 321.41).abs() < 1e-9);
    assert!((at(Method::Euler, 100) - 1398.11).abs() < 1e-9);
    // The adaptive scheme takes the larger of Gouraud's and corrected Euler's.
    assert_eq!(
        profile_bound(Method::Adaptive, Profile::Shader, 1, 1.0, F32),
        Some(148.11 * u32_)
    );
}

/// A declared form takes that form's theorems alone: corrected Euler's closed form
/// at `n = 4095` under `ieee` binary32 is `59.61·u`, its recurrence
/// `(2.2·4095 + 51.21)·u`, undeclared the larger; only Euler and corrected Euler
/// tell their forms apart; fixed point proves the loop only.
#[test]
fn a_declared_form_takes_its_own_theorems() {
    let u32_ = F32.u();
    let ce = |form| proved_bound_in(Method::CorrectedEuler, Profile::Ieee, form, 4095, F32);
    assert_eq!(ce(Form::Closed), Some(59.61 * u32_));
    assert_eq!(ce(Form::Recurrence), Some((2.2 * 4095.0 + 51.21) * u32_));
    assert_eq!(ce(Form::Any), ce(Form::Recurrence));
    // At n = 1 the closed form's constant is the larger: undeclared takes it.
    let ce1 = |form| proved_bound_in(Method::CorrectedEuler, Profile::Ieee, form, 1, F32);
    assert_eq!(ce1(Form::Any), Some(59.61 * u32_));
    assert_eq!(ce1(Form::Recurrence), Some((2.2 + 51.21) * u32_));
    // Under shader the closed forms' four theorems, the largest.
    let sh = proved_bound_in(Method::Euler, Profile::Shader, Form::Closed, 4095, F32);
    assert_eq!(sh, Some(313.36 * u32_));
    for m in Method::ALL {
        assert_eq!(
            Form::applies_to(m),
            matches!(m, Method::Euler | Method::CorrectedEuler),
            "{m}"
        );
        if !Form::applies_to(m) {
            for form in [Form::Recurrence, Form::Closed] {
                assert!(
                    proved_in(m, Profile::Ieee, form, F32).is_none(),
                    "{m} {form}"
                );
            }
        }
    }
    use phong_approx::reference::unit::unit_from_ints;
    let span = crate::Span::new(
        unit_from_ints(0, 0, 1),
        unit_from_ints(1, 0, 3),
        unit_from_ints(0, 0, 1),
        8,
    )
    .unwrap();
    let shape = phong_approx::tolerance::Shape::of(&span);
    let fixed = Profile::Fixed {
        int_bits: 16,
        frac_bits: 16,
    };
    let b = |form| profile_span_bound(Method::CorrectedEuler, fixed, form, &shape, F32);
    assert!(b(Form::Any).is_some());
    assert_eq!(b(Form::Recurrence), b(Form::Any));
    assert_eq!(b(Form::Closed), None);
    assert_eq!(
        profile_span_bound(Method::Phong, Profile::Ieee, Form::Closed, &shape, F32),
        None
    );
    for form in Form::ALL {
        assert_eq!(form.name().parse::<Form>(), Ok(form));
    }
    assert!("horner".parse::<Form>().is_err());
}

/// Each theorem row states its form ([`phong_approx::method::Proved::closed`]); the
/// statement agrees: a closed form's bound does not grow with `n` (α = 0) and its
/// theorem is named `_closed`, a recurrence's grows.
#[test]
fn every_theorem_row_states_its_form() {
    let mut closed = 0;
    for m in Method::ALL {
        for p in [Profile::Ieee, Profile::Shader] {
            for f in [Format::Binary32, Format::Binary64] {
                for t in proved(m, p, f).unwrap_or_default() {
                    assert_eq!(t.closed, t.alpha == 0.0, "{}", t.theorem);
                    assert_eq!(t.closed, t.theorem.contains("_closed"), "{}", t.theorem);
                    assert_eq!(t.profile, p, "{}", t.theorem);
                    closed += usize::from(t.closed);
                }
            }
        }
    }
    assert_eq!(closed, 12);
}
