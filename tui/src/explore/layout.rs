//! Where each part of the screen goes: shared by the views (drawing) and by `app` (mouse hits), so
//! neither depends on the other.

use ratatui::layout::Rect;

/// Smallest usable terminal.
pub const MIN_SIZE: (u16, u16) = (60, 20);

/// Where each part of the screen goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout {
    /// Parameter panel.
    pub panel: Rect,
    /// ε_N chart (with its title and readout rows).
    pub chart: Rect,
    /// Stick map (with its title and readout rows).
    pub map: Rect,
    /// Derived quantities line.
    pub derived: Rect,
    /// Status line (accuracy, compute time, warnings).
    pub status: Rect,
    /// Message / input line (None on short terminals: the message joins the status line).
    pub message: Option<Rect>,
    /// Whether the chart and the stick map share one pane (short terminals, below
    /// [`SPLIT_HEIGHT`] rows): then `chart` and `map` are the same area and one of them is shown.
    pub shared: bool,
}

/// Terminals at least this tall show the ε_N chart and the stick map one above the other; shorter
/// ones (80×24, the usual default) show one of them in the whole right-hand pane, so that the chart
/// keeps a useful height (15 rows of plot at 80×24 instead of 5).
pub const SPLIT_HEIGHT: u16 = 30;

impl Layout {
    /// The area of the tidal calculator: the chart and the stick map together.
    pub fn views(&self) -> Rect {
        if self.shared {
            return self.chart;
        }
        Rect::new(
            self.chart.x,
            self.chart.y,
            self.chart.width,
            self.chart.height + self.map.height,
        )
    }
}

/// Splits a `w × h` screen, or `None` if it is below [`MIN_SIZE`].
pub fn layout(w: u16, h: u16) -> Option<Layout> {
    if w < MIN_SIZE.0 || h < MIN_SIZE.1 {
        return None;
    }
    let bottom = if h >= 24 { 3 } else { 2 };
    let main_h = h - bottom;
    let panel_w = (w * 3 / 8).clamp(26, 40);
    let right_w = w - panel_w;
    let shared = h < SPLIT_HEIGHT;
    let right = Rect::new(panel_w, 0, right_w, main_h);
    let chart_h = main_h * 11 / 20;
    let (chart, map) = if shared {
        (right, right)
    } else {
        (
            Rect::new(panel_w, 0, right_w, chart_h),
            Rect::new(panel_w, chart_h, right_w, main_h - chart_h),
        )
    };
    Some(Layout {
        panel: Rect::new(0, 0, panel_w, main_h),
        chart,
        map,
        shared,
        derived: Rect::new(0, main_h, w, 1),
        status: Rect::new(0, main_h + 1, w, 1),
        message: (bottom == 3).then(|| Rect::new(0, main_h + 2, w, 1)),
    })
}

/// A chart's x axis as drawn: the graph's columns and the axis and label rows (mouse hits read it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LogAxis {
    /// First column of the graph.
    pub x: u16,
    /// Width of the graph in cells.
    pub width: u16,
    /// Row of the axis line.
    pub axis_row: u16,
    /// Row of the labels.
    pub label_row: u16,
    /// Left end of the column span the labels may use (the y labels' column).
    pub left: u16,
    /// log10 of the axis ends.
    pub lo: f64,
    /// log10 of the axis ends.
    pub hi: f64,
}

impl LogAxis {
    /// The column where log10 value `t` is drawn (ratatui's canvas: two Braille dots a cell, rounded).
    /// A value within 1e-9 of the span outside an end is drawn at that end (issue 37 E13: the
    /// `i` panel's overlap starts at a float-noise 2.7e-26 m, so the tick at 0 fell off the axis
    /// and the origin had no `0`).
    pub fn column(&self, t: f64) -> Option<u16> {
        let span = self.hi - self.lo;
        let slack = 1e-9 * span;
        if self.width == 0
            || span.is_nan()
            || span <= 0.0
            || t < self.lo - slack
            || t > self.hi + slack
        {
            return None;
        }
        let t = t.clamp(self.lo, self.hi);
        let dots = f64::from(self.width) * 2.0 - 1.0;
        let dot = ((t - self.lo) * dots / (self.hi - self.lo)).round() as u16;
        Some(self.x + dot / 2)
    }
}
