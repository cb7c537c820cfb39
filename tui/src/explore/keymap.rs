//! The one keymap: the key handler ([`mod@super::update`]), the `?` overlay ([`super::view::help`]) and
//! the README's key list (`readme_list`, checked by a test) all read [`KEYMAP`].

use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

/// A key as the table names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Key {
    /// A printable character (Shift is part of the character: `L`, `{`).
    Char(char),
    /// ↑.
    Up,
    /// ↓.
    Down,
    /// ←.
    Left,
    /// →.
    Right,
    /// Shift+←.
    ShiftLeft,
    /// Shift+→.
    ShiftRight,
    /// Enter.
    Enter,
    /// Tab.
    Tab,
    /// Shift+Tab.
    BackTab,
    /// Esc.
    Esc,
    /// Ctrl-C.
    CtrlC,
    /// Ctrl-Z.
    CtrlZ,
    /// Ctrl-Y.
    CtrlY,
}

impl Key {
    /// The terminal event this key arrives as (tests press every key of the table with it).
    #[cfg(test)]
    pub fn event(self) -> KeyEvent {
        let plain = |code| KeyEvent::new(code, KeyModifiers::NONE);
        match self {
            Key::Char(c) => plain(KeyCode::Char(c)),
            Key::Up => plain(KeyCode::Up),
            Key::Down => plain(KeyCode::Down),
            Key::Left => plain(KeyCode::Left),
            Key::Right => plain(KeyCode::Right),
            Key::ShiftLeft => KeyEvent::new(KeyCode::Left, KeyModifiers::SHIFT),
            Key::ShiftRight => KeyEvent::new(KeyCode::Right, KeyModifiers::SHIFT),
            Key::Enter => plain(KeyCode::Enter),
            Key::Tab => plain(KeyCode::Tab),
            Key::BackTab => KeyEvent::new(KeyCode::BackTab, KeyModifiers::SHIFT),
            Key::Esc => plain(KeyCode::Esc),
            Key::CtrlC => KeyEvent::new(KeyCode::Char('c'), KeyModifiers::CONTROL),
            Key::CtrlZ => KeyEvent::new(KeyCode::Char('z'), KeyModifiers::CONTROL),
            Key::CtrlY => KeyEvent::new(KeyCode::Char('y'), KeyModifiers::CONTROL),
        }
    }

    /// The table's name of a terminal key event, if the table has one.
    pub fn of(event: KeyEvent) -> Option<Key> {
        let shift = event.modifiers.contains(KeyModifiers::SHIFT);
        if event.modifiers.contains(KeyModifiers::CONTROL) {
            return match event.code {
                KeyCode::Char('c') => Some(Key::CtrlC),
                KeyCode::Char('z') => Some(Key::CtrlZ),
                KeyCode::Char('y') => Some(Key::CtrlY),
                _ => None,
            };
        }
        Some(match event.code {
            KeyCode::Char(c) => Key::Char(c),
            KeyCode::Up => Key::Up,
            KeyCode::Down => Key::Down,
            KeyCode::Left if shift => Key::ShiftLeft,
            KeyCode::Right if shift => Key::ShiftRight,
            KeyCode::Left => Key::Left,
            KeyCode::Right => Key::Right,
            KeyCode::Enter => Key::Enter,
            KeyCode::Tab => Key::Tab,
            KeyCode::BackTab => Key::BackTab,
            KeyCode::Esc => Key::Esc,
            _ => return None,
        })
    }
}

/// What a key does; arrows act on the focused pane (parameters, chart cursor, map cursor).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Action {
    /// Previous parameter; map: cursor up.
    Up,
    /// Next parameter; map: cursor down.
    Down,
    /// Decrease the parameter; chart/map: cursor left.
    Left,
    /// Increase the parameter; chart/map: cursor right.
    Right,
    /// Finely decrease; chart/map: one step left.
    FineLeft,
    /// Finely increase; chart/map: one step right.
    FineRight,
    /// Cycle a choice, switch an effect, edit a number.
    Activate,
    /// Type a value.
    Edit,
    /// Next preset.
    Preset,
    /// Next accuracy level.
    Accuracy,
    /// Next swept parameter.
    Sweep,
    /// Move the g_N cursor by this many points.
    Cursor(i8),
    /// Next pane.
    FocusNext,
    /// Previous pane.
    FocusPrev,
    /// Zoom in: the stick map's range ÷2 when it has the focus, else the chart's speed range ÷2
    /// (in decades, around the cursor).
    ZoomIn,
    /// Zoom out (the inverse of [`Action::ZoomIn`]).
    ZoomOut,
    /// Automatic range of the focused view (stick map, else the chart's speeds).
    ZoomAuto,
    /// Pan the chart's speed range by a quarter of its width (−1 left, +1 right).
    Pan(i8),
    /// The ε_N axis: log ↔ linear.
    YScale,
    /// Pin the current ε_N curve (or unpin it).
    Pin,
    /// The scene's sliding law: the paper's Eq. (23) ↔ Walton's.
    Walton,
    /// Undo the last scene edit.
    Undo,
    /// Redo the last undone scene edit.
    Redo,
    /// Experiments on/off.
    Experiments,
    /// Tidal appendix on/off.
    Tidal,
    /// The collision panel (inside one collision at the cursor) on/off.
    Inside,
    /// Next comparison on the ε_N chart: measured ice, other models, none.
    Compare,
    /// Fit the damping time A to the first measured law compared with.
    FitToLaw,
    /// The sticking-thresholds panel on/off.
    Stick,
    /// Ring card on/off.
    Ring,
    /// Ring optical depth ÷1.25.
    RingThinner,
    /// Ring optical depth ×1.25.
    RingDenser,
    /// The ring card's grain sizes: one, R–5R, R–10R.
    RingSizes,
    /// Tidal planet distance ÷1.05.
    TidalNearer,
    /// Tidal planet distance ×1.05.
    TidalFarther,
    /// Export the frame.
    Export,
    /// Save the scene.
    Save,
    /// Open a scene.
    Open,
    /// Show the help.
    Help,
    /// Close the tidal appendix, else quit.
    Back,
    /// Quit (asks first when the scene has unsaved edits).
    Quit,
    /// Ctrl-C: quit at once.
    Interrupt,
}

/// One row of the table: how the help names the keys, what they do, and the keys themselves.
#[derive(Debug, Clone, Copy)]
pub struct Row {
    /// The keys as the help shows them.
    pub keys: &'static str,
    /// What they do.
    pub does: &'static str,
    /// Every key of the row with its action (empty for rows that only explain other rows' keys).
    pub bindings: &'static [(Key, Action)],
}

/// Every key of the explorer.
pub const KEYMAP: &[Row] = &[
    Row {
        keys: "↑/↓  j/k",
        does: "select parameter",
        bindings: &[
            (Key::Up, Action::Up),
            (Key::Char('k'), Action::Up),
            (Key::Down, Action::Down),
            (Key::Char('j'), Action::Down),
        ],
    },
    Row {
        keys: "←/→  h/l",
        does: "change: ×/÷1.25 (log) or ±5% of range",
        bindings: &[
            (Key::Left, Action::Left),
            (Key::Char('h'), Action::Left),
            (Key::Right, Action::Right),
            (Key::Char('l'), Action::Right),
        ],
    },
    Row {
        keys: "Shift+←/→  H/L",
        does: "fine change: ×/÷1.02 or ±1%",
        bindings: &[
            (Key::ShiftLeft, Action::FineLeft),
            (Key::Char('H'), Action::FineLeft),
            (Key::ShiftRight, Action::FineRight),
            (Key::Char('L'), Action::FineRight),
        ],
    },
    Row {
        keys: "Enter/space",
        does: "cycle a choice, switch an effect on/off",
        bindings: &[
            (Key::Enter, Action::Activate),
            (Key::Char(' '), Action::Activate),
        ],
    },
    Row {
        keys: "e",
        does: "type an exact value with units (2 um)",
        bindings: &[(Key::Char('e'), Action::Edit)],
    },
    Row {
        keys: "p",
        does: "next preset",
        bindings: &[(Key::Char('p'), Action::Preset)],
    },
    Row {
        keys: "a",
        does: "next accuracy (fast/precise/integrated)",
        bindings: &[(Key::Char('a'), Action::Accuracy)],
    },
    Row {
        keys: "s",
        does: "next swept parameter (family of curves)",
        bindings: &[(Key::Char('s'), Action::Sweep)],
    },
    Row {
        keys: "[ ] { }  wheel",
        does: "move the g_N cursor (fine, coarse)",
        bindings: &[
            (Key::Char('['), Action::Cursor(-1)),
            (Key::Char(']'), Action::Cursor(1)),
            (Key::Char('{'), Action::Cursor(-10)),
            (Key::Char('}'), Action::Cursor(10)),
        ],
    },
    Row {
        keys: "Tab  click",
        does: "focus: parameters → chart → stick map (short terminals: one at a time)",
        bindings: &[
            (Key::Tab, Action::FocusNext),
            (Key::BackTab, Action::FocusPrev),
        ],
    },
    Row {
        keys: "arrows (map focus)",
        does: "move the map cursor",
        bindings: &[],
    },
    Row {
        keys: "+ / - / 0",
        does: "zoom in / out / automatic: speed range (map focus: map range)",
        bindings: &[
            (Key::Char('+'), Action::ZoomIn),
            (Key::Char('='), Action::ZoomIn),
            (Key::Char('-'), Action::ZoomOut),
            (Key::Char('0'), Action::ZoomAuto),
        ],
    },
    Row {
        keys: ", / .  wheel on axis",
        does: "pan the speed range left / right; wheel on the g_N axis zooms",
        bindings: &[
            (Key::Char(','), Action::Pan(-1)),
            (Key::Char('.'), Action::Pan(1)),
        ],
    },
    Row {
        keys: "y",
        does: "ε_N axis log / linear (linear shows sticking, ε_N = 0)",
        bindings: &[(Key::Char('y'), Action::YScale)],
    },
    Row {
        keys: "P",
        does: "pin this ε_N curve to compare with later edits / unpin",
        bindings: &[(Key::Char('P'), Action::Pin)],
    },
    Row {
        keys: "W",
        does: "sliding law: the paper's Eq. (23) ↔ Walton's (no sliding gap)",
        bindings: &[(Key::Char('W'), Action::Walton)],
    },
    Row {
        keys: "u / U  Ctrl-Z/Y",
        does: "undo / redo a scene edit (also p, o, f, W)",
        bindings: &[
            (Key::Char('u'), Action::Undo),
            (Key::CtrlZ, Action::Undo),
            (Key::Char('U'), Action::Redo),
            (Key::CtrlY, Action::Redo),
        ],
    },
    Row {
        keys: "b",
        does: "experiments on the ε_N chart on/off (sources below)",
        bindings: &[(Key::Char('b'), Action::Experiments)],
    },
    Row {
        keys: "t  (then < >)",
        does: "tidal appendix A.1–A.7 (planet distance ÷/×1.05)",
        bindings: &[
            (Key::Char('t'), Action::Tidal),
            (Key::Char('<'), Action::TidalNearer),
            (Key::Char('>'), Action::TidalFarther),
        ],
    },
    Row {
        keys: "r  (then ( ) < > g)",
        does: "ring card: what this law does to a ring (τ ÷/×1.25, g grain sizes)",
        bindings: &[
            (Key::Char('r'), Action::Ring),
            (Key::Char('('), Action::RingThinner),
            (Key::Char(')'), Action::RingDenser),
            (Key::Char('g'), Action::RingSizes),
        ],
    },
    Row {
        keys: "c / f",
        does: "compare: measured ice, other models, none / fit A to it",
        bindings: &[
            (Key::Char('c'), Action::Compare),
            (Key::Char('f'), Action::FitToLaw),
        ],
    },
    Row {
        keys: "i / v",
        does: "one collision: ξ(t), F(ξ), ledger / sticking thresholds",
        bindings: &[
            (Key::Char('i'), Action::Inside),
            (Key::Char('v'), Action::Stick),
        ],
    },
    Row {
        keys: "x",
        does: "export CSV, SVG, PNG + scene JSON to rime-export-*/",
        bindings: &[(Key::Char('x'), Action::Export)],
    },
    Row {
        keys: "w / o",
        does: "save (asks before overwriting) / open a scene JSON (rime-scene.json)",
        bindings: &[
            (Key::Char('w'), Action::Save),
            (Key::Char('o'), Action::Open),
        ],
    },
    Row {
        keys: "?  /  q Esc Ctrl-C",
        does: "this help (↑↓ scroll; q Esc close it) / quit (asks if edits are unsaved); Esc closes a panel first and asks before a pin, zoom or comparison goes",
        bindings: &[
            (Key::Char('?'), Action::Help),
            (Key::Char('q'), Action::Quit),
            (Key::Esc, Action::Back),
            (Key::CtrlC, Action::Interrupt),
        ],
    },
];

/// The action the table gives a key event, if any.
pub fn action(event: KeyEvent) -> Option<Action> {
    let key = Key::of(event)?;
    KEYMAP
        .iter()
        .flat_map(|r| r.bindings)
        .find(|(k, _)| *k == key)
        .map(|(_, a)| *a)
}

/// The README's key list (one Markdown bullet per row), kept equal to the table by a test.
#[cfg(test)]
pub fn readme_list() -> String {
    let mut out = String::new();
    for row in KEYMAP {
        out.push_str(&format!(
            "- `{}` {}\n",
            row.keys.replace("  ", " "),
            row.does
        ));
    }
    out
}
