//! JSON text read into a type with errors that name the field (`grains.radius_1: invalid type: …`),
//! without a path-tracking deserializer: `serde_json` says where in the text it failed (line and
//! column), and the path is read off the text up to there. The wasm module carries one small
//! scanner instead of a tracking wrapper around every type it reads (issue 36: that wrapper was
//! 120 kB of the module). A scene read this way is also validated ([`parse_scene`]).

use super::limits::MAX_SCENE_BYTES;
use crate::Scene;
use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec::Vec;
use serde::de::DeserializeOwned;

/// Reads `text` as a `T`; the error is `(path, message)`: the JSON path of the element where
/// reading failed (`grains.radius_1`, `pinned.g[3]`; empty for the whole) and the cause without
/// its position.
pub fn read<T: DeserializeOwned>(text: &str) -> Result<T, (String, String)> {
    serde_json::from_str(text).map_err(|e| {
        let path = path_at(text, e.line(), e.column());
        let message = e.to_string();
        let message = match message.rfind(" at line ") {
            Some(at) => message[..at].to_string(),
            None => message,
        };
        (path, message)
    })
}

/// Reads `text` as a `T`; an error names the JSON path of the offending field: `field` for the
/// whole, else `field.path` (`nested`) or the path alone (a scene's fields are named as they are).
pub fn read_named<T: DeserializeOwned>(text: &str, field: &str, nested: bool) -> Result<T, String> {
    read(text).map_err(|(path, message)| {
        let path = if path.is_empty() {
            field.to_string()
        } else if nested {
            format!("{field}.{path}")
        } else {
            path
        };
        format!("{path}: {message}")
    })
}

/// Parses scene JSON; errors name the JSON path (`layer.viscosity: ...`).
pub fn parse_scene(text: &str) -> Result<Scene, String> {
    if text.len() > MAX_SCENE_BYTES {
        return Err(format!(
            "scene: {} bytes; a scene is at most {MAX_SCENE_BYTES} bytes",
            text.len()
        ));
    }
    let scene: Scene = read_named(text, "scene", false)?;
    scene.validate().map_err(|e| e.to_string())?;
    Ok(scene)
}

/// The byte offset of `line` and `column` (1-based, as `serde_json` counts them).
fn offset(text: &str, line: usize, column: usize) -> usize {
    let start: usize = text
        .split_inclusive('\n')
        .take(line.saturating_sub(1))
        .map(str::len)
        .sum();
    (start + column).min(text.len())
}

/// Where the reader is inside a container.
enum Level {
    /// In an object, under the last key read (none yet after `{` or `,`).
    Object(Option<String>),
    /// In an array, at this element (and whether it has begun).
    Array(usize, bool),
}

/// The JSON path of the element being read at `line`, `column` of `text`.
fn path_at(text: &str, line: usize, column: usize) -> String {
    let end = offset(text, line, column);
    let bytes = text.as_bytes();
    let mut stack: Vec<Level> = Vec::new();
    let mut expect_key = false;
    let mut i = 0;
    while i < end {
        // A value begins inside an array: the path reaches its element.
        if !matches!(bytes[i], b' ' | b'\n' | b'\r' | b'\t' | b',' | b']')
            && let Some(Level::Array(_, begun)) = stack.last_mut()
        {
            *begun = true;
        }
        match bytes[i] {
            b'{' => {
                stack.push(Level::Object(None));
                expect_key = true;
            }
            b'[' => {
                stack.push(Level::Array(0, false));
                expect_key = false;
            }
            b'}' | b']' => {
                stack.pop();
                expect_key = false;
            }
            b',' => match stack.last_mut() {
                Some(Level::Object(key)) => {
                    *key = None;
                    expect_key = true;
                }
                Some(Level::Array(k, begun)) => {
                    *k += 1;
                    *begun = false;
                }
                None => {}
            },
            b':' => expect_key = false,
            b'"' => {
                let start = i + 1;
                i += 1;
                while i < bytes.len() && bytes[i] != b'"' {
                    i += if bytes[i] == b'\\' { 2 } else { 1 };
                }
                if expect_key && let Some(Level::Object(key)) = stack.last_mut() {
                    let raw = text.get(start..i.min(text.len())).unwrap_or("");
                    *key = Some(
                        serde_json::from_str(&format!("\"{raw}\""))
                            .unwrap_or_else(|_| raw.to_string()),
                    );
                }
            }
            _ => {}
        }
        i += 1;
    }
    // An element the reader looked at but did not take (`{` where a number is due) is the one
    // that failed.
    let next = bytes[end.min(bytes.len())..]
        .iter()
        .find(|b| !b.is_ascii_whitespace());
    if let (Some(Level::Array(_, begun)), Some(b)) = (stack.last_mut(), next)
        && *b != b']'
    {
        *begun = true;
    }
    let mut path = String::new();
    for level in &stack {
        match level {
            Level::Object(Some(key)) => {
                if !path.is_empty() {
                    path.push('.');
                }
                path.push_str(key);
            }
            Level::Object(None) | Level::Array(_, false) => break,
            Level::Array(k, true) => path.push_str(&format!("[{k}]")),
        }
    }
    path
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde::Deserialize;

    #[derive(Debug, Deserialize)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct Inner {
        radius: f64,
        list: Vec<f64>,
    }

    #[derive(Debug, Deserialize)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct Outer {
        grains: Inner,
        name: String,
    }

    fn path(text: &str) -> String {
        read::<Outer>(text).unwrap_err().0
    }

    #[test]
    fn issue_36_an_error_names_the_element_it_is_in() {
        // Each expected path is where the bad element sits in the text.
        assert_eq!(
            path(r#"{"grains": {"radius": "x", "list": []}, "name": "a"}"#),
            "grains.radius"
        );
        assert_eq!(
            path(r#"{"grains": {"radius": 1, "list": [1, 2, "3"]}, "name": "a"}"#),
            "grains.list[2]"
        );
        assert_eq!(
            path(r#"{"name": 5, "grains": {"radius": 1, "list": []}}"#),
            "name"
        );
        assert_eq!(
            path("{\"grains\": {\n  \"radius\": 1,\n  \"lst\": []}, \"name\": \"a\"}"),
            "grains.lst"
        );
        // A key with an escape, a missing field (the object that lacks it), the whole.
        assert_eq!(
            path(r#"{"grains": {"radius": 1, "list": []}, "na\"me": 1}"#),
            "na\"me"
        );
        assert_eq!(path(r#"{"grains": {"radius": 1}, "name": "a"}"#), "grains");
        assert_eq!(path(r#"{"grains": {"radius": 1, "list": []}}"#), "");
        // A struct reads an array field by field: its first element is the one that fails.
        assert_eq!(path("[1"), "[0]");
        assert_eq!(path("5"), "");
        assert_eq!(
            path(r#"{"grains": {"radius": 1, "list": [1, 2, {}]}, "name": "a"}"#),
            "grains.list[2]"
        );
        let (_, message) = read::<Outer>(r#"{"name": 5}"#).unwrap_err();
        assert!(
            message.starts_with("invalid type: integer `5`, expected a string"),
            "{message}"
        );
        assert!(!message.contains(" at line "), "{message}");
    }
}
