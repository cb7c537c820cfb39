//! The one-line views: derived quantities, status (accuracy, timing, warnings), message or input.

use crate::explore::compute::Computed;
use crate::explore::format::{num3, qty3};
use crate::explore::line_input::LineInput;
use crate::explore::state::{Confirm, SCENE_FILE, Tone};
use ratatui::style::{Color, Style};
use ratatui::text::{Line, Span};
use rime_core::params::PARAMETERS;
use rime_core::{Accuracy, Status};
use std::time::Duration;

/// The derived quantities of the frame's contact (δ at the chart cursor when there is room).
pub fn derived_line(data: Option<&Computed>, cursor: usize, width: u16) -> Line<'static> {
    let Some(data) = data else {
        return Line::from("computing…");
    };
    let Some(c) = data.contact.as_ref() else {
        return Line::from(Span::styled(
            data.problem().unwrap_or_default(),
            Style::new().fg(Color::Red),
        ));
    };
    let dim = Style::new().fg(Color::Gray);
    let g = data.g.get(cursor).copied().unwrap_or(f64::NAN);
    let delta = if g.is_finite() {
        num3(c.delta(g))
    } else {
        "—".into()
    };
    let tan = c.friction.map_or("—".to_string(), |f| {
        num3(rime_core::tangential::tan_psi0(&f))
    });
    let mut items = vec![
        ("R_eff", qty3(c.r_eff, "m")),
        ("m_eff", qty3(c.m_eff, "kg")),
        ("A", qty3(c.damping_time, "s")),
    ];
    if let Some(l) = c.layer {
        items.push(("g_s(layer)", qty3(l.critical_velocity, "m/s")));
    }
    if let Some(a) = c.adhesion {
        items.push(("g_s(adh.)", qty3(a.critical_velocity, "m/s")));
    }
    items.push(("tan ψ₀", tan));
    // δ at the cursor is also in the chart's readout; keep it here when there is room.
    let used: usize = items
        .iter()
        .map(|(n, v)| n.chars().count() + v.chars().count() + 3)
        .sum();
    if used + 6 + delta.chars().count() <= width as usize {
        items.push(("δ(g)", delta));
    }
    let mut spans = Vec::new();
    for (k, (name, value)) in items.into_iter().enumerate() {
        if k > 0 {
            spans.push(Span::raw("  "));
        }
        spans.push(Span::styled(format!("{name} "), dim));
        spans.push(Span::raw(value));
    }
    Line::from(spans)
}

/// What the status line shows.
#[derive(Debug, Clone, Copy)]
pub struct StatusView<'a> {
    /// Accuracy level.
    pub accuracy: Accuracy,
    /// The latest frame.
    pub data: Option<&'a Computed>,
    /// Compute time to show instead of the measured one.
    pub elapsed: Option<Duration>,
    /// Whether a newer frame is being computed.
    pub computing: bool,
    /// Chart cursor (index into the curve speeds).
    pub cursor: usize,
}

/// The status line's end when it is cut: `?` lists every warning of the frame.
pub const STATUS_CUT: &str = "… ? lists all";

/// Accuracy, compute time and warnings, within `width` cells ([`STATUS_CUT`] when cut).
pub fn status_line(app: &StatusView, width: u16) -> Line<'static> {
    fit(status_spans(app, width), width as usize, STATUS_CUT)
}

/// The status line's spans before they are fitted (`width` chooses the long or short wording).
pub fn status_spans(app: &StatusView, width: u16) -> Vec<Span<'static>> {
    let level = Span::styled(
        app.accuracy.name().to_string(),
        Style::new().fg(Color::Black).bg(Color::Cyan),
    );
    let mut spans = Vec::new();
    match app.data {
        Some(d) if d.preview => {
            // The preview's own level, then what it is being refined to.
            let t = app.elapsed.unwrap_or(d.elapsed);
            spans.push(Span::raw(format!(
                " preview in {} at ",
                qty3(t.as_secs_f64(), "s")
            )));
            spans.push(Span::styled(
                d.request.accuracy.name().to_string(),
                Style::new().fg(Color::Black).bg(Color::Cyan),
            ));
            spans.push(Span::styled(
                format!(" refining to {}… ", app.accuracy.name()),
                Style::new().fg(Color::Yellow),
            ));
        }
        Some(d) => {
            let t = app.elapsed.unwrap_or(d.elapsed);
            spans.push(Span::raw(format!(
                " computed in {} at ",
                qty3(t.as_secs_f64(), "s")
            )));
            spans.push(level);
            spans.push(Span::raw(" "));
        }
        None => {
            spans.push(Span::raw(" accuracy "));
            spans.push(level);
            spans.push(Span::raw(" "));
        }
    }
    if app.computing && !app.data.is_some_and(|d| d.preview) {
        spans.push(Span::styled(" computing… ", Style::new().fg(Color::Yellow)));
    }
    let warn = Style::new().fg(Color::LightRed);
    if let Some(d) = app.data {
        if let Some(n) = d.point(app.cursor)
            && n.status == Status::Overdamped
        {
            spans.push(Span::styled("│ ⚠ overdamped at cursor ", warn));
        }
        if let (Some(e), Some(_)) = (d.problem(), &d.contact) {
            spans.push(Span::styled(format!("│ ⚠ {e} "), warn));
        }
        if let Some(note) = d.notes() {
            spans.push(Span::styled(format!("│ {note} "), warn));
        }
    }
    // The core's warnings of the frame (the page and `rime curve` show the same set); the
    // options that depart from the paper in yellow.
    let shown = app.data.map(|d| d.warnings.as_slice()).unwrap_or_default();
    let opts: Vec<&str> = shown
        .iter()
        .filter(|w| w.is_paper_option())
        .map(|w| w.short())
        .collect();
    for w in shown.iter().filter(|w| !w.is_paper_option()) {
        spans.push(Span::styled(format!("│ ⚠ {} ", w.short()), warn));
    }
    if !opts.is_empty() {
        let used: usize = spans.iter().map(|s| s.content.chars().count()).sum();
        let long = format!("│ ⚠ paper-inconsistent option in use: {}", opts.join(", "));
        let text = if used + long.chars().count() <= width as usize {
            long
        } else {
            format!("│ ⚠ paper-inconsistent: {}", opts.join(", "))
        };
        spans.push(Span::styled(text, Style::new().fg(Color::Yellow)));
    }
    spans
}

/// What the message line shows: an input being typed, else the last message.
#[derive(Debug, Clone, Copy)]
pub struct MessageView<'a> {
    /// A yes/no question waiting for its answer.
    pub confirm: Option<Confirm>,
    /// Path being typed after `o`.
    pub open: Option<&'a LineInput>,
    /// Value being typed after `e`.
    pub input: Option<&'a LineInput>,
    /// Selected row of [`PARAMETERS`] (the one `e` sets).
    pub selected: usize,
    /// Last status message.
    pub message: Option<&'a (String, Tone)>,
    /// What Esc's quit would lose of the view ([`Confirm::Leave`]).
    pub view_to_lose: &'a [&'static str],
}

/// Appends spans to a line.
trait PatchSpans {
    fn patch_spans(self, spans: Vec<Span<'static>>) -> Self;
}

impl PatchSpans for Line<'static> {
    fn patch_spans(mut self, spans: Vec<Span<'static>>) -> Self {
        self.spans.extend(spans);
        self
    }
}

/// An input's text with its cursor, then the hint. A pre-fill that typing replaces is shown
/// highlighted, and the hint says so.
fn input_spans(input: &LineInput, hint: &str) -> Vec<Span<'static>> {
    let cursor = Span::styled("▏", Style::new().fg(Color::Yellow));
    let hint_style = Style::new().fg(Color::Gray);
    if input.fresh && !input.text.is_empty() {
        return vec![
            Span::styled(
                input.text.clone(),
                Style::new().fg(Color::Black).bg(Color::Gray),
            ),
            cursor,
            Span::styled(format!("  typing replaces ·{hint}"), hint_style),
        ];
    }
    let (before, after) = input.split();
    vec![
        Span::raw(before),
        cursor,
        Span::raw(after),
        Span::styled(format!("{hint} · ←→ Home End"), hint_style),
    ]
}

/// The message / input line.
pub fn message_line(app: &MessageView) -> Line<'static> {
    let ask = Style::new().fg(Color::Black).bg(Color::Yellow);
    match app.confirm {
        Some(Confirm::Quit) => {
            return Line::from(vec![
                Span::styled(" unsaved edits: quit anyway? ", ask),
                Span::raw(" y quits · n stays (w saves, u undoes)"),
            ]);
        }
        Some(Confirm::Leave) => {
            return Line::from(vec![
                Span::styled(" Esc quits rime? ", ask),
                Span::raw(format!(
                    " {} would go · y quits · n stays",
                    app.view_to_lose.join(", ")
                )),
            ]);
        }
        Some(Confirm::Overwrite) => {
            return Line::from(vec![
                Span::styled(format!(" {SCENE_FILE} exists: overwrite it? "), ask),
                Span::raw(" y overwrites · n keeps it"),
            ]);
        }
        None => {}
    }
    if let Some(text) = app.open {
        return Line::from(vec![
            Span::styled(
                " open scene file: ",
                Style::new().fg(Color::Black).bg(Color::Yellow),
            ),
            Span::raw(" "),
        ])
        .patch_spans(input_spans(
            text,
            "  Enter load · Esc cancel · Ctrl-U clear",
        ));
    }
    if let Some(text) = app.input {
        let p = PARAMETERS.get(app.selected);
        let label = p.map_or("", |p| p.label);
        let unit = p.map_or("", |p| p.unit);
        let unit = if unit.is_empty() {
            String::new()
        } else {
            format!(" [{unit}]")
        };
        return Line::from(vec![
            Span::styled(
                format!(" set {label}{unit}: "),
                Style::new().fg(Color::Black).bg(Color::Yellow),
            ),
            Span::raw(" "),
        ])
        .patch_spans(input_spans(
            text,
            "  Enter apply · Esc cancel · Ctrl-U clear · units ok (2 um, 1 kPa s)",
        ));
    }
    match app.message {
        Some((text, Tone::Error)) => Line::from(Span::styled(
            format!(" ✗ {text}"),
            Style::new().fg(Color::LightRed),
        )),
        Some((text, Tone::Info)) => Line::from(Span::raw(format!(" {text}"))),
        None => Line::default(),
    }
}

/// The spans within `width` cells: when they do not fit, the last ones are cut and the line ends
/// with `more` (`… ? lists all` on the status line: `?` lists every warning of the frame), so a
/// cut line says so (it was cut silently at 80 columns).
pub fn fit(spans: Vec<Span<'static>>, width: usize, more: &'static str) -> Line<'static> {
    let total: usize = spans.iter().map(|s| s.content.chars().count()).sum();
    if total <= width {
        return Line::from(spans);
    }
    let room = width.saturating_sub(more.chars().count());
    let mut out = Vec::new();
    let mut used = 0;
    for span in spans {
        let n = span.content.chars().count();
        if used + n <= room {
            used += n;
            out.push(span);
        } else {
            let part: String = span.content.chars().take(room - used).collect();
            if !part.is_empty() {
                out.push(Span::styled(part, span.style));
            }
            break;
        }
    }
    out.push(Span::styled(more, Style::new().fg(Color::Yellow)));
    Line::from(out)
}
