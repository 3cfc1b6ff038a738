//! Why a [`super::Request`] cannot be run, as data: the field it is about, what is
//! wrong, and what else the caller may do. The library names no command-line flag:
//! `phong-approx span` turns each [`Field`] and [`Remedy`] into its own flags.

use std::fmt;

/// The part of a [`super::Request`] an error is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Field {
    /// `N_a`, the normal at the span's start.
    Na,
    /// `N_b`, the normal at its end.
    Nb,
    /// `L`, the light direction.
    Light,
    /// `n`, the number of steps.
    Steps,
    /// The size of angular interpolation's cosine table.
    TableSize,
    /// The significant digits asked for.
    Digits,
    /// The number type ([`super::Arithmetic`]).
    Arithmetic,
    /// The span as a whole (none of its fields alone).
    Span,
}

impl Field {
    /// Its name as the paper and [`super::Request`] write it.
    pub fn name(self) -> &'static str {
        match self {
            Field::Na => "N_a",
            Field::Nb => "N_b",
            Field::Light => "L",
            Field::Steps => "n",
            Field::TableSize => "the table size",
            Field::Digits => "the digits",
            Field::Arithmetic => "the number type",
            Field::Span => "the span",
        }
    }
}

impl From<crate::Input> for Field {
    fn from(i: crate::Input) -> Field {
        match i {
            crate::Input::Na => Field::Na,
            crate::Input::Nb => Field::Nb,
            crate::Input::L => Field::Light,
        }
    }
}

impl fmt::Display for Field {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// What the caller may do besides changing the [`Field`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Remedy {
    /// Nothing but changing the field.
    None,
    /// Run anyway: the request is within reach, only over a work or output budget
    /// ([`super::SPAN_BUDGET`], [`super::OUTPUT_BUDGET`]).
    RunAnyway,
    /// Normalize the inputs first ([`super::Request::normalize`]).
    Normalize,
    /// Build with the `mpfr` feature (needs m4 and a C compiler).
    BuildWithMpfr,
}

/// A request that cannot be run: the field it is about, why (one line, naming no
/// command-line flag) and what else may be done.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{field}: {message}")]
pub struct ReportError {
    /// The field it is about.
    pub field: Field,
    /// What is wrong with it.
    pub message: String,
    /// What else the caller may do.
    pub remedy: Remedy,
}

impl ReportError {
    /// An error about `field` with no remedy but changing it.
    pub(super) fn new(field: Field, message: impl fmt::Display) -> Self {
        ReportError {
            field,
            message: message.to_string(),
            remedy: Remedy::None,
        }
    }

    /// The same error with a remedy.
    pub(super) fn or(mut self, remedy: Remedy) -> Self {
        self.remedy = remedy;
        self
    }
}
