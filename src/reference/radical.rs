//! Exact arithmetic in `Q(√a, √b, √c)`: the values of a span whose inputs are
//! normalized rational vectors (`N_a/√a`, `N_b/√b`, `L/√c` with `a = |N_a|²`, …), so
//! that `--normalize` can decide a level exactly where the value sits on a level
//! boundary (a value of exactly 1, say), as it does for unit inputs.
//!
//! An element is `Σ_S x_S·√(Π_{j∈S} r_j)` over the subsets `S` of the radicands (bit
//! `j` of the index says whether `√r_j` is a factor). The representation need not be
//! unique (a radicand may be a square), but the sign is decided exactly whatever the
//! radicands: `x = α + β·√r` with `α`, `β` in the smaller field has the sign of `α`
//! when `α` and `β` agree in sign, else the sign of `α² − β²·r` times that of `α`
//! (both sides of `|α| ≶ |β|·√r` are non-negative, so squaring keeps the order).
//!
//! Tested: the unit tests below and `tests/reliability/span.rs::exact_levels_with_normalize`.

use crate::reference::level::level_within;
use crate::vector::Vec3;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};
use std::cmp::Ordering;

/// An element of `Q(√r_0, …, √r_{k−1})`: `2^k` rational coefficients.
#[derive(Clone, Debug, PartialEq)]
pub struct Radical {
    c: Vec<BigRational>,
}

impl Radical {
    /// The rational `x` in a tower of `k` radicands.
    pub fn rational(x: BigRational, k: usize) -> Radical {
        let mut c = vec![BigRational::zero(); 1 << k];
        c[0] = x;
        Radical { c }
    }

    /// `x·√r_j` in a tower of `k` radicands.
    pub fn root(x: BigRational, j: usize, k: usize) -> Radical {
        let mut c = vec![BigRational::zero(); 1 << k];
        c[1 << j] = x;
        Radical { c }
    }

    /// `self + o`.
    pub fn add(&self, o: &Radical) -> Radical {
        Radical {
            c: self.c.iter().zip(&o.c).map(|(x, y)| x + y).collect(),
        }
    }

    /// `self − o`.
    pub fn sub(&self, o: &Radical) -> Radical {
        Radical {
            c: self.c.iter().zip(&o.c).map(|(x, y)| x - y).collect(),
        }
    }

    /// `x·self` for a rational `x`.
    pub fn scale(&self, x: &BigRational) -> Radical {
        Radical {
            c: self.c.iter().map(|y| y * x).collect(),
        }
    }

    /// `self·o`, with `√r_j·√r_j = r_j` (`r`: the radicands).
    pub fn mul(&self, o: &Radical, r: &[BigRational]) -> Radical {
        let mut c = vec![BigRational::zero(); self.c.len()];
        for (i, x) in self.c.iter().enumerate() {
            if x.is_zero() {
                continue;
            }
            for (j, y) in o.c.iter().enumerate() {
                if y.is_zero() {
                    continue;
                }
                let mut t = x * y;
                let both = i & j;
                for (bit, rb) in r.iter().enumerate() {
                    if both & (1 << bit) != 0 {
                        t *= rb;
                    }
                }
                c[i ^ j] += t;
            }
        }
        Radical { c }
    }

    /// The sign of the element, exactly, for positive radicands `r`.
    pub fn sign(&self, r: &[BigRational]) -> Ordering {
        sign_of(&self.c, r)
    }
}

fn sign_of(c: &[BigRational], r: &[BigRational]) -> Ordering {
    let Some((top, rest)) = r.split_last() else {
        return c[0].cmp(&BigRational::zero());
    };
    let half = c.len() / 2;
    let (alpha, beta) = c.split_at(half);
    let sa = sign_of(alpha, rest);
    let sb = sign_of(beta, rest);
    if sb == Ordering::Equal {
        return sa;
    }
    if sa == Ordering::Equal || sa == sb {
        return sb;
    }
    // α and β differ in sign: compare α² with β²·r.
    let a = Radical { c: alpha.to_vec() };
    let b = Radical { c: beta.to_vec() };
    let d = a.mul(&a, rest).sub(&b.mul(&b, rest).scale(top));
    match d.sign(rest) {
        Ordering::Greater => sa,
        Ordering::Less => sb,
        Ordering::Equal => Ordering::Equal,
    }
}

/// What the normalized span's exact values are, in `Q(√a, √b, √c)`.
struct Normalized {
    r: Vec<BigRational>,
    na: Vec3<Radical>,
    k: Vec3<Radical>,
    l: Vec3<Radical>,
    n: u32,
}

fn dot(x: &Vec3<Radical>, y: &Vec3<Radical>, r: &[BigRational]) -> Radical {
    x.x.mul(&y.x, r)
        .add(&x.y.mul(&y.y, r))
        .add(&x.z.mul(&y.z, r))
}

impl Normalized {
    fn new(na: &Vec3<BigRational>, nb: &Vec3<BigRational>, l: &Vec3<BigRational>, n: u32) -> Self {
        let r = vec![na.dot(na), nb.dot(nb), l.dot(l)];
        // v/√r_j = (v/r_j)·√r_j.
        let unit = |v: &Vec3<BigRational>, j: usize| {
            let s = BigRational::one() / r[j].clone();
            Vec3 {
                x: Radical::root(v.x.clone() * s.clone(), j, 3),
                y: Radical::root(v.y.clone() * s.clone(), j, 3),
                z: Radical::root(v.z.clone() * s, j, 3),
            }
        };
        let (na, nb, l) = (unit(na, 0), unit(nb, 1), unit(l, 2));
        let inv_n = BigRational::new(BigInt::one(), BigInt::from(n));
        let k = Vec3 {
            x: nb.x.sub(&na.x).scale(&inv_n),
            y: nb.y.sub(&na.y).scale(&inv_n),
            z: nb.z.sub(&na.z).scale(&inv_n),
        };
        Normalized { r, na, k, l, n }
    }

    /// `N_i = N_a + i·k` (§2.1).
    fn normal(&self, i: u32) -> Vec3<Radical> {
        let t = BigRational::from_integer(i.into());
        Vec3 {
            x: self.na.x.add(&self.k.x.scale(&t)),
            y: self.na.y.add(&self.k.y.scale(&t)),
            z: self.na.z.add(&self.k.z.scale(&t)),
        }
    }

    /// `p_i` and `q_i` (eqs. 2–3).
    fn p_q(&self, i: u32) -> (Radical, Radical) {
        let ni = self.normal(i);
        (dot(&ni, &self.l, &self.r), dot(&ni, &ni, &self.r))
    }

    /// `p_a`, `di_a` and `ds` of the set-up (eqs. 10–11 and §3), in the field.
    fn setup(&self) -> (Radical, Radical, Radical, Radical) {
        let r = &self.r;
        let two = BigRational::from_integer(2.into());
        let half = BigRational::new(1.into(), 2.into());
        let n_s = BigRational::from_integer(self.n.into());
        let nb = self.normal(self.n);
        let a = dot(&self.k, &self.l, r);
        let c = dot(&self.k, &self.k, r);
        let d = dot(&self.k, &self.na, r).scale(&two);
        let p_a = dot(&self.na, &self.l, r);
        let p_b = dot(&nb, &self.l, r);
        let dq_b = c.scale(&(two * n_s.clone())).add(&d);
        let di_a = a.sub(&p_a.scale(&half).mul(&d, r));
        let di_b = a.sub(&p_b.scale(&half).mul(&dq_b, r));
        let ds = di_b.sub(&di_a).scale(&(BigRational::one() / n_s));
        (p_a, p_b, di_a, ds)
    }
}

/// The largest `ℓ ∈ 0..=255` with `fits(ℓ)`, for a `fits` that holds at 0 and, once
/// false, stays false (a binary search).
fn largest_level(fits: impl Fn(u32) -> bool) -> u8 {
    let (mut lo, mut hi) = (0u32, 255u32);
    while lo < hi {
        let mid = (lo + hi).div_ceil(2);
        if fits(mid) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    lo as u8
}

/// The largest level `ℓ ∈ 0..=255` with `ℓ ≤ 255·kd·v`, i.e. `floor(255·clamp(kd·v, 0, 1))`.
fn level_of(v: &Radical, kd: &BigRational, r: &[BigRational]) -> u8 {
    let w = v.scale(&(kd * BigRational::from_integer(255.into())));
    let fits = |l: u32| {
        w.sub(&Radical::rational(
            BigRational::from_integer(l.into()),
            r.len(),
        ))
        .sign(r)
            != Ordering::Less
    };
    largest_level(fits)
}

/// The level of `kd·p/√q` (`q > 0`): `ℓ ≤ 255·kd·p/√q` iff `ℓ = 0` or `p > 0` and
/// `ℓ²·q ≤ 255²·kd²·p²`. `None` where `q = 0`.
fn phong_level_of(p: &Radical, q: &Radical, kd: &BigRational, r: &[BigRational]) -> Option<u8> {
    if q.sign(r) != Ordering::Greater {
        return None;
    }
    if p.sign(r) != Ordering::Greater || kd.is_zero() {
        return Some(0);
    }
    let s = kd * BigRational::from_integer(255.into());
    let p2 = p.mul(p, r).scale(&(s.clone() * s));
    let fits = |l: u32| {
        let l2 = BigRational::from_integer((l * l).into());
        p2.sub(&q.scale(&l2)).sign(r) != Ordering::Less
    };
    Some(largest_level(fits))
}

/// Which exact value a method has on a span, for [`normalized_levels`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Valued {
    /// `p_i/√q_i` (Phong, Duff, symmetric Phong).
    Phong,
    /// `p_a + i·(p_b − p_a)/n` (Gouraud).
    Gouraud,
    /// `p_a + i·di_a + i(i−1)/2·ds` (Euler, eqs. 12–13).
    Euler,
    /// `p_a + i·t_0 + i(i−1)/2·ds`, `t_0 = di_a − ε/n` (corrected Euler, eqs. 15–17).
    CorrectedEuler,
}

/// The 8-bit levels of `kd·v_i` for the span of the *normalized* inputs
/// `N_a/|N_a|`, `N_b/|N_b|`, `L/|L|` (rational, non-zero), given `approx`: values
/// within `e` of the exact ones. A level is taken from the approximation where the
/// interval `[v − e, v + e]` decides it, and decided exactly in `Q(√a, √b, √c)`
/// elsewhere (a value on a level boundary, such as exactly 1) when `valued(i)` says
/// what the exact value at pixel `i` is; `None` where it says nothing (a method whose
/// value there is not in the field) or where `q_i` is zero.
pub fn normalized_levels(
    valued: impl Fn(u32) -> Option<Valued>,
    (na, nb, l): (&Vec3<BigRational>, &Vec3<BigRational>, &Vec3<BigRational>),
    n: u32,
    kd: &BigRational,
    approx: &[BigRational],
    e: &BigRational,
) -> Vec<Option<u8>> {
    let mut field: Option<(Normalized, (Radical, Radical, Radical, Radical))> = None;
    (0..=n)
        .map(|i| {
            if let Some(v) = approx.get(i as usize) {
                if let Some(l) = level_within(&(v * kd), &(e * kd)) {
                    return Some(l);
                }
            }
            let valued = valued(i)?;
            let (z, setup) = field.get_or_insert_with(|| {
                let z = Normalized::new(na, nb, l, n);
                let s = z.setup();
                (z, s)
            });
            let r = &z.r;
            let (p_a, p_b, di_a, ds) = setup;
            let t = BigRational::from_integer(i.into());
            let n_s = BigRational::from_integer(n.into());
            let tri = |m: &BigRational| {
                m * (m - BigRational::one()) / BigRational::from_integer(2.into())
            };
            let v = match valued {
                Valued::Phong => {
                    let (p, q) = z.p_q(i);
                    return phong_level_of(&p, &q, kd, r);
                }
                Valued::Gouraud => p_a.add(&p_b.sub(p_a).scale(&(t / n_s))),
                Valued::Euler => p_a.add(&di_a.scale(&t)).add(&ds.scale(&tri(&t))),
                Valued::CorrectedEuler => {
                    let p_n = p_a.add(&di_a.scale(&n_s)).add(&ds.scale(&tri(&n_s)));
                    let eps = p_n.sub(p_b);
                    let t0 = di_a.sub(&eps.scale(&(BigRational::one() / n_s)));
                    p_a.add(&t0.scale(&t)).add(&ds.scale(&tri(&t)))
                }
            };
            Some(level_of(&v, kd, r))
        })
        .collect()
}

/// Whether eq. 24's test picks Gouraud for the span of the *normalized* inputs `N_a/|N_a|`, `N_b/|N_b|`,
/// `L/|L|` (rational, non-zero), decided exactly in `Q(√a, √b, √c)`: Gouraud when
/// `ds = 0` or `|δ·255·kd| < 1`, with `δ` the difference between Gouraud and corrected
/// Euler after `j = ⌈n/2⌉` steps, the step eq. 23 gives in exact arithmetic
/// (`eq_23_m_is_half_n_minus_1`, `eq_23_truncated_step_is_ceil_half`,
/// proofs/Adaptive.v). What [`crate::adaptive::decide`] computes from square roots
/// accurate to 2^-256 cannot decide a span whose `255·kd·|δ|` lies within that of 1;
/// this does. `true`: Gouraud.
pub fn normalized_adaptive_gouraud(
    (na, nb, l): (&Vec3<BigRational>, &Vec3<BigRational>, &Vec3<BigRational>),
    n: u32,
    kd: &BigRational,
) -> bool {
    let z = Normalized::new(na, nb, l, n);
    let r = &z.r;
    let (p_a, p_b, di_a, ds) = z.setup();
    if ds.sign(r) == Ordering::Equal || n < 2 {
        return true;
    }
    let n_s = BigRational::from_integer(n.into());
    let j = BigRational::from_integer(n.div_ceil(2).into());
    let tri = |m: &BigRational| m * (m - BigRational::one()) / BigRational::from_integer(2.into());
    let p_n = p_a.add(&di_a.scale(&n_s)).add(&ds.scale(&tri(&n_s)));
    let t0 = di_a.sub(&p_n.sub(&p_b).scale(&(BigRational::one() / n_s.clone())));
    let dp = p_b.sub(&p_a).scale(&(BigRational::one() / n_s));
    // Eq. 24: δ = j·d_p − (j·t_0 + (j² − j)/2·ds).
    let delta = dp.scale(&j).sub(&t0.scale(&j).add(&ds.scale(&tri(&j))));
    let w = delta.scale(&(kd * BigRational::from_integer(255.into())));
    let one = Radical::rational(BigRational::one(), r.len());
    w.sub(&one).sign(r) == Ordering::Less && w.add(&one).sign(r) == Ordering::Greater
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn signs_are_exact_whatever_the_radicands() {
        let r = vec![q(2, 1), q(3, 1), q(4, 1)];
        // √2 − √3 < 0; 1 + √2 − √3 > 0 (2.414 > 1.732); √4 − 2 = 0 (a square radicand).
        let mut x = Radical::root(q(1, 1), 0, 3).sub(&Radical::root(q(1, 1), 1, 3));
        assert_eq!(x.sign(&r), Ordering::Less);
        x = x.add(&Radical::rational(q(1, 1), 3));
        assert_eq!(x.sign(&r), Ordering::Greater);
        let y = Radical::root(q(1, 1), 2, 3).sub(&Radical::rational(q(2, 1), 3));
        assert_eq!(y.sign(&r), Ordering::Equal);
        // (√2 + √3)² = 5 + 2√6: equal to its expansion.
        let s = Radical::root(q(1, 1), 0, 3).add(&Radical::root(q(1, 1), 1, 3));
        let sq = s.mul(&s, &r);
        let mut want = Radical::rational(q(5, 1), 3);
        want.c[0b011] = q(2, 1);
        assert_eq!(sq.sub(&want).sign(&r), Ordering::Equal);
        // √2·√3 − √6 in a tower holding 6 as a third radicand: exactly zero.
        let r6 = vec![q(2, 1), q(3, 1), q(6, 1)];
        let z = Radical::root(q(1, 1), 0, 3)
            .mul(&Radical::root(q(1, 1), 1, 3), &r6)
            .sub(&Radical::root(q(1, 1), 2, 3));
        assert_eq!(z.sign(&r6), Ordering::Equal);
    }

    #[test]
    fn a_value_of_exactly_one_is_level_255() {
        let v = Vec3::new(q(1, 1), q(0, 1), q(1, 1));
        for valued in [
            Valued::Phong,
            Valued::Gouraud,
            Valued::Euler,
            Valued::CorrectedEuler,
        ] {
            // An approximation just below 1 whose interval straddles the boundary.
            let approx = vec![q(1, 1) - q(1, 1 << 40); 2];
            let levels = normalized_levels(
                |_| Some(valued),
                (&v, &v, &v),
                1,
                &q(1, 1),
                &approx,
                &q(1, 1 << 30),
            );
            assert_eq!(levels, vec![Some(255), Some(255)], "{valued:?}");
        }
    }

    #[test]
    fn the_symmetric_middle_pixel_is_exactly_one() {
        // N_a = (1, 0, 1)/√2, N_b = (−1, 0, 1)/√2, L = (0, 0, 1), n = 2: the middle
        // normal is parallel to L, so Phong's value there is exactly 1; Gouraud's is
        // 1/√2 (level 180: 180.3…).
        let (na, nb, l) = (
            Vec3::new(q(1, 1), q(0, 1), q(1, 1)),
            Vec3::new(q(-1, 1), q(0, 1), q(1, 1)),
            Vec3::new(q(0, 1), q(0, 1), q(3, 1)),
        );
        let phong = normalized_levels(
            |_| Some(Valued::Phong),
            (&na, &nb, &l),
            2,
            &q(1, 1),
            &[],
            &q(1, 1),
        );
        assert_eq!(phong, vec![Some(180), Some(255), Some(180)]);
        let g = normalized_levels(
            |_| Some(Valued::Gouraud),
            (&na, &nb, &l),
            2,
            &q(1, 1),
            &[],
            &q(1, 1),
        );
        assert_eq!(g, vec![Some(180), Some(180), Some(180)]);
        // K_d = 1/2 halves every value: Phong's middle is exactly 1/2, level 127.
        let half = normalized_levels(
            |_| Some(Valued::Phong),
            (&na, &nb, &l),
            2,
            &q(1, 2),
            &[],
            &q(1, 1),
        );
        assert_eq!(half[1], Some(127));
    }
}
