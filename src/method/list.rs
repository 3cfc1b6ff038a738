//! The one list of methods: a row per method — its doc, how it runs and its catalogue
//! facts — from which [`declare`](super::declare)'s macro generates the [`Method`]
//! enum, [`Method::ALL`] (in this order: the order of every table), the dispatch of
//! [`Method::run`] and [`Method::run_field`], and [`Method::info`]. Adding a method is
//! a row here and its own file (ARCHITECTURE.md, "Adding a span method").

use super::catalogue::{
    Bound, DerivedForm, Family, FixedBound, FloatBound, Info, Needs, PhongPixels, ProfileBounds,
    Roots, ValueRange, WholeSpan,
};
use super::profiles::{
    ADAPTIVE_THEOREMS, CORRECTED_EULER_THEOREMS, DUFF_THEOREMS, EULER_THEOREMS, GOURAUD_THEOREMS,
    PHONG_THEOREMS, SYMMETRIC_PHONG_THEOREMS,
};
use super::{Prepared, SOURCE_TABLE};
use crate::adaptive::Decision;
use crate::angular::CosTable;
use crate::error::SpanError;
use crate::reference::radical::Valued;
use crate::related::{binary, bishop_weimer, spherical};
use crate::scalar::{Real, Scalar};
use crate::span::Span;

const HBB: &str = "Hast, Barrera, Bengtsson";
use Bound::{Linear, Ratio};
use Family::{Paper, Related};
use PhongPixels::{All, BinarySegments, Ends, EndsAndEvenMiddle, EvenMiddle};
use ValueRange::{Diffuse, HalfAngleTaylor};
// The reference bounds' constants (docs/float.md, the row's section): Gouraud
// and corrected Euler are the theorems float_gouraud_binary32/_binary64 and
// float_corrected_euler_binary32/_binary64 (proofs/Float.v), corrected Euler
// past 4096 profile_ieee_corrected_euler_binary64_large (proofs/Profiles.v;
// Gouraud's own theorem there, (1.0006n + 11.001)u, lies below (1.001n + 10)u).
const GOURAUD: Bound = Linear {
    below: (1.001, 10.0),
    large: None,
};
const CORRECTED_EULER: Bound = Linear {
    below: (2.2, 42.0),
    large: Some((2.2, 51.21)),
};
const EULER: Bound = Linear {
    below: (5.6, 115.0),
    large: None,
};
const DUFF: Bound = Ratio {
    p: (1.01, 20.0),
    q: (3.01, 118.0),
};
const PHONG: Bound = Bound::PerPixel {
    normal: 10.01,
    eval: 7.6,
};
const ADAPTIVE: Bound = Bound::LargerOfPicks;
const ANGLE: Bound = Bound::Angle {
    extra: 2.0,
    table: None,
};
// Beyond the reference profile (`method/profiles.rs`).
const NO_FIXED: FixedBound = FixedBound::None(
    "proofs/Fixed.v proves the loops of Gouraud, Euler, corrected Euler, the adaptive choice and Duff's unit only",
);
// The operation graphs' names (`tolerance::graphs`, docs/float.md §19.2): the forms an
// implementation may compute, in the order the graphs are written.
const GOURAUD_GRAPHS: &[&str] = &["recurrence"];
const SECOND_ORDER_GRAPHS: &[&str] = &[
    "recurrence",
    "closed",
    "closed/half-coefficient",
    "closed/half-product",
];
const DUFF_GRAPHS: &[&str] = &["forward-differences"];
const PHONG_GRAPHS: &[&str] = &["horner", "pixel", "lerp"];
const fn composed(
    theorems: &'static [&'static str],
    section: &'static str,
    form: DerivedForm,
    graphs: &'static [&'static str],
) -> ProfileBounds {
    ProfileBounds {
        reference: None,
        float: FloatBound::Composed {
            theorems,
            section,
            form,
        },
        fixed: NO_FIXED,
        graphs,
    }
}
const COMPOSED_PER_PIXEL: ProfileBounds = composed(
    PHONG_THEOREMS,
    "docs/float.md §18.4",
    DerivedForm::PerPixel,
    PHONG_GRAPHS,
);
const COMPOSED_RATIO: ProfileBounds = ProfileBounds {
    fixed: FixedBound::Ratio {
        theorem: "fixed_point_duff_unit_error",
    },
    ..composed(
        DUFF_THEOREMS,
        "docs/float.md §18.5",
        DerivedForm::Ratio,
        DUFF_GRAPHS,
    )
};
const COMPOSED_HALF_RATIO: ProfileBounds = composed(
    SYMMETRIC_PHONG_THEOREMS,
    "docs/float.md §18.5",
    DerivedForm::HalfRatio,
    DUFF_GRAPHS,
);
// The larger of the two proved bounds, against the exact run of the method the
// implementation chose (docs/float.md §10, §18.5).
const ADAPTIVE_PROFILES: ProfileBounds = ProfileBounds {
    fixed: FixedBound::Picks {
        theorem: "fixed_point_adaptive_decision",
    },
    graphs: &[],
    ..composed(
        ADAPTIVE_THEOREMS,
        "docs/float.md §10",
        DerivedForm::LargerOfPicks,
        &[],
    )
};
const GOURAUD_PROFILES: ProfileBounds = ProfileBounds {
    reference: Some(["float_gouraud_binary32", "float_gouraud_binary64"]),
    float: FloatBound::Proved(GOURAUD_THEOREMS),
    fixed: FixedBound::Proved {
        theorem: "fixed_point_gouraud_error",
        second_order: false,
        value_max: 1.0,
        slope_times_n: 2.0,
    },
    graphs: GOURAUD_GRAPHS,
};
const CORRECTED_EULER_PROFILES: ProfileBounds = ProfileBounds {
    reference: Some([
        "float_corrected_euler_binary32",
        "float_corrected_euler_binary64",
    ]),
    float: FloatBound::Proved(CORRECTED_EULER_THEOREMS),
    fixed: FixedBound::Proved {
        theorem: "fixed_point_corrected_euler_error",
        second_order: true,
        value_max: 2.5,
        slope_times_n: 28.0,
    },
    graphs: SECOND_ORDER_GRAPHS,
};
const EULER_PROFILES: ProfileBounds = ProfileBounds {
    reference: None,
    float: FloatBound::Proved(EULER_THEOREMS),
    // |di_a|, |di_b| ≤ |A| + |p·D/2| ≤ 2/n + 2/n, so every slope up to the one after
    // the last pixel is within 4/n + 8/n ≤ 12/n, and |p_i| ≤ 1 + n·4/n = 5
    // (docs/float.md §14).
    fixed: FixedBound::Proved {
        theorem: "fixed_point_euler_error",
        second_order: true,
        value_max: 5.0,
        slope_times_n: 12.0,
    },
    graphs: SECOND_ORDER_GRAPHS,
};
const ANGLE_PROFILES: ProfileBounds = ProfileBounds {
    reference: None,
    float: FloatBound::None(
        "no profile bounds acos and cos (docs/float.md §18.5, \"Not covered\")",
    ),
    fixed: NO_FIXED,
    graphs: &[],
};
// The squared method (docs/float.md §19.7): its graph alone under `ieee` and
// `shader`, the value's root and sign composed by `sq_signed_value_error`, the root
// taken as `1/inverseSqrt` under `shader` rounded as `sq_shader_root_rounding` says.
const SQUARED_PROFILES: ProfileBounds = ProfileBounds {
    reference: None,
    float: FloatBound::Graphs {
        theorem: "sq_signed_value_error",
        shader_root: "sq_shader_root_rounding",
        section: "docs/float.md §19.7",
    },
    fixed: NO_FIXED,
    graphs: &["recurrence", "closed", "lanes"],
};
const RELATED_PROFILES: ProfileBounds = ProfileBounds {
    reference: None,
    float: FloatBound::None("their bounds follow this crate's own evaluation (docs/float.md §16)"),
    fixed: NO_FIXED,
    graphs: &[],
};

methods! {
    /// [`crate::phong`]: the exact per-pixel value (eq. 4).
    Phong {
        run: real |span, _prep, out| crate::phong::shade(span, out).map(|()| None),
        info: {
            name: "phong",
            label: "Phong",
            source: "Phong 1975",
            equations: "eq. 4",
            module: "phong",
            phong_pixels: All,
            roots: Roots::None,
            reconstructed: false,
            family: Paper,
            exact_cost: 16,
            range: Diffuse,
            float_section: "§9",
            bound: PHONG,
            picks: None,
            closed_form: None,
            profiles: COMPOSED_PER_PIXEL,
        },
    }
    /// [`crate::duff`]: Duff's forward differences (eqs. 5–7).
    Duff {
        run: real |span, _prep, out| crate::duff::shade(span, out).map(|()| None),
        info: {
            name: "duff",
            label: "Duff",
            source: "Duff 1979",
            equations: "eqs. 5–7",
            module: "duff",
            phong_pixels: All,
            roots: Roots::None,
            reconstructed: false,
            family: Paper,
            exact_cost: 16,
            range: Diffuse,
            float_section: "§8",
            bound: DUFF,
            picks: None,
            closed_form: None,
            profiles: COMPOSED_RATIO,
        },
    }
    /// [`crate::symmetric_phong`]: half the square roots (§4).
    SymmetricPhong {
        run: real |span, _prep, out| crate::symmetric_phong::shade(span, out).map(|()| None),
        info: {
            name: "symmetric-phong",
            label: "symmetric Phong",
            source: HBB,
            equations: "§4",
            module: "symmetric_phong",
            phong_pixels: All,
            roots: Roots::None,
            reconstructed: false,
            family: Paper,
            exact_cost: 16,
            range: Diffuse,
            float_section: "§8",
            bound: DUFF,
            picks: None,
            closed_form: None,
            profiles: COMPOSED_HALF_RATIO,
        },
    }
    /// [`crate::gouraud`]: linear between the exact edge values (Gouraud along the
    /// span, Behrens' fence shading).
    Gouraud {
        run: field |span, _kd, out| crate::gouraud::shade(span, out).map(|()| None),
        info: {
            name: "gouraud",
            label: "Gouraud (fence)",
            source: "Gouraud 1971, Behrens 1994",
            equations: "§1, eq. 23's d_p",
            module: "gouraud",
            phong_pixels: Ends,
            roots: Roots::None,
            reconstructed: false,
            family: Paper,
            exact_cost: 1,
            range: Diffuse,
            float_section: "§5",
            bound: GOURAUD,
            picks: None,
            closed_form: Some(Valued::Gouraud),
            profiles: GOURAUD_PROFILES,
        },
    }
    /// [`crate::euler`]: eqs. 12–13.
    Euler {
        run: field |span, _kd, out| crate::euler::shade(span, out).map(|()| None),
        info: {
            name: "euler",
            label: "Euler",
            source: HBB,
            equations: "eqs. 12–14",
            module: "euler",
            phong_pixels: PhongPixels::First,
            roots: Roots::None,
            reconstructed: false,
            family: Paper,
            exact_cost: 1,
            range: Diffuse,
            float_section: "§7",
            bound: EULER,
            picks: None,
            closed_form: Some(Valued::Euler),
            profiles: EULER_PROFILES,
        },
    }
    /// [`crate::corrected_euler`]: eqs. 16–17.
    CorrectedEuler {
        run: field |span, _kd, out| crate::corrected_euler::shade(span, out).map(|()| None),
        info: {
            name: "corrected-euler",
            label: "corrected Euler",
            source: HBB,
            equations: "eqs. 15–17",
            module: "corrected_euler",
            phong_pixels: Ends,
            roots: Roots::None,
            reconstructed: false,
            family: Paper,
            exact_cost: 1,
            range: Diffuse,
            float_section: "§6",
            bound: CORRECTED_EULER,
            picks: None,
            closed_form: Some(Valued::CorrectedEuler),
            profiles: CORRECTED_EULER_PROFILES,
        },
    }
    /// [`crate::adaptive`]: Gouraud or corrected Euler by eqs. 23–24.
    Adaptive {
        run: field |span, kd, out| crate::adaptive::shade(span, kd, out).map(Some),
        info: {
            name: "adaptive",
            label: "adaptive",
            source: HBB,
            equations: "eqs. 23–24",
            module: "adaptive",
            phong_pixels: Ends,
            roots: Roots::None,
            reconstructed: false,
            family: Paper,
            exact_cost: 1,
            range: Diffuse,
            float_section: "§10",
            bound: ADAPTIVE,
            picks: Some([Method::Gouraud, Method::CorrectedEuler]),
            closed_form: None,
            profiles: ADAPTIVE_PROFILES,
        },
    }
    /// [`crate::squared_corrected_euler`]: corrected Euler on `g = (N·L)²/|N|²`, the
    /// paper's open question (§7.1, b); the value `sign(p)·√max(0, g)`.
    SquaredCorrectedEuler {
        run: real |span, _prep, out| crate::squared_corrected_euler::shade(span, out).map(|()| None),
        info: {
            name: "squared-corrected-euler",
            label: "squared corrected Euler",
            source: HBB,
            equations: "§7.1 (b), eqs. 15–17 on g",
            module: "squared_corrected_euler",
            phong_pixels: Ends,
            roots: Roots::SignedRootOfG,
            reconstructed: false,
            family: Paper,
            exact_cost: 16,
            range: Diffuse,
            float_section: "§19.7",
            bound: Bound::Graphs,
            picks: None,
            closed_form: None,
            profiles: SQUARED_PROFILES,
        },
    }
    /// [`crate::angular`]: cosine of the linearly interpolated angle (second source).
    Angular {
        run: real |span, _prep, out| crate::angular::shade(span, out).map(|()| None),
        info: {
            name: "angular",
            label: "angular",
            source: "Mortensen 1995",
            equations: "second source",
            module: "angular",
            phong_pixels: PhongPixels::AngularEnds,
            roots: Roots::None,
            reconstructed: false,
            family: Family::Angular,
            exact_cost: 16,
            range: Diffuse,
            float_section: "§11",
            bound: ANGLE,
            picks: None,
            closed_form: None,
            profiles: ANGLE_PROFILES,
        },
    }
    /// [`crate::angular::shade_table`] with a cosine table of this many entries.
    AngularTable(size: u32 = SOURCE_TABLE) {
        run: real |span, prep, out| match &prep.table {
            // The prepared table when it is this size, else one built for the call.
            Some(t) if t.values.len() == *size as usize => crate::angular::shade_table(span, t, out),
            _ => crate::angular::shade_table(span, &CosTable::new(*size)?, out),
        }
        .map(|()| None),
        info: {
            name: "angular-table",
            label: "angular, tabled",
            source: "Mortensen 1995",
            equations: "second source",
            module: "angular",
            phong_pixels: PhongPixels::Table,
            roots: Roots::None,
            reconstructed: false,
            family: Family::Angular,
            exact_cost: 16,
            range: Diffuse,
            float_section: "§11",
            bound: Bound::Angle {
                extra: 20.0,
                table: Some(*size),
            },
            picks: None,
            closed_form: None,
            profiles: ANGLE_PROFILES,
        },
    }
    /// [`crate::related::spherical`]: Kuijk & Blake's spherical interpolation.
    Spherical {
        run: real |span, _prep, out| spherical::shade(span, out).map(|()| None),
        info: {
            name: "spherical",
            label: "spherical",
            source: "Kuijk & Blake 1989",
            equations: "Chebyshev recurrence",
            module: "related::spherical",
            phong_pixels: EndsAndEvenMiddle,
            roots: Roots::None,
            reconstructed: true,
            family: Related,
            exact_cost: 20,
            range: Diffuse,
            float_section: "§16.1",
            bound: Bound::WholeSpan(WholeSpan::Spherical),
            picks: None,
            closed_form: None,
            profiles: RELATED_PROFILES,
        },
    }
    /// [`crate::related::binary`]: Ouyang & Maynard's binary interpolation.
    Binary {
        run: real |span, _prep, out| binary::shade(span, out).map(|()| None),
        info: {
            name: "binary",
            label: "binary",
            source: "Ouyang & Maynard 1996",
            equations: "binary subdivision",
            module: "related::binary",
            phong_pixels: BinarySegments,
            roots: Roots::None,
            reconstructed: true,
            family: Related,
            exact_cost: 300,
            range: Diffuse,
            float_section: "§16.2",
            bound: Bound::WholeSpan(WholeSpan::Binary),
            picks: None,
            closed_form: None,
            profiles: RELATED_PROFILES,
        },
    }
    /// [`crate::related::bishop_weimer::shade`]: Bishop & Weimer's Taylor expansion
    /// along the span, about its middle pixel.
    BishopWeimer {
        run: real |span, _prep, out| bishop_weimer::shade(span, out).map(|()| None),
        info: {
            name: "bishop-weimer",
            label: "Bishop–Weimer",
            source: "Bishop & Weimer 1986",
            equations: "2-D Taylor, along the span",
            module: "related::bishop_weimer",
            phong_pixels: EvenMiddle,
            roots: Roots::None,
            reconstructed: false,
            family: Related,
            exact_cost: 20,
            range: HalfAngleTaylor,
            float_section: "§16.3",
            bound: Bound::WholeSpan(WholeSpan::BishopWeimer),
            picks: None,
            closed_form: None,
            profiles: RELATED_PROFILES,
        },
    }
}

impl Method {
    /// The paper's method, corrected Euler (eqs. 16–17): the test kit's default, the
    /// method of the paper's Table 1 and Figures 3–4 in the studies.
    pub const PAPER: Method = Method::CorrectedEuler;
}
