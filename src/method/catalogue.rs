//! The catalogue's columns: the types of the named facts each row of the list
//! (`list.rs`, read through [`Method::info`]) gives a method — its name, source,
//! equations, module, what it needs of the number type, where its exact level is
//! decided from `p` and `q`, its family, the cost of its exact run, its value range,
//! its float bound under the `reference` profile and its bounds under every acceptance
//! profile (`profiles.rs`), as data.

use super::Method;
use crate::reference::radical::Valued;
use crate::related::binary;
use crate::span::Span;
use crate::BigRational;
use std::fmt;

pub use super::profiles::{DerivedForm, FixedBound, FloatBound, ProfileBounds, Proved};

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
    /// Where its exact value is a root of a rational of its exact run at every pixel
    /// (the squared method's `sign(p_i)·√max(0, g_i)`), so that its exact 8-bit level
    /// is decided in rationals everywhere, as at [`Info::phong_pixels`].
    pub roots: Roots,
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
    /// A bound that reads the whole span (`sin Ω`): the related methods', each its
    /// own derivation ([`crate::tolerance::related`]).
    WholeSpan(WholeSpan),
    /// The `ieee` bound of the method's operation graphs on the case's own inputs
    /// (this crate's run is one `ieee` implementation: round to nearest, its own
    /// order): no formula in `n` and `q_min`, so only with the span's shape, and
    /// `n ≤ 4096` (`crate::tolerance::graphs::MAX_GRAPH_STEPS`).
    Graphs,
}

/// Which whole-span derivation bounds a related method (`docs/float.md` §16).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WholeSpan {
    /// Kuijk & Blake's spherical interpolation (§16.1).
    Spherical,
    /// Ouyang & Maynard's binary interpolation (§16.2).
    Binary,
    /// Bishop & Weimer's Taylor expansion (§16.3).
    BishopWeimer,
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

/// A method whose exact value at every pixel is a root of a rational of its exact
/// run: its levels, diffuse and specular, are decided from `(p, q)` with the value
/// `p/√q` ([`Roots::pairs`]), as Phong's are, however close to a level boundary.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Roots {
    /// The squared method's `sign(p_i)·√max(0, g_i)`, `g_i` and `p_i` its exact
    /// recurrences (`sq_closed_form`, exact in rationals): `p/√q` with
    /// `(p, q) = (sign(p_i)·g_i, g_i)` where `g_i > 0`, else `(0, 1)`.
    SignedRootOfG,
    /// None: the value is the exact run's rational, or known to its precision only.
    None,
}

impl Roots {
    /// `(p, q)` at every pixel of `span`, `q > 0`, with the method's exact value
    /// `p/√q`; `None` for [`Roots::None`] or a span the method refuses.
    pub fn pairs(&self, span: &Span<BigRational>) -> Option<Vec<(BigRational, BigRational)>> {
        use num_traits::{One, Signed, Zero};
        match self {
            Roots::None => None,
            Roots::SignedRootOfG => {
                let sq = crate::squared_corrected_euler::SquaredSpan::of(span).ok()?;
                let mut g = vec![BigRational::zero(); span.n as usize + 1];
                sq.shade(&mut g).ok()?;
                let mut p = sq.b.clone();
                let pairs = g
                    .into_iter()
                    .map(|g| {
                        let pair = if g.is_positive() && !p.is_zero() {
                            let signed = if p.is_positive() {
                                g.clone()
                            } else {
                                -g.clone()
                            };
                            (signed, g)
                        } else {
                            (BigRational::zero(), BigRational::one())
                        };
                        p += &sq.a;
                        pair
                    })
                    .collect();
                Some(pairs)
            }
        }
    }
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
