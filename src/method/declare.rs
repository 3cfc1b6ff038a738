//! The macro that turns the one list of methods (`list.rs`) into the
//! [`Method`](super::Method) enum, [`Method::ALL`](super::Method::ALL), the dispatch of
//! [`Method::run`](super::Method::run) and [`Method::run_field`](super::Method::run_field),
//! and the catalogue rows of [`Method::info`](super::Method::info) — libm-test's `for_each_function!` pattern, so
//! that a method is added in one place and the compiler asks for every fact of it.
//!
//! Each row of the list reads
//!
//! ```text
//! /// doc of the variant
//! Variant(binding: type = value in ALL) {
//!     run: field | real |span, parameter, out| body,
//!     info: { name: …, label: …, … },
//! }
//! ```
//!
//! - The optional field (`AngularTable(size: u32 = SOURCE_TABLE)`) is bound by that
//!   name in `body` and in the `info` row; [`Method::ALL`](super::Method::ALL) holds the variant with the
//!   value after `=`.
//! - `field` methods run on field operations only: their `parameter` is `K_d`
//!   ([`Prepared::kd`](super::Prepared::kd)) and `body` is generic over
//!   [`Scalar`](crate::Scalar), so [`Method::run_field`](super::Method::run_field) runs them in any field;
//!   `real` methods get the [`Prepared`](super::Prepared) parameters and need
//!   [`Real`](crate::Real). The row's [`Info::needs`](super::Info::needs) is this word,
//!   not a second statement of it.
//! - `body` is the method's run, of type `Result<Option<Decision<T>>, SpanError>`
//!   (the adaptive method's decision, `None` for the others).
//! - `info` names every field of [`Info`](super::Info) but `needs`: leaving one out
//!   does not compile.

/// Generates the enum, its list, its dispatch and its catalogue rows from the list of
/// `list.rs` (the module documentation says how a row reads).
macro_rules! methods {
    ($(
        $(#[$doc:meta])*
        $variant:ident $(($arg:ident : $arg_ty:ty = $all:expr))? {
            run: $kind:ident |$span:ident, $param:ident, $out:ident| $body:expr,
            info: { $($field:ident : $value:expr),* $(,)? } $(,)?
        }
    )*) => {
        /// One way of shading a span (the list: `src/method/list.rs`).
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum Method {
            $( $(#[$doc])* $variant $(($arg_ty))?, )*
        }

        /// How many methods the list declares.
        const COUNT: usize = [$(stringify!($variant)),*].len();

        impl Method {
            /// Every method, in the order of the tables; the tabled angular method
            /// with the second source's 256 entries.
            pub const ALL: [Method; COUNT] = [$( Method::$variant $(($all))?, )*];

            /// The catalogue entry.
            pub fn info(&self) -> Info {
                match self {
                    $( Method::$variant $(($arg))? => Info {
                        needs: methods!(@needs $kind),
                        $($field: $value,)*
                    }, )*
                }
            }

            /// [`Method::run`] before the finiteness check.
            pub(super) fn dispatch<T: Real>(
                &self,
                span: &Span<T>,
                prep: &Prepared<T>,
                out: &mut [T],
            ) -> Result<Option<Decision<T>>, SpanError> {
                match self {
                    $( Method::$variant $(($arg))? => {
                        methods!(@real $kind, self, span, prep, out, |$span, $param, $out| $body)
                    } )*
                }
            }

            /// [`Method::run_field`] before the finiteness check. (A method's field,
            /// as the tabled angular method's size, is bound but unused in the arm of
            /// a method that needs more than a field.)
            #[allow(unused_variables)]
            pub(super) fn dispatch_field<T: Scalar>(
                &self,
                span: &Span<T>,
                kd: &T,
                out: &mut [T],
            ) -> Result<Option<Decision<T>>, SpanError> {
                match self {
                    $( Method::$variant $(($arg))? => {
                        methods!(@field $kind, self, span, kd, out, |$span, $param, $out| $body)
                    } )*
                }
            }
        }
    };
    (@needs field) => { Needs::Field };
    (@needs real) => { Needs::Real };
    // A field method run from `run`: through `dispatch_field`, with `K_d`.
    (@real field, $m:ident, $s:ident, $p:ident, $o:ident, |$span:ident, $param:ident, $out:ident| $body:expr) => {
        $m.dispatch_field($s, &$p.kd, $o)
    };
    (@real real, $m:ident, $s:ident, $p:ident, $o:ident, |$span:ident, $param:ident, $out:ident| $body:expr) => {{
        let ($span, $param, $out) = ($s, $p, $o);
        $body
    }};
    (@field field, $m:ident, $s:ident, $k:ident, $o:ident, |$span:ident, $param:ident, $out:ident| $body:expr) => {{
        let ($span, $param, $out) = ($s, $k, $o);
        $body
    }};
    (@field real, $m:ident, $s:ident, $k:ident, $o:ident, |$span:ident, $param:ident, $out:ident| $body:expr) => {
        Err(SpanError::Parameter(format!(
            "{} needs square roots or trigonometry, not only field operations",
            $m.name()
        )))
    };
}
