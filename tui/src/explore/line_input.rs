//! A one-line text input (the `e` prompt and the `o` path), with its cursor.

use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use std::path::PathBuf;

/// What a key did to a one-line input.
pub(crate) enum LineEdit {
    /// The text changed (or nothing happened); keep editing.
    Editing,
    /// Esc: drop the input.
    Cancel,
    /// Enter: the finished text.
    Submit(String),
    /// Ctrl-C: quit the explorer.
    Quit,
}

/// A one-line input (`e` values, `o` file names): the text, a cursor, and whether the text is
/// still the pre-fill, which the first typed character replaces.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LineInput {
    /// The text.
    pub text: String,
    /// Cursor position in characters (0 … length).
    pub cursor: usize,
    /// True until the user edits: the text is the pre-fill and a typed character replaces it.
    pub fresh: bool,
}

impl LineInput {
    /// An input pre-filled with `text` (cursor at the end; the first typed character replaces it).
    pub fn prefilled(text: impl Into<String>) -> LineInput {
        let text = text.into();
        LineInput {
            cursor: text.chars().count(),
            text,
            fresh: true,
        }
    }

    /// The text before and after the cursor.
    pub fn split(&self) -> (String, String) {
        let before: String = self.text.chars().take(self.cursor).collect();
        let after: String = self.text.chars().skip(self.cursor).collect();
        (before, after)
    }

    fn byte(&self, chars: usize) -> usize {
        self.text
            .char_indices()
            .nth(chars)
            .map_or(self.text.len(), |(i, _)| i)
    }

    /// Applies one key: characters insert at the cursor (replacing a fresh pre-fill), Backspace and
    /// Delete remove, ←/→/Home/End (and Ctrl-A/E) move, Ctrl-U clears.
    pub(crate) fn key(&mut self, key: KeyEvent) -> LineEdit {
        let ctrl = key.modifiers.contains(KeyModifiers::CONTROL);
        let len = self.text.chars().count();
        let was_fresh = std::mem::replace(&mut self.fresh, false);
        match key.code {
            KeyCode::Esc => return LineEdit::Cancel,
            KeyCode::Enter => return LineEdit::Submit(std::mem::take(&mut self.text)),
            KeyCode::Char('c') if ctrl => return LineEdit::Quit,
            KeyCode::Char('u') if ctrl => {
                self.text.clear();
                self.cursor = 0;
            }
            KeyCode::Char('a') if ctrl => self.cursor = 0,
            KeyCode::Char('e') if ctrl => self.cursor = len,
            KeyCode::Home => self.cursor = 0,
            KeyCode::End => self.cursor = len,
            KeyCode::Left => self.cursor = self.cursor.saturating_sub(1),
            KeyCode::Right => self.cursor = (self.cursor + 1).min(len),
            KeyCode::Backspace if was_fresh => {
                self.text.clear();
                self.cursor = 0;
            }
            KeyCode::Backspace if self.cursor > 0 => {
                let at = self.byte(self.cursor - 1);
                self.text.remove(at);
                self.cursor -= 1;
            }
            KeyCode::Delete if self.cursor < len => {
                let at = self.byte(self.cursor);
                self.text.remove(at);
            }
            KeyCode::Char(c) if !ctrl => {
                if was_fresh {
                    self.text.clear();
                    self.cursor = 0;
                }
                let at = self.byte(self.cursor);
                self.text.insert(at, c);
                self.cursor += 1;
            }
            _ => self.fresh = was_fresh,
        }
        LineEdit::Editing
    }
}

/// A typed path with a leading `~` or `~/` read as the home directory (as a shell would), so
/// `~/scenes/a.json` opens what the user means; any other path is taken as typed.
pub fn expand_home(path: &str) -> PathBuf {
    let home = std::env::var_os("HOME").filter(|h| !h.is_empty());
    match (path.strip_prefix('~'), home) {
        (Some(""), Some(home)) => PathBuf::from(home),
        (Some(rest), Some(home)) if rest.starts_with('/') => {
            PathBuf::from(home).join(rest.trim_start_matches('/'))
        }
        _ => PathBuf::from(path),
    }
}
