//! Fixed-length arrays of the case file read with their length checked.
//!
//! serde reads a `[f64; 3]` by taking three elements and ignoring the rest, so
//! `origin = [0, 0, 0, 1]` would lose its fourth number without a word. Every point,
//! direction and pair of the format goes through [`exact`] (or its `Option` and list
//! forms), which refuses any other length; the error carries the value's span, so it
//! names the line, table and key like every other parse error.

use serde::de::{Deserialize, Deserializer, Error, SeqAccess, Visitor};
use std::fmt;
use std::marker::PhantomData;

/// `[T; N]`, refusing a TOML array of any other length.
struct Exact<T, const N: usize>([T; N]);

struct ExactVisitor<T, const N: usize>(PhantomData<T>);

impl<'de, T: Deserialize<'de>, const N: usize> Visitor<'de> for ExactVisitor<T, N> {
    type Value = Exact<T, N>;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        match N {
            3 => write!(f, "an array of 3 numbers [x, y, z]"),
            _ => write!(f, "an array of {N} numbers"),
        }
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
        let mut items = Vec::with_capacity(N);
        while let Some(item) = seq.next_element::<T>()? {
            items.push(item);
            if items.len() > N {
                // Count the rest for the message, without keeping them.
                let mut len = items.len();
                while seq.next_element::<serde::de::IgnoredAny>()?.is_some() {
                    len += 1;
                }
                return Err(A::Error::invalid_length(len, &self));
            }
        }
        let len = items.len();
        items.try_into().map(Exact).map_err(|_| A::Error::invalid_length(len, &self))
    }
}

impl<'de, T: Deserialize<'de>, const N: usize> Deserialize<'de> for Exact<T, N> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_seq(ExactVisitor(PhantomData))
    }
}

/// A `[T; N]` key (`#[serde(deserialize_with = "exact")]`).
pub fn exact<'de, D: Deserializer<'de>, T: Deserialize<'de>, const N: usize>(d: D) -> Result<[T; N], D::Error> {
    Exact::deserialize(d).map(|e| e.0)
}

/// An optional `[T; N]` key (with `#[serde(default)]`).
pub fn exact_opt<'de, D: Deserializer<'de>, T: Deserialize<'de>, const N: usize>(
    d: D,
) -> Result<Option<[T; N]>, D::Error> {
    Option::<Exact<T, N>>::deserialize(d).map(|o| o.map(|e| e.0))
}

/// An optional list of `[T; N]` (with `#[serde(default)]`), e.g. a polygon's `vertices`.
pub fn exact_list<'de, D: Deserializer<'de>, T: Deserialize<'de>, const N: usize>(
    d: D,
) -> Result<Option<Vec<[T; N]>>, D::Error> {
    Option::<Vec<Exact<T, N>>>::deserialize(d).map(|o| o.map(|v| v.into_iter().map(|e| e.0).collect()))
}
