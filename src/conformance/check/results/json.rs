//! Streaming JSON results: `{"cases": [{"id": …, "values": […]}, …]}` read with
//! serde's seeds, so that each case's values go straight into a [`Reading`] of the
//! size its vector-file case needs and reading stops at the first value too many.

use super::Reading;
use crate::error::shown;
use serde::de::{self, DeserializeSeed, IgnoredAny, MapAccess, SeqAccess, Visitor};
use std::cell::RefCell;
use std::collections::HashMap;
use std::fmt;

/// What the reader knows and has read. `problem` holds the message of the first
/// problem found (serde's error then only carries the line).
pub(super) struct Ctx<'a> {
    pub need: &'a HashMap<&'a str, usize>,
    pub longest: usize,
    pub got: RefCell<HashMap<String, Reading>>,
    pub problem: RefCell<Option<String>>,
}

impl Ctx<'_> {
    fn fail<E: de::Error>(&self, message: String) -> E {
        let e = E::custom(&message);
        self.problem.borrow_mut().get_or_insert(message);
        e
    }
}

/// The whole file.
pub(super) struct File<'c, 'a>(pub &'c Ctx<'a>);
impl<'de> DeserializeSeed<'de> for File<'_, '_> {
    type Value = ();
    fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
        d.deserialize_map(self)
    }
}
impl<'de> Visitor<'de> for File<'_, '_> {
    type Value = ();
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(r#"an object {"cases": [...]}"#)
    }
    fn visit_map<A: MapAccess<'de>>(self, mut m: A) -> Result<(), A::Error> {
        let mut cases = false;
        while let Some(k) = m.next_key::<std::borrow::Cow<'de, str>>()? {
            if k == "cases" {
                if cases {
                    return Err(self.0.fail("the key \"cases\" appears twice".into()));
                }
                cases = true;
                m.next_value_seed(Cases(self.0))?;
            } else {
                m.next_value::<IgnoredAny>()?;
            }
        }
        if !cases {
            return Err(self.0.fail("no \"cases\" array".into()));
        }
        Ok(())
    }
}

struct Cases<'c, 'a>(&'c Ctx<'a>);
impl<'de> DeserializeSeed<'de> for Cases<'_, '_> {
    type Value = ();
    fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
        d.deserialize_seq(self)
    }
}
impl<'de> Visitor<'de> for Cases<'_, '_> {
    type Value = ();
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("an array of cases")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut s: A) -> Result<(), A::Error> {
        let mut k = 0usize;
        while s.next_element_seed(OneCase { ctx: self.0, k })?.is_some() {
            k += 1;
        }
        Ok(())
    }
}

struct OneCase<'c, 'a> {
    ctx: &'c Ctx<'a>,
    k: usize,
}
impl<'de> DeserializeSeed<'de> for OneCase<'_, '_> {
    type Value = ();
    fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
        d.deserialize_map(self)
    }
}
impl<'de> Visitor<'de> for OneCase<'_, '_> {
    type Value = ();
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(r#"a case {"id": ..., "values": [...]}"#)
    }
    fn visit_map<A: MapAccess<'de>>(self, mut m: A) -> Result<(), A::Error> {
        let ctx = self.ctx;
        let at = format!("cases[{}]", self.k);
        let mut id: Option<String> = None;
        let mut values: Option<(Vec<f64>, usize)> = None;
        while let Some(key) = m.next_key::<std::borrow::Cow<'de, str>>()? {
            match key.as_ref() {
                "id" if id.is_some() => return Err(ctx.fail(format!("{at}: \"id\" appears twice"))),
                "id" => {
                    let s: std::borrow::Cow<'de, str> = m.next_value()?;
                    if !ctx.need.contains_key(s.as_ref()) {
                        return Err(
                            ctx.fail(format!("{at}: unknown case id '{}'", shown(s.as_ref())))
                        );
                    }
                    if ctx.got.borrow().contains_key(s.as_ref()) {
                        return Err(
                            ctx.fail(format!("{at}: duplicate case id '{}'", shown(s.as_ref())))
                        );
                    }
                    id = Some(s.into_owned());
                }
                "values" if values.is_some() => {
                    return Err(ctx.fail(format!("{at}: \"values\" appears twice")))
                }
                "values" => {
                    // The id may come first (then its size is known) or after.
                    let cap = id.as_deref().map_or(ctx.longest, |i| ctx.need[i]);
                    values = Some(m.next_value_seed(Values {
                        ctx,
                        at: &at,
                        id: id.as_deref(),
                        cap,
                    })?);
                }
                _ => {
                    m.next_value::<IgnoredAny>()?;
                }
            }
        }
        let Some(id) = id else {
            return Err(ctx.fail(format!("{at}: the case has no \"id\"")));
        };
        let Some((vals, count)) = values else {
            return Err(ctx.fail(format!("{at}: case {id} has no \"values\"")));
        };
        let len = ctx.need[id.as_str()];
        if count != len {
            return Err(ctx.fail(format!(
                "{at}: case {id} needs {len} values, found {}",
                if count > len {
                    format!("more ({count} or more)")
                } else {
                    count.to_string()
                }
            )));
        }
        let mut r = Reading::new(0);
        r.lines = vec![1; len];
        r.values = vals;
        ctx.got.borrow_mut().insert(id, r);
        Ok(())
    }
}

/// A case's values: at most `cap` of them are kept; one more stops the reading.
struct Values<'c, 'a, 's> {
    ctx: &'c Ctx<'a>,
    at: &'s str,
    id: Option<&'s str>,
    cap: usize,
}
impl<'de> DeserializeSeed<'de> for Values<'_, '_, '_> {
    type Value = (Vec<f64>, usize);
    fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<(Vec<f64>, usize), D::Error> {
        d.deserialize_seq(self)
    }
}
impl<'de> Visitor<'de> for Values<'_, '_, '_> {
    type Value = (Vec<f64>, usize);
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("an array of numbers")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut s: A) -> Result<(Vec<f64>, usize), A::Error> {
        let who = match self.id {
            Some(id) => format!("case {id}"),
            None => "the case".to_string(),
        };
        let mut out = Vec::with_capacity(self.cap.min(1 << 16));
        loop {
            let i = out.len();
            let Some(x) = s.next_element_seed(Number)? else {
                break;
            };
            // "NaN" or "inf" as a string is a result (a failing pixel), not an
            // error of the file.
            let Some(x) = x else {
                return Err(self
                    .ctx
                    .fail(format!("{}: value {i} of {who} is not a number", self.at)));
            };
            if i == self.cap {
                return Err(self.ctx.fail(format!(
                    "{}: {who} has more than {} values",
                    self.at, self.cap
                )));
            }
            out.push(x);
        }
        let n = out.len();
        Ok((out, n))
    }
}

/// One value: a number, or a string holding one; `None` for anything else.
struct Number;
impl<'de> DeserializeSeed<'de> for Number {
    type Value = Option<f64>;
    fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<Option<f64>, D::Error> {
        d.deserialize_any(self)
    }
}
impl<'de> Visitor<'de> for Number {
    type Value = Option<f64>;
    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a number")
    }
    fn visit_f64<E>(self, v: f64) -> Result<Option<f64>, E> {
        Ok(Some(v))
    }
    fn visit_i64<E>(self, v: i64) -> Result<Option<f64>, E> {
        Ok(Some(v as f64))
    }
    fn visit_u64<E>(self, v: u64) -> Result<Option<f64>, E> {
        Ok(Some(v as f64))
    }
    fn visit_str<E>(self, v: &str) -> Result<Option<f64>, E> {
        // A string that reads as 0 but is not zero (below f64's range) is no value.
        Ok(v.trim()
            .parse::<f64>()
            .ok()
            .filter(|x| !super::underflows(v.trim(), *x)))
    }
    fn visit_bool<E>(self, _: bool) -> Result<Option<f64>, E> {
        Ok(None)
    }
    fn visit_unit<E>(self) -> Result<Option<f64>, E> {
        Ok(None)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut s: A) -> Result<Option<f64>, A::Error> {
        while s.next_element::<IgnoredAny>()?.is_some() {}
        Ok(None)
    }
    fn visit_map<A: MapAccess<'de>>(self, mut m: A) -> Result<Option<f64>, A::Error> {
        while m.next_entry::<IgnoredAny, IgnoredAny>()?.is_some() {}
        Ok(None)
    }
}
