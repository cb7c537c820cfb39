//! What crosses to the web page: any serde value as one JSON text and two flat buffers.
//!
//! The explorer's types derive `Serialize`; their number arrays are marked with [`f64s`] or
//! [`u8s`] (`#[serde(serialize_with = "wire::f64s")]`). In every ordinary serde form (a JSON file,
//! a test's `serde_json::Value`) a marked array is a plain array. Through [`to_wire`] it is taken
//! out of the text into [`Wire::numbers`] (a `Float64Array` on the page) or [`Wire::codes`] (a
//! `Uint8Array`), and the text holds `{"$f64": [at, len]}` or `{"$u8": [at, len]}` in its place:
//! the numbers cross as they are (NaN in a curve's gaps included, which JSON cannot carry), and the
//! page's reader replaces each reference with a view into the buffer. Everything else is the derived
//! JSON, keys as the types spell them (snake_case); a non-finite number outside a buffer is `null`,
//! as in `serde_json`.

use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec::Vec;
use core::fmt::{self, Write as _};
use serde::ser::{self, Serialize, Serializer};

/// The newtype name that marks an `f64` array for the number buffer.
const F64_TOKEN: &str = "$rime::wire::f64";
/// The newtype name that marks a `u8` array for the code buffer.
const U8_TOKEN: &str = "$rime::wire::u8";

/// Serializes `values` as an `f64` buffer on the wire (a plain array in any other serde form).
pub fn f64s<S: Serializer>(values: &[f64], s: S) -> Result<S::Ok, S::Error> {
    s.serialize_newtype_struct(F64_TOKEN, values)
}

/// Serializes `values` as a `u8` buffer on the wire (a plain array in any other serde form).
pub fn u8s<S: Serializer>(values: &[u8], s: S) -> Result<S::Ok, S::Error> {
    s.serialize_newtype_struct(U8_TOKEN, values)
}

/// An owned `f64` array marked for the number buffer (for a hand-written `Serialize` that builds
/// the array it sends, e.g. a curve's ε_N with NaN in its gaps).
pub struct F64s(pub Vec<f64>);

impl Serialize for F64s {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        f64s(&self.0, s)
    }
}

/// An owned `u8` array marked for the code buffer.
pub struct U8s(pub Vec<u8>);

impl Serialize for U8s {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        u8s(&self.0, s)
    }
}

/// A value as it crosses to the page.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Wire {
    /// The value's JSON, each marked array replaced by a reference into a buffer.
    pub json: String,
    /// Every marked `f64` array, concatenated.
    pub numbers: Vec<f64>,
    /// Every marked `u8` array, concatenated.
    pub codes: Vec<u8>,
}

/// Why a value could not cross (a custom `Serialize` that failed, or a marked array holding
/// something other than numbers).
#[derive(Debug, Clone, PartialEq)]
pub struct WireError(String);

impl fmt::Display for WireError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "wire: {}", self.0)
    }
}

impl ser::StdError for WireError {}

impl ser::Error for WireError {
    fn custom<T: fmt::Display>(msg: T) -> Self {
        WireError(msg.to_string())
    }
}

/// Turns `value` into its wire form.
pub fn to_wire<T: Serialize + ?Sized>(value: &T) -> Result<Wire, WireError> {
    let mut w = Writer::default();
    value.serialize(&mut w)?;
    Ok(w.wire)
}

#[derive(Clone, Copy, PartialEq)]
enum Buffer {
    F64,
    U8,
}

#[derive(Default)]
struct Writer {
    wire: Wire,
    /// Inside a marked array: its numbers go to this buffer, not to the text.
    into: Option<Buffer>,
}

impl Writer {
    fn text(&mut self, s: &str) {
        self.wire.json.push_str(s);
    }
    fn number(&mut self, x: f64) -> Result<(), WireError> {
        match self.into {
            Some(Buffer::F64) => self.wire.numbers.push(x),
            Some(Buffer::U8) => return Err(WireError("a u8 array holds a non-u8 number".into())),
            // `{:?}` is the shortest text that reads back to the same f64, exponent when shorter.
            None if x.is_finite() => {
                let _ = write!(self.wire.json, "{x:?}");
            }
            None => self.text("null"),
        }
        Ok(())
    }
    fn integer(&mut self, x: impl fmt::Display + Copy + TryInto<u8>) -> Result<(), WireError> {
        match self.into {
            Some(Buffer::U8) => {
                let code = x
                    .try_into()
                    .map_err(|_| WireError(format!("{x} is not a u8 code")))?;
                self.wire.codes.push(code);
            }
            Some(Buffer::F64) => return Err(WireError("an f64 array holds an integer".into())),
            None => {
                let _ = write!(self.wire.json, "{x}");
            }
        }
        Ok(())
    }
    fn string(&mut self, s: &str) -> Result<(), WireError> {
        if self.into.is_some() {
            return Err(WireError("a marked array holds a string".into()));
        }
        let out = &mut self.wire.json;
        out.push('"');
        for c in s.chars() {
            match c {
                '"' => out.push_str("\\\""),
                '\\' => out.push_str("\\\\"),
                '\n' => out.push_str("\\n"),
                '\r' => out.push_str("\\r"),
                '\t' => out.push_str("\\t"),
                c if (c as u32) < 0x20 => {
                    let _ = write!(out, "\\u{:04x}", c as u32);
                }
                c => out.push(c),
            }
        }
        out.push('"');
        Ok(())
    }
    fn plain(&self) -> Result<(), WireError> {
        match self.into {
            None => Ok(()),
            Some(_) => Err(WireError("a marked array holds a non-number".into())),
        }
    }
}

/// A sequence or map being written: `first` says whether a comma is due.
struct Compound<'a> {
    w: &'a mut Writer,
    first: bool,
    close: &'static str,
}

impl Compound<'_> {
    fn comma(&mut self) {
        if !self.first && self.w.into.is_none() {
            self.w.text(",");
        }
        self.first = false;
    }
    fn key(&mut self, key: &str) -> Result<(), WireError> {
        self.comma();
        self.w.string(key)?;
        self.w.text(":");
        Ok(())
    }
    fn end(self) -> Result<(), WireError> {
        if self.w.into.is_none() {
            self.w.text(self.close);
        }
        Ok(())
    }
}

impl<'a> Serializer for &'a mut Writer {
    type Ok = ();
    type Error = WireError;
    type SerializeSeq = Compound<'a>;
    type SerializeTuple = Compound<'a>;
    type SerializeTupleStruct = Compound<'a>;
    type SerializeTupleVariant = Compound<'a>;
    type SerializeMap = Compound<'a>;
    type SerializeStruct = Compound<'a>;
    type SerializeStructVariant = Compound<'a>;

    fn serialize_bool(self, v: bool) -> Result<(), WireError> {
        self.plain()?;
        self.text(if v { "true" } else { "false" });
        Ok(())
    }
    fn serialize_i8(self, v: i8) -> Result<(), WireError> {
        self.integer(v)
    }
    fn serialize_i16(self, v: i16) -> Result<(), WireError> {
        self.integer(v)
    }
    fn serialize_i32(self, v: i32) -> Result<(), WireError> {
        self.integer(v)
    }
    fn serialize_i64(self, v: i64) -> Result<(), WireError> {
        self.integer(v)
    }
    fn serialize_u8(self, v: u8) -> Result<(), WireError> {
        self.integer(v)
    }
    fn serialize_u16(self, v: u16) -> Result<(), WireError> {
        self.integer(v)
    }
    fn serialize_u32(self, v: u32) -> Result<(), WireError> {
        self.integer(v)
    }
    fn serialize_u64(self, v: u64) -> Result<(), WireError> {
        self.integer(v)
    }
    fn serialize_f32(self, v: f32) -> Result<(), WireError> {
        self.number(f64::from(v))
    }
    fn serialize_f64(self, v: f64) -> Result<(), WireError> {
        self.number(v)
    }
    fn serialize_char(self, v: char) -> Result<(), WireError> {
        let mut buf = [0u8; 4];
        self.string(v.encode_utf8(&mut buf))
    }
    fn serialize_str(self, v: &str) -> Result<(), WireError> {
        self.string(v)
    }
    fn serialize_bytes(self, v: &[u8]) -> Result<(), WireError> {
        use ser::SerializeSeq;
        let mut seq = self.serialize_seq(Some(v.len()))?;
        for b in v {
            seq.serialize_element(b)?;
        }
        seq.end()
    }
    fn serialize_none(self) -> Result<(), WireError> {
        self.plain()?;
        self.text("null");
        Ok(())
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<(), WireError> {
        value.serialize(self)
    }
    fn serialize_unit(self) -> Result<(), WireError> {
        self.serialize_none()
    }
    fn serialize_unit_struct(self, _name: &'static str) -> Result<(), WireError> {
        self.serialize_none()
    }
    fn serialize_unit_variant(
        self,
        _name: &'static str,
        _index: u32,
        variant: &'static str,
    ) -> Result<(), WireError> {
        self.string(variant)
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        name: &'static str,
        value: &T,
    ) -> Result<(), WireError> {
        let buffer = match name {
            F64_TOKEN => Buffer::F64,
            U8_TOKEN => Buffer::U8,
            _ => return value.serialize(self),
        };
        self.plain()?;
        let (key, at) = match buffer {
            Buffer::F64 => ("$f64", self.wire.numbers.len()),
            Buffer::U8 => ("$u8", self.wire.codes.len()),
        };
        self.into = Some(buffer);
        let done = value.serialize(&mut *self);
        self.into = None;
        done?;
        let len = match buffer {
            Buffer::F64 => self.wire.numbers.len(),
            Buffer::U8 => self.wire.codes.len(),
        } - at;
        let _ = write!(self.wire.json, "{{\"{key}\":[{at},{len}]}}");
        Ok(())
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _name: &'static str,
        _index: u32,
        variant: &'static str,
        value: &T,
    ) -> Result<(), WireError> {
        self.plain()?;
        self.text("{");
        self.string(variant)?;
        self.text(":");
        value.serialize(&mut *self)?;
        self.text("}");
        Ok(())
    }
    fn serialize_seq(self, _len: Option<usize>) -> Result<Compound<'a>, WireError> {
        if self.into.is_none() {
            self.text("[");
        }
        Ok(Compound {
            w: self,
            first: true,
            close: "]",
        })
    }
    fn serialize_tuple(self, len: usize) -> Result<Compound<'a>, WireError> {
        self.serialize_seq(Some(len))
    }
    fn serialize_tuple_struct(
        self,
        _name: &'static str,
        len: usize,
    ) -> Result<Compound<'a>, WireError> {
        self.serialize_seq(Some(len))
    }
    fn serialize_tuple_variant(
        self,
        _name: &'static str,
        _index: u32,
        variant: &'static str,
        _len: usize,
    ) -> Result<Compound<'a>, WireError> {
        self.plain()?;
        self.text("{");
        self.string(variant)?;
        self.text(":[");
        Ok(Compound {
            w: self,
            first: true,
            close: "]}",
        })
    }
    fn serialize_map(self, _len: Option<usize>) -> Result<Compound<'a>, WireError> {
        self.plain()?;
        self.text("{");
        Ok(Compound {
            w: self,
            first: true,
            close: "}",
        })
    }
    fn serialize_struct(self, _name: &'static str, len: usize) -> Result<Compound<'a>, WireError> {
        self.serialize_map(Some(len))
    }
    fn serialize_struct_variant(
        self,
        _name: &'static str,
        _index: u32,
        variant: &'static str,
        _len: usize,
    ) -> Result<Compound<'a>, WireError> {
        self.plain()?;
        self.text("{");
        self.string(variant)?;
        self.text(":{");
        Ok(Compound {
            w: self,
            first: true,
            close: "}}",
        })
    }
}

impl ser::SerializeSeq for Compound<'_> {
    type Ok = ();
    type Error = WireError;
    fn serialize_element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), WireError> {
        self.comma();
        value.serialize(&mut *self.w)
    }
    fn end(self) -> Result<(), WireError> {
        Compound::end(self)
    }
}

impl ser::SerializeTuple for Compound<'_> {
    type Ok = ();
    type Error = WireError;
    fn serialize_element<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), WireError> {
        ser::SerializeSeq::serialize_element(self, value)
    }
    fn end(self) -> Result<(), WireError> {
        Compound::end(self)
    }
}

impl ser::SerializeTupleStruct for Compound<'_> {
    type Ok = ();
    type Error = WireError;
    fn serialize_field<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), WireError> {
        ser::SerializeSeq::serialize_element(self, value)
    }
    fn end(self) -> Result<(), WireError> {
        Compound::end(self)
    }
}

impl ser::SerializeTupleVariant for Compound<'_> {
    type Ok = ();
    type Error = WireError;
    fn serialize_field<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), WireError> {
        ser::SerializeSeq::serialize_element(self, value)
    }
    fn end(self) -> Result<(), WireError> {
        Compound::end(self)
    }
}

impl ser::SerializeMap for Compound<'_> {
    type Ok = ();
    type Error = WireError;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, key: &T) -> Result<(), WireError> {
        self.comma();
        // JSON keys are strings: a number key is quoted.
        let start = self.w.wire.json.len();
        key.serialize(&mut *self.w)?;
        if !self.w.wire.json[start..].starts_with('"') {
            self.w.wire.json.insert(start, '"');
            self.w.text("\"");
        }
        self.w.text(":");
        Ok(())
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), WireError> {
        value.serialize(&mut *self.w)
    }
    fn end(self) -> Result<(), WireError> {
        Compound::end(self)
    }
}

impl ser::SerializeStruct for Compound<'_> {
    type Ok = ();
    type Error = WireError;
    fn serialize_field<T: Serialize + ?Sized>(
        &mut self,
        key: &'static str,
        value: &T,
    ) -> Result<(), WireError> {
        self.key(key)?;
        value.serialize(&mut *self.w)
    }
    fn end(self) -> Result<(), WireError> {
        Compound::end(self)
    }
}

impl ser::SerializeStructVariant for Compound<'_> {
    type Ok = ();
    type Error = WireError;
    fn serialize_field<T: Serialize + ?Sized>(
        &mut self,
        key: &'static str,
        value: &T,
    ) -> Result<(), WireError> {
        ser::SerializeStruct::serialize_field(self, key, value)
    }
    fn end(self) -> Result<(), WireError> {
        Compound::end(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::collections::BTreeMap;
    use alloc::vec;

    #[derive(serde::Serialize)]
    struct Part {
        #[serde(serialize_with = "f64s")]
        eps: Vec<f64>,
        #[serde(serialize_with = "u8s")]
        status: Vec<u8>,
        label: &'static str,
        gap: f64,
        big: f64,
        none: Option<u8>,
        pair: (f64, i32),
    }

    #[derive(serde::Serialize)]
    enum Kind {
        Unit,
        Tuple(u8, u8),
        Named { x: bool },
    }

    #[test]
    fn issue_36_arrays_cross_as_buffers_and_the_rest_as_json() {
        let parts = vec![
            Part {
                eps: vec![0.5, f64::NAN, 2.5e-7],
                status: vec![0, 255],
                label: "a \"b\"\n\u{1}é",
                gap: f64::INFINITY,
                big: 1e300,
                none: None,
                pair: (-0.25, -3),
            },
            Part {
                eps: vec![],
                status: vec![7],
                label: "",
                gap: 1.0,
                big: 123456.0,
                none: Some(4),
                pair: (0.1, 0),
            },
        ];
        let w = to_wire(&parts).unwrap();
        // JSON as RFC 8259 writes it: escaped quote, newline and control character, a non-finite
        // number as null (serde_json's choice), each marked array as a reference.
        assert_eq!(
            w.json,
            concat!(
                r#"[{"eps":{"$f64":[0,3]},"status":{"$u8":[0,2]},"label":"a \"b\"\n\u0001é","#,
                r#""gap":null,"big":1e300,"none":null,"pair":[-0.25,-3]},"#,
                r#"{"eps":{"$f64":[3,0]},"status":{"$u8":[2,1]},"label":"","gap":1.0,"#,
                r#""big":123456.0,"none":4,"pair":[0.1,0]}]"#
            )
        );
        // The numbers as they were, NaN included (JSON cannot carry it).
        assert_eq!(w.numbers.len(), 3);
        assert_eq!((w.numbers[0], w.numbers[2]), (0.5, 2.5e-7));
        assert!(w.numbers[1].is_nan());
        assert_eq!(w.codes, [0, 255, 7]);
    }

    #[test]
    fn issue_36_enums_maps_and_bad_buffers() {
        let kinds = [Kind::Unit, Kind::Tuple(1, 2), Kind::Named { x: true }];
        assert_eq!(
            to_wire(&kinds).unwrap().json,
            r#"["Unit",{"Tuple":[1,2]},{"Named":{"x":true}}]"#
        );
        let mut m = BTreeMap::new();
        m.insert(3u32, "three");
        assert_eq!(to_wire(&m).unwrap().json, r#"{"3":"three"}"#);
        // A u8 buffer holding a number beyond u8 is refused, named.
        struct Wide;
        impl Serialize for Wide {
            fn serialize<S: Serializer>(&self, s: S) -> core::result::Result<S::Ok, S::Error> {
                s.serialize_newtype_struct(U8_TOKEN, &[300u16])
            }
        }
        let e = to_wire(&Wide).unwrap_err().to_string();
        assert!(e.contains("300 is not a u8 code"), "{e}");
    }
}
