//! The form of a method an implementation declares (`check --form`,
//! `testkit::Suite::form`), which narrows the theorems its bound is taken from.

use super::Proved;
use std::fmt;
use std::str::FromStr;

/// The form of a method an implementation declares (`check --form`,
/// `testkit::Suite::form`): the profile's bound then covers that form alone and is
/// the largest of that form's theorems only. A closed form's error does not grow with
/// `n` and a recurrence's does, so the bound `check` applies to an undeclared
/// implementation — the largest over every form — is the recurrence's at large `n`:
/// at `n = 4095` corrected Euler's closed form is judged by `(2.2·n + 51.21)·u =
/// 9060·u` under `ieee`, and by its own theorem's `59.61·u` once declared
/// (`docs/float.md` §18.6). Only Euler and corrected Euler have theorems for both
/// forms ([`Form::applies_to`]); for the other methods only [`Form::Any`] is accepted.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Form {
    /// Any form the profile covers: the largest of their bounds (the default).
    #[default]
    Any,
    /// The recurrence, the paper's loop: `p += t; t += ds` (corrected Euler, eqs.
    /// 15–20) or `E += s; s += ds` (Euler, eqs. 12–14).
    Recurrence,
    /// The closed form in `i`, no loop-carried sum: `p_a + i·(t_0 + (i − 1)/2·ds)`
    /// (corrected Euler) or `p_a + i·(di_a + (i − 1)/2·ds)` (Euler).
    Closed,
}

impl Form {
    /// Every form, `Any` first.
    pub const ALL: [Form; 3] = [Form::Any, Form::Recurrence, Form::Closed];

    /// The form's name as `--form` takes it.
    pub fn name(self) -> &'static str {
        match self {
            Form::Any => "any",
            Form::Recurrence => "recurrence",
            Form::Closed => "closed",
        }
    }

    /// Whether a profile's theorems tell `method`'s forms apart: its theorems
    /// ([`super::proved`], `ieee` binary32) include a recurrence's, whose bound grows
    /// with `n`, and a closed form's, whose bound does not — Euler and corrected Euler.
    /// A declared form other than [`Form::Any`] is refused for the other methods.
    pub fn applies_to(method: crate::Method) -> bool {
        super::proved(method, super::Profile::Ieee, crate::Format::Binary32).is_some_and(|forms| {
            forms.iter().any(|p| Form::Recurrence.covers(p))
                && forms.iter().any(|p| Form::Closed.covers(p))
        })
    }

    /// Whether a theorem is of this form, as its catalogue row states
    /// ([`Proved::closed`]).
    pub(super) fn covers(self, p: &Proved) -> bool {
        match self {
            Form::Any => true,
            Form::Recurrence => !p.closed,
            Form::Closed => p.closed,
        }
    }
}

impl fmt::Display for Form {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A `--form` that is not one of [`Form::ALL`]'s names.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown form {0:?}: expected any, recurrence or closed")]
pub struct UnknownForm(pub String);

impl FromStr for Form {
    type Err = UnknownForm;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Form::ALL
            .into_iter()
            .find(|f| f.name() == s)
            .ok_or_else(|| UnknownForm(s.to_string()))
    }
}
