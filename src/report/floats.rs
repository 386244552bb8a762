//! Plot series in report.json: every f64 inside a series is written as a [`Num`] (ten
//! significant digits, `null` when not finite) and read back as one (`null` as NaN), whatever the
//! shape of the series (vectors, pairs, labelled curves). Use `#[serde(with = "floats")]`.
//!
//! ```
//! use gearloss::report::floats::Floats;
//! let curve = vec![("μ".to_string(), vec![0.1234567890123, f64::NAN])];
//! let written = serde_json::to_string(&curve.write()).unwrap();
//! assert_eq!(written, r#"[["μ",[0.123456789,null]]]"#);
//! ```

use serde::de::DeserializeOwned;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use super::number::Num;

/// A value whose f64s are written as [`Num`]s.
pub trait Floats: Sized {
    type Written: Serialize + DeserializeOwned;
    fn write(&self) -> Self::Written;
    fn read(w: Self::Written) -> Self;
}

impl Floats for f64 {
    type Written = Num;
    fn write(&self) -> Num {
        Num(*self)
    }
    fn read(w: Num) -> f64 {
        w.0
    }
}

macro_rules! as_is {
    ($($t:ty),*) => {$(
        impl Floats for $t {
            type Written = $t;
            fn write(&self) -> $t {
                self.clone()
            }
            fn read(w: $t) -> $t {
                w
            }
        }
    )*};
}
as_is!(String, usize);

impl<T: Floats> Floats for Vec<T> {
    type Written = Vec<T::Written>;
    fn write(&self) -> Self::Written {
        self.iter().map(Floats::write).collect()
    }
    fn read(w: Self::Written) -> Self {
        w.into_iter().map(T::read).collect()
    }
}

impl<T: Floats> Floats for Option<T> {
    type Written = Option<T::Written>;
    fn write(&self) -> Self::Written {
        self.as_ref().map(Floats::write)
    }
    fn read(w: Self::Written) -> Self {
        w.map(T::read)
    }
}

impl<T: Floats, const N: usize> Floats for [T; N]
where
    [T::Written; N]: Serialize + DeserializeOwned,
{
    type Written = [T::Written; N];
    fn write(&self) -> Self::Written {
        std::array::from_fn(|i| self[i].write())
    }
    fn read(w: Self::Written) -> Self {
        w.map(T::read)
    }
}

impl<A: Floats, B: Floats> Floats for (A, B) {
    type Written = (A::Written, B::Written);
    fn write(&self) -> Self::Written {
        (self.0.write(), self.1.write())
    }
    fn read(w: Self::Written) -> Self {
        (A::read(w.0), B::read(w.1))
    }
}

impl<A: Floats, B: Floats, C: Floats> Floats for (A, B, C) {
    type Written = (A::Written, B::Written, C::Written);
    fn write(&self) -> Self::Written {
        (self.0.write(), self.1.write(), self.2.write())
    }
    fn read(w: Self::Written) -> Self {
        (A::read(w.0), B::read(w.1), C::read(w.2))
    }
}

impl<A: Floats, B: Floats, C: Floats, D: Floats, E: Floats> Floats for (A, B, C, D, E) {
    type Written = (A::Written, B::Written, C::Written, D::Written, E::Written);
    fn write(&self) -> Self::Written {
        (self.0.write(), self.1.write(), self.2.write(), self.3.write(), self.4.write())
    }
    fn read(w: Self::Written) -> Self {
        (A::read(w.0), B::read(w.1), C::read(w.2), D::read(w.3), E::read(w.4))
    }
}

/// `#[serde(with = "floats")]`: writes the value's f64s as [`Num`]s.
pub fn serialize<T: Floats, S: Serializer>(x: &T, s: S) -> Result<S::Ok, S::Error> {
    x.write().serialize(s)
}

/// `#[serde(with = "floats")]`: reads them back (`null` as NaN).
pub fn deserialize<'de, T: Floats, D: Deserializer<'de>>(d: D) -> Result<T, D::Error> {
    Ok(T::read(T::Written::deserialize(d)?))
}

/// Reads a series written as plain numbers, a value that was not finite written as `null` (serde_json
/// writes NaN so), back with NaN in its place: a report whose series holds such a value (flagged
/// in its findings) still reads back. Use `#[serde(deserialize_with = "floats::nan_from_null")]`.
pub fn nan_from_null<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<f64>, D::Error> {
    let read: Vec<Option<f64>> = Deserialize::deserialize(d)?;
    Ok(read.into_iter().map(|x| x.unwrap_or(f64::NAN)).collect())
}
