//! The wire read back: a value in its wire form ([`Wire`]) deserialized into its type.
//!
//! The reader is generic, as the page's (`www/wire.js` `readWire`): the JSON is read as it is and
//! each `{"$f64": [at, len]}` or `{"$u8": [at, len]}` becomes the slice of the buffer it points at,
//! so a type that derives `Deserialize` reads its own wire form back with every number as it was
//! (NaN and infinities in a marked array included). A non-finite number outside a buffer crossed as
//! `null`, so a type that must keep one marks its array ([`crate::wire::f64s`]).

use crate::wire::{F64s, U8s, Wire, WireError};
use alloc::vec::Vec;
use serde::de::value::{MapDeserializer, SeqDeserializer, StrDeserializer};
use serde::de::{self, DeserializeOwned, DeserializeSeed, IntoDeserializer, Visitor};
use serde::{Deserialize, Deserializer, forward_to_deserialize_any};
use serde_json::Value;

impl de::Error for WireError {
    fn custom<T: core::fmt::Display>(msg: T) -> Self {
        <WireError as serde::ser::Error>::custom(msg)
    }
}

/// Reads `wire` back into a `T` (the inverse of [`crate::wire::to_wire`] for a type that derives
/// both); errors name what does not fit.
pub fn from_wire<T: DeserializeOwned>(wire: &Wire) -> Result<T, WireError> {
    let tree: Value = serde_json::from_str(&wire.json).map_err(de::Error::custom)?;
    T::deserialize(Node { v: &tree, wire })
}

impl<'de> Deserialize<'de> for F64s {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        Vec::deserialize(d).map(F64s)
    }
}

impl<'de> Deserialize<'de> for U8s {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        Vec::deserialize(d).map(U8s)
    }
}

/// A node of the wire's JSON, with the buffers its references point into.
#[derive(Clone, Copy)]
struct Node<'a> {
    v: &'a Value,
    wire: &'a Wire,
}

/// A marked array: the slice a `{"$f64": [at, len]}` or `{"$u8": [at, len]}` points at.
enum Marked<'a> {
    F64(&'a [f64]),
    U8(&'a [u8]),
}

impl<'a> Node<'a> {
    fn at(&self, v: &'a Value) -> Node<'a> {
        Node { v, wire: self.wire }
    }

    fn marked(&self) -> Result<Option<Marked<'a>>, WireError> {
        let Value::Object(m) = self.v else {
            return Ok(None);
        };
        let Some((key, range)) = m.iter().next().filter(|_| m.len() == 1) else {
            return Ok(None);
        };
        if key != "$f64" && key != "$u8" {
            return Ok(None);
        }
        let bad = || de::Error::custom(format_args!("{key}: not a reference [at, len]"));
        let pair = range.as_array().filter(|a| a.len() == 2).ok_or_else(bad)?;
        let (at, len) = match (pair[0].as_u64(), pair[1].as_u64()) {
            (Some(at), Some(len)) => (at as usize, len as usize),
            _ => return Err(bad()),
        };
        let span = at..at.saturating_add(len);
        let beyond = || de::Error::custom(format_args!("{key}: [{at}, {len}] beyond its buffer"));
        Ok(Some(if key == "$f64" {
            Marked::F64(self.wire.numbers.get(span).ok_or_else(beyond)?)
        } else {
            Marked::U8(self.wire.codes.get(span).ok_or_else(beyond)?)
        }))
    }
}

impl<'de> IntoDeserializer<'de, WireError> for Node<'_> {
    type Deserializer = Self;
    fn into_deserializer(self) -> Self {
        self
    }
}

impl<'de> de::Deserializer<'de> for Node<'_> {
    type Error = WireError;

    fn deserialize_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, WireError> {
        match self.marked()? {
            Some(Marked::F64(s)) => return seq(visitor, s.iter().copied()),
            Some(Marked::U8(s)) => return seq(visitor, s.iter().copied()),
            None => {}
        }
        match self.v {
            Value::Null => visitor.visit_unit(),
            Value::Bool(b) => visitor.visit_bool(*b),
            Value::Number(n) => match (n.as_u64(), n.as_i64(), n.as_f64()) {
                (Some(u), _, _) => visitor.visit_u64(u),
                (None, Some(i), _) => visitor.visit_i64(i),
                (None, None, x) => visitor.visit_f64(x.unwrap_or(f64::NAN)),
            },
            Value::String(s) => visitor.visit_str(s),
            Value::Array(a) => seq(visitor, a.iter().map(|v| self.at(v))),
            Value::Object(m) => {
                let mut map = MapDeserializer::new(m.iter().map(|(k, v)| (k.as_str(), self.at(v))));
                let value = visitor.visit_map(&mut map)?;
                map.end()?;
                Ok(value)
            }
        }
    }

    fn deserialize_option<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, WireError> {
        match self.v {
            Value::Null => visitor.visit_none(),
            _ => visitor.visit_some(self),
        }
    }

    fn deserialize_newtype_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        visitor: V,
    ) -> Result<V::Value, WireError> {
        visitor.visit_newtype_struct(self)
    }

    fn deserialize_enum<V: Visitor<'de>>(
        self,
        _name: &'static str,
        _variants: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, WireError> {
        match self.v {
            Value::String(s) => visitor.visit_enum(StrDeserializer::<WireError>::new(s)),
            Value::Object(m) if m.len() == 1 => match m.iter().next() {
                Some((name, v)) => visitor.visit_enum(Variant {
                    name,
                    value: self.at(v),
                }),
                None => Err(de::Error::custom("an enum without its variant")),
            },
            _ => Err(de::Error::custom("an enum is a name or {name: value}")),
        }
    }

    forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string
        bytes byte_buf unit unit_struct seq tuple tuple_struct map struct identifier ignored_any
    }
}

fn seq<'de, V: Visitor<'de>, I>(visitor: V, items: I) -> Result<V::Value, WireError>
where
    I: Iterator,
    I::Item: IntoDeserializer<'de, WireError>,
{
    let mut s = SeqDeserializer::new(items);
    let value = visitor.visit_seq(&mut s)?;
    s.end()?;
    Ok(value)
}

/// An enum written as `{variant: value}`.
struct Variant<'a> {
    name: &'a str,
    value: Node<'a>,
}

impl<'de, 'a> de::EnumAccess<'de> for Variant<'a> {
    type Error = WireError;
    type Variant = Node<'a>;
    fn variant_seed<S: DeserializeSeed<'de>>(
        self,
        seed: S,
    ) -> Result<(S::Value, Node<'a>), WireError> {
        let name = seed.deserialize(StrDeserializer::<WireError>::new(self.name))?;
        Ok((name, self.value))
    }
}

impl<'de> de::VariantAccess<'de> for Node<'_> {
    type Error = WireError;
    fn unit_variant(self) -> Result<(), WireError> {
        Ok(())
    }
    fn newtype_variant_seed<S: DeserializeSeed<'de>>(self, seed: S) -> Result<S::Value, WireError> {
        seed.deserialize(self)
    }
    fn tuple_variant<V: Visitor<'de>>(
        self,
        _len: usize,
        visitor: V,
    ) -> Result<V::Value, WireError> {
        de::Deserializer::deserialize_any(self, visitor)
    }
    fn struct_variant<V: Visitor<'de>>(
        self,
        _fields: &'static [&'static str],
        visitor: V,
    ) -> Result<V::Value, WireError> {
        de::Deserializer::deserialize_any(self, visitor)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wire::{f64s, to_wire, u8s};
    use alloc::string::{String, ToString};
    use alloc::vec;
    use serde::Serialize;

    #[derive(Debug, PartialEq, Serialize, Deserialize)]
    enum Shape {
        Dot,
        Line(F64sEq),
        Pair(u32, String),
        Box { side: f64, codes: U8sEq },
    }

    /// [`F64s`] compared bit for bit (NaN equals NaN).
    #[derive(Debug, Serialize, Deserialize)]
    struct F64sEq(#[serde(serialize_with = "f64s")] Vec<f64>);
    impl PartialEq for F64sEq {
        fn eq(&self, o: &Self) -> bool {
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            bits(&self.0) == bits(&o.0)
        }
    }

    #[derive(Debug, PartialEq, Serialize, Deserialize)]
    struct U8sEq(#[serde(serialize_with = "u8s")] Vec<u8>);

    #[derive(Debug, PartialEq, Serialize, Deserialize)]
    struct Record {
        shapes: Vec<Shape>,
        first: Option<String>,
        none: Option<usize>,
        at: (usize, i64),
        ratio: f64,
    }

    #[test]
    fn issue_36_a_value_comes_back_from_its_wire_form_bit_for_bit() {
        let r = Record {
            shapes: vec![
                Shape::Dot,
                Shape::Line(F64sEq(vec![0.5, f64::NAN, f64::INFINITY, -0.0, 1e-300])),
                Shape::Pair(7, "g = \"1\"".into()),
                Shape::Box {
                    side: 2.5,
                    codes: U8sEq(vec![0, 255, 3]),
                },
                Shape::Line(F64sEq(vec![])),
            ],
            first: Some("why".into()),
            none: None,
            at: (3, -4),
            ratio: 0.1,
        };
        let w = to_wire(&r).expect("wire");
        // The arrays crossed in the buffers, not the text.
        assert_eq!(w.numbers.len(), 5);
        assert_eq!(w.codes, [0, 255, 3]);
        let back: Record = from_wire(&w).expect("read back");
        assert_eq!(back, r);
        // The sign of a negative zero came back too.
        let Shape::Line(F64sEq(v)) = &back.shapes[1] else {
            unreachable!("the second shape is a line")
        };
        assert!(v[3].is_sign_negative());
    }

    #[test]
    fn issue_36_a_reference_beyond_its_buffer_is_refused_naming_it() {
        let mut w = to_wire(&F64sEq(vec![1.0, 2.0])).expect("wire");
        w.numbers.pop();
        let e = from_wire::<F64sEq>(&w).unwrap_err().to_string();
        assert!(e.contains("$f64: [0, 2] beyond its buffer"), "{e}");
        w.json = r#"{"$u8": [0]}"#.into();
        let e = from_wire::<U8sEq>(&w).unwrap_err().to_string();
        assert!(e.contains("not a reference"), "{e}");
        w.json = "{".into();
        assert!(from_wire::<F64sEq>(&w).is_err());
    }
}
