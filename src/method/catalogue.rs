//! The catalogue: one row of named facts per method ([`Method::info`]) — its name,
//! source, equations, module, what it needs of the number type, where its exact level
//! is decided from `p` and `q`, its family, the cost of its exact run, its value range
//! and its float bound under the `reference` profile, as data — and the types of
//! those columns. The acceptance profiles' bounds are `tolerance::profile::status`'s
//! rows, one per method too.

use super::Method;
use crate::reference::radical::Valued;
use crate::related::binary;
use crate::span::Span;
use crate::BigRational;
use std::fmt;

pub use super::profiles::{
    DerivedForm, FixedBound, FloatBound, FloatProfile, ProfileBounds, Proved,
};
use super::profiles::{CORRECTED_EULER_THEOREMS, EULER_THEOREMS, GOURAUD_THEOREMS};

/// What a method asks of the number type.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Needs {
    /// Field operations only ([`Scalar`](crate::Scalar)): exact in rationals.
    Field,
    /// Square roots, `acos` or `cos` as well ([`Real`](crate::Real)).
    Real,
}

/// Everything the catalogue knows of a method.
#[derive(Clone, Copy)]
pub struct Info {
    /// The name in the CLI, the vector files and every table; the tabled angular
    /// method's is this followed by its table size (`angular-table256`).
    pub name: &'static str,
    /// A label for people (`corrected Euler`).
    pub label: &'static str,
    /// Who the method is by.
    pub source: &'static str,
    /// The equations it implements.
    pub equations: &'static str,
    /// The module that implements it.
    pub module: &'static str,
    /// What it asks of the number type.
    pub needs: Needs,
    /// The pixels where its exact value is Phong's `p_i/√q_i`, so that the exact
    /// 8-bit level there is decided from `p_i` and `q_i` in rationals
    /// ([`phong_level_exact`](crate::reference::level::phong_level_exact)) however close it is to a level boundary.
    pub phong_pixels: PhongPixels,
    /// Whether part of the method is a reconstruction from an incomplete description
    /// (`docs/comparison.md`).
    pub reconstructed: bool,
    /// Where the method comes from: the paper, the second source, or the related work.
    pub family: Family,
    /// The cost of one pixel of its exact run, in units of corrected Euler's (about
    /// 8 µs in release: `docs/performance.md`, "Exact runs"), for the budgets of
    /// `check` and `span` (`conformance::integrity::exact_work`).
    pub exact_cost: u64,
    /// How far its values may range on exact unit inputs (what a vector file's
    /// expectations are checked against).
    pub range: ValueRange,
    /// The section of `docs/float.md` that derives its float bound (`§5`).
    pub float_section: &'static str,
    /// That bound under the `reference` profile, as data: its form and constants
    /// ([`crate::tolerance::reference_bound`] evaluates it).
    pub bound: Bound,
    /// The methods it picks between per span (the adaptive scheme: Gouraud where
    /// eq. 23's test says the span is flat enough, else corrected Euler), whose exact
    /// runs judge an implementation that picks the other one near the test's
    /// threshold; `None` for a method that runs itself.
    pub picks: Option<[Method; 2]>,
    /// Its values as a closed form of the span's set-up, everywhere (Gouraud's line,
    /// Euler's and corrected Euler's parabolas), so that an exact level on normalized
    /// inputs is decided in `Q(√a, √b, √c)` ([`crate::reference::radical`]) at every
    /// pixel, not only where it is Phong's ([`Info::phong_pixels`]); `None` for the
    /// others.
    pub closed_form: Option<Valued>,
    /// Its bounds beyond the `reference` derivation: under `ieee` and `shader`, in
    /// fixed point, and the theorems of its `reference` bound, as data.
    pub profiles: ProfileBounds,
}

/// A method's float bound against its exact run under the `reference` profile, as
/// data: the form of the derivation (the `docs/float.md` section of the catalogue
/// row) and its constants, in units of the unit roundoff `u`. Every form holds while
/// `n·u ≤ 2^-12`. A new method whose bound has one of these forms needs only its
/// catalogue row; a new form needs its arm in [`crate::tolerance::reference_bound`]
/// too.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Bound {
    /// A recurrence's `(α·n + β)·u`, `below = (α, β)` for `n ≤ 4096`; past 4096
    /// (binary64) the coefficients `large` where a theorem gives others.
    Linear {
        /// `(α, β)` for `n ≤ 4096`.
        below: (f64, f64),
        /// `(α, β)` past 4096, when they differ.
        large: Option<(f64, f64)>,
    },
    /// The ratio `p/√q` of two recurrences whose errors are `(α·n + β)·u` each
    /// (`docs/float.md` §8), with the square root and the division rounded.
    Ratio {
        /// `(α, β)` of `p`.
        p: (f64, f64),
        /// `(α, β)` of `q`.
        q: (f64, f64),
    },
    /// A normal interpolated and normalized per pixel (§9): `(normal/√q_min + eval)·u`.
    PerPixel {
        /// The interpolated normal's error (Euclidean, in `u`).
        normal: f64,
        /// The evaluation's error (in `u`).
        eval: f64,
    },
    /// The larger of the bounds of the methods it picks between ([`Info::picks`]: the
    /// adaptive scheme runs one or the other).
    LargerOfPicks,
    /// The interpolated angle's bound (§11) plus `extra·u`, and one step of a cosine
    /// table of `table` entries when the cosine is tabled.
    Angle {
        /// Further roundings (in `u`).
        extra: f64,
        /// The cosine table's size.
        table: Option<u32>,
    },
    /// A bound that reads the whole span (`sin Ω`): the related methods'
    /// ([`crate::tolerance::related`]).
    WholeSpan,
}

/// Where a method comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// The paper's own methods and the ones it compares itself with (Phong, Duff,
    /// Gouraud, Euler, corrected Euler, symmetric Phong, the adaptive scheme).
    Paper,
    /// The second source's angular interpolation.
    Angular,
    /// A related method along a span (Kuijk & Blake, Ouyang & Maynard, Bishop &
    /// Weimer): its float bound and its exact precision read the whole span (`sin Ω`,
    /// not only `n` and `q_min`).
    Related,
}

/// The range of a method's values on exact unit inputs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ValueRange {
    /// Within `[−4, 4]` (plain Euler's overshoot, `|E_i| ≤ 3.77`, is the largest:
    /// `docs/float.md` §3).
    Diffuse,
    /// Bishop–Weimer's expansion, which grows without limit as the normals near
    /// opposite: `|v| ≤ 1 + τ + τ²/2`, `τ = tan(Ω/2)` (`docs/float.md` §16.3).
    HalfAngleTaylor,
}

impl fmt::Debug for Info {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Info")
            .field("name", &self.name)
            .field("needs", &self.needs)
            .field("phong_pixels", &self.phong_pixels)
            .finish_non_exhaustive()
    }
}

/// Where a method's exact value is Phong's `p_i/√q_i` (in real arithmetic; the run in
/// floats or with approximate square roots may differ by its error).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PhongPixels {
    /// Every pixel (Phong, Duff, symmetric Phong).
    All,
    /// Pixel 0 only (Euler misses `p_b`, eq. 15).
    First,
    /// Pixels `0` and `n`, where the value is `p_a` or `p_b` (Gouraud, corrected
    /// Euler, adaptive).
    Ends,
    /// The ends (`cos(acos p)`), and every pixel when `p_a = p_b` (the angle does not
    /// move: the value is `p_a`) — angular interpolation.
    AngularEnds,
    /// The ends and, for even `n`, the middle pixel (spherical:
    /// `spherical_equals_phong_at_the_middle`).
    EndsAndEvenMiddle,
    /// The segment ends of binary interpolation and, when `n` is a power of two, the
    /// middle (`binary_exact_at_ends_and_whole_span_midpoint`).
    BinarySegments,
    /// For even `n`, the middle pixel, the expansion point (Bishop–Weimer's `T0`).
    EvenMiddle,
    /// None known, but a value of exactly 1 is the table's entry `cos 0`, which the
    /// exact run computes exactly (the tabled angular method reads even its ends from
    /// the table).
    Table,
    /// None known.
    None,
}

impl PhongPixels {
    /// `(p, q)` with the method's exact value at pixel `i` of `span` equal to
    /// `p/√q`, where that is known; `None` elsewhere.
    pub fn exact_at(&self, span: &Span<BigRational>, i: u32) -> Option<(BigRational, BigRational)> {
        // N_a = N_b: every untabled method is constant p_a (k = 0, q = 1: no step
        // moves the value). Angular with p_a = p_b: the angle does not move.
        let constant = (span.na == span.nb
            && !matches!(self, PhongPixels::None | PhongPixels::Table))
            || (*self == PhongPixels::AngularEnds && span.p_a == span.p_b);
        if constant {
            return Some((span.p_a.clone(), BigRational::from_integer(1.into())));
        }
        self.at(span.n, i).then(|| (span.p_at(i), span.q_at(i)))
    }

    /// Whether pixel `i` of a span of `n` steps is one where the value is Phong's
    /// (for any `p_a`, `p_b`).
    pub fn at(&self, n: u32, i: u32) -> bool {
        let ends = i == 0 || i == n;
        let even_middle = n.is_multiple_of(2) && 2 * i == n;
        match self {
            PhongPixels::All => true,
            PhongPixels::First => i == 0,
            PhongPixels::Ends | PhongPixels::AngularEnds => ends,
            PhongPixels::EndsAndEvenMiddle => ends || even_middle,
            PhongPixels::BinarySegments => {
                binary::segments(n).contains(&i) || (n.is_power_of_two() && even_middle)
            }
            PhongPixels::EvenMiddle => even_middle,
            PhongPixels::Table | PhongPixels::None => false,
        }
    }
}

impl Method {
    /// The catalogue entry.
    pub fn info(&self) -> Info {
        const HBB: &str = "Hast, Barrera, Bengtsson";
        let (field, real) = (Needs::Field, Needs::Real);
        use Bound::{Linear, Ratio, WholeSpan};
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
        const NO_FIXED: FixedBound =
            FixedBound::None("proofs/Fixed.v proves Gouraud's and corrected Euler's loops only");
        const fn derived(section: &'static str, form: DerivedForm) -> ProfileBounds {
            ProfileBounds {
                reference: None,
                float: FloatBound::Derived { section, form },
                fixed: NO_FIXED,
            }
        }
        const DERIVED_PER_PIXEL: ProfileBounds =
            derived("docs/float.md §18.4", DerivedForm::PerPixel);
        const DERIVED_RATIO: ProfileBounds = derived("docs/float.md §18.5", DerivedForm::Ratio);
        const DERIVED_HALF_RATIO: ProfileBounds =
            derived("docs/float.md §18.5", DerivedForm::HalfRatio);
        // The larger of the two proved bounds, against the exact run of the method the
        // implementation chose (docs/float.md §10, §18.5).
        const ADAPTIVE_PROFILES: ProfileBounds =
            derived("docs/float.md §18.5", DerivedForm::LargerOfPicks);
        const GOURAUD_PROFILES: ProfileBounds = ProfileBounds {
            reference: Some(["float_gouraud_binary32", "float_gouraud_binary64"]),
            float: FloatBound::Proved(GOURAUD_THEOREMS),
            fixed: FixedBound::Proved {
                theorem: "fixed_point_gouraud_error",
                second_order: false,
                value_max: 1.0,
                slope_times_n: 2.0,
            },
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
        };
        const EULER_PROFILES: ProfileBounds = ProfileBounds {
            reference: None,
            float: FloatBound::Proved(EULER_THEOREMS),
            fixed: NO_FIXED,
        };
        const ANGLE_PROFILES: ProfileBounds = ProfileBounds {
            reference: None,
            float: FloatBound::None(
                "no profile bounds acos and cos (docs/float.md §18.5, \"Not covered\")",
            ),
            fixed: NO_FIXED,
        };
        const RELATED_PROFILES: ProfileBounds = ProfileBounds {
            reference: None,
            float: FloatBound::None(
                "their bounds follow this crate's own evaluation (docs/float.md §16)",
            ),
            fixed: NO_FIXED,
        };
        match self {
            Method::Phong => Info {
                name: "phong",
                label: "Phong",
                source: "Phong 1975",
                equations: "eq. 4",
                module: "phong",
                needs: real,
                phong_pixels: All,
                reconstructed: false,
                family: Paper,
                exact_cost: 16,
                range: Diffuse,
                float_section: "§9",
                bound: PHONG,
                picks: None,
                closed_form: None,
                profiles: DERIVED_PER_PIXEL,
            },
            Method::Duff => Info {
                name: "duff",
                label: "Duff",
                source: "Duff 1979",
                equations: "eqs. 5–7",
                module: "duff",
                needs: real,
                phong_pixels: All,
                reconstructed: false,
                family: Paper,
                exact_cost: 16,
                range: Diffuse,
                float_section: "§8",
                bound: DUFF,
                picks: None,
                closed_form: None,
                profiles: DERIVED_RATIO,
            },
            Method::SymmetricPhong => Info {
                name: "symmetric-phong",
                label: "symmetric Phong",
                source: HBB,
                equations: "§4",
                module: "symmetric_phong",
                needs: real,
                phong_pixels: All,
                reconstructed: false,
                family: Paper,
                exact_cost: 16,
                range: Diffuse,
                float_section: "§8",
                bound: DUFF,
                picks: None,
                closed_form: None,
                profiles: DERIVED_HALF_RATIO,
            },
            Method::Gouraud => Info {
                name: "gouraud",
                label: "Gouraud (fence)",
                source: "Gouraud 1971, Behrens 1994",
                equations: "§1, eq. 23's d_p",
                module: "gouraud",
                needs: field,
                phong_pixels: Ends,
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
            Method::Euler => Info {
                name: "euler",
                label: "Euler",
                source: HBB,
                equations: "eqs. 12–14",
                module: "euler",
                needs: field,
                phong_pixels: PhongPixels::First,
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
            Method::CorrectedEuler => Info {
                name: "corrected-euler",
                label: "corrected Euler",
                source: HBB,
                equations: "eqs. 15–17",
                module: "corrected_euler",
                needs: field,
                phong_pixels: Ends,
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
            Method::Adaptive => Info {
                name: "adaptive",
                label: "adaptive",
                source: HBB,
                equations: "eqs. 23–24",
                module: "adaptive",
                needs: field,
                phong_pixels: Ends,
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
            Method::Angular => Info {
                name: "angular",
                label: "angular",
                source: "Mortensen 1995",
                equations: "second source",
                module: "angular",
                needs: real,
                phong_pixels: PhongPixels::AngularEnds,
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
            Method::AngularTable(size) => Info {
                name: "angular-table",
                label: "angular, tabled",
                source: "Mortensen 1995",
                equations: "second source",
                module: "angular",
                needs: real,
                phong_pixels: PhongPixels::Table,
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
            Method::Spherical => Info {
                name: "spherical",
                label: "spherical",
                source: "Kuijk & Blake 1989",
                equations: "Chebyshev recurrence",
                module: "related::spherical",
                needs: real,
                phong_pixels: EndsAndEvenMiddle,
                reconstructed: true,
                family: Related,
                exact_cost: 20,
                range: Diffuse,
                float_section: "§16.1",
                bound: WholeSpan,
                picks: None,
                closed_form: None,
                profiles: RELATED_PROFILES,
            },
            Method::Binary => Info {
                name: "binary",
                label: "binary",
                source: "Ouyang & Maynard 1996",
                equations: "binary subdivision",
                module: "related::binary",
                needs: real,
                phong_pixels: BinarySegments,
                reconstructed: true,
                family: Related,
                exact_cost: 300,
                range: Diffuse,
                float_section: "§16.2",
                bound: WholeSpan,
                picks: None,
                closed_form: None,
                profiles: RELATED_PROFILES,
            },
            Method::BishopWeimer => Info {
                name: "bishop-weimer",
                label: "Bishop–Weimer",
                source: "Bishop & Weimer 1986",
                equations: "2-D Taylor, along the span",
                module: "related::bishop_weimer",
                needs: real,
                phong_pixels: EvenMiddle,
                reconstructed: false,
                family: Related,
                exact_cost: 20,
                range: HalfAngleTaylor,
                float_section: "§16.3",
                bound: WholeSpan,
                picks: None,
                closed_form: None,
                profiles: RELATED_PROFILES,
            },
        }
    }
}
