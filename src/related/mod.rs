//! The methods of the paper's introduction and related work, on the same footing as the
//! paper's own: generic over [`crate::Scalar`] / [`crate::Real`], tested against the
//! exact reference (`tests/related.rs`), compared on the torus harness
//! (`studies::compare`, feature `harness`; `docs/comparison.md`).
//!
//! | method | module | level | reconstructed? |
//! |---|---|---|---|
//! | Bishop & Weimer's Taylor-series fast Phong | [`bishop_weimer`] | polygon (and span) | the specular table only |
//! | Seiler's six-point quadratic | [`seiler`] | triangle | yes: the Lagrange form |
//! | Kuijk & Blake's angular (spherical) interpolation | [`spherical`] | span | yes: along one span |
//! | Mortensen's vertex angles with a byte table | [`vertex_angle`] | polygon | no (the second source) |
//! | Ouyang & Maynard's binary interpolation | [`binary`] | span | yes: the halving factors |
//!
//! The polygon set-up they share (barycentric forms, the affine normal field) lives in
//! [`triangle`]; the power look-up of the specular term in [`power`].

pub mod binary;
pub mod bishop_weimer;
pub mod power;
pub mod seiler;
pub mod spherical;
pub mod triangle;
pub mod vertex_angle;
