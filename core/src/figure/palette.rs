//! The one colour palette of every surface: the terminal (`ratatui` RGB colours), the exported
//! figures ([`crate::figure`]) and the web page ([`palette_json`]).
//!
//! The hues are Okabe & Ito's colour-blind-safe set (*Color Universal Design*, 2008) plus greys.
//! Roles, not hues, are what the views use:
//!
//! * this scene's curve and its critical-speed markers: orange (a marker has its curve's colour);
//! * the family of curves: mid blue, bluish green, reddish purple, ochre (sky blue and yellow,
//!   too pale on a white plot, darkened so that every line reads: see below);
//! * the clean surface: light grey; the experimental context (Bridges et al. 1984 and the
//!   microgravity boxes): vermillion, so that neither shares a grey with the other;
//! * stick-map classes: "aggregation" (sticking) vermillion and "rolling" sky blue stay far apart
//!   under deuteranopia; `sliding_gap`, an artifact of the printed law, is grey.
//!
//! Every role that a terminal prints as text has a contrast of at least 4.5:1 on black (no dark
//! blue), checked by a test. Every family and comparison line has at least 3:1 (WCAG 2.1, 1.4.11,
//! graphical objects) on the white plot area that the figures, the exports and the page draw on in
//! both of its themes; the yellow γ = 0.5 member had 1.3:1 (issue 22). This scene's orange (2.3:1,
//! drawn thickest and on top) and the clean surface's light grey (1.9:1, a faint reference by
//! design) keep their colours.
//!
//! A comparison (`explorer::figures::overlay_style`) takes a hue and a stroke of its own: five hues by three broken
//! strokes give fifteen pairs, more than the comparisons offered (thirteen), so no two series of a
//! figure share both colour and stroke (issue 21, 22). The comparisons' five hues are their own:
//! none is a family member's or this scene's hue (at least 20° of hue apart), because a family and
//! comparisons are drawn together and on a terminal's braille cells the stroke barely shows (issue
//! 37: `muller_poschel2011` was Okabe–Ito blue beside the family's mid blue, and three comparisons
//! had the family's very colours). Okabe–Ito has eight colours for ten roles, so the comparisons
//! take red, lime, cyan, violet and magenta, placed between the family's hues; the strokes keep
//! them apart where colour vision does not.

use crate::tangential::StickClass;

/// An sRGB colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Rgb {
    /// Red.
    pub r: u8,
    /// Green.
    pub g: u8,
    /// Blue.
    pub b: u8,
}

impl Rgb {
    /// A colour from `0xRRGGBB`.
    pub const fn hex(v: u32) -> Rgb {
        Rgb {
            r: (v >> 16) as u8,
            g: (v >> 8) as u8,
            b: v as u8,
        }
    }

    /// The colour as an `(r, g, b)` tuple.
    pub const fn tuple(self) -> (u8, u8, u8) {
        (self.r, self.g, self.b)
    }

    /// WCAG relative luminance (0 black … 1 white).
    pub fn luminance(self) -> f64 {
        let lin = |c: u8| {
            let c = f64::from(c) / 255.0;
            if c <= 0.040_45 {
                c / 12.92
            } else {
                libm::pow((c + 0.055) / 1.055, 2.4)
            }
        };
        0.2126 * lin(self.r) + 0.7152 * lin(self.g) + 0.0722 * lin(self.b)
    }

    /// WCAG contrast ratio with `other` (1 … 21).
    pub fn contrast(self, other: Rgb) -> f64 {
        let (a, b) = (self.luminance() + 0.05, other.luminance() + 0.05);
        if a > b { a / b } else { b / a }
    }

    /// Black or white, whichever reads better on this colour (letters on stick-map cells).
    pub fn text_on(self) -> Rgb {
        if self.contrast(BLACK) >= self.contrast(WHITE) {
            BLACK
        } else {
            WHITE
        }
    }
}

/// Okabe–Ito black `#000000`.
pub const BLACK: Rgb = Rgb::hex(0x000000);
/// Okabe–Ito orange `#E69F00`.
pub const ORANGE: Rgb = Rgb::hex(0xE69F00);
/// Okabe–Ito sky blue `#56B4E9`.
pub const SKY_BLUE: Rgb = Rgb::hex(0x56B4E9);
/// Okabe–Ito bluish green `#009E73`.
pub const BLUISH_GREEN: Rgb = Rgb::hex(0x009E73);
/// Okabe–Ito yellow `#F0E442`.
pub const YELLOW: Rgb = Rgb::hex(0xF0E442);
/// Okabe–Ito blue `#0072B2` (figures only: too dark for text on dark terminals).
pub const BLUE: Rgb = Rgb::hex(0x0072B2);
/// Okabe–Ito vermillion `#D55E00`.
pub const VERMILLION: Rgb = Rgb::hex(0xD55E00);
/// Okabe–Ito reddish purple `#CC79A7`.
pub const REDDISH_PURPLE: Rgb = Rgb::hex(0xCC79A7);
/// Light grey `#BBBBBB`.
pub const GREY_LIGHT: Rgb = Rgb::hex(0xBBBBBB);
/// Dark grey `#555555`.
pub const GREY_DARK: Rgb = Rgb::hex(0x555555);
/// White `#FFFFFF`.
pub const WHITE: Rgb = Rgb::hex(0xFFFFFF);
/// Mid blue `#3A7DC9`: sky blue darkened to read on white (4.2:1) and on black (5.0:1).
pub const MID_BLUE: Rgb = Rgb::hex(0x3A7DC9);
/// Ochre `#A08C00`: yellow darkened to read on white (3.4:1) and on black (6.3:1).
pub const OCHRE: Rgb = Rgb::hex(0xA08C00);

/// Red `#D93A2B`: the first comparison hue (between the family's reddish purple and this scene's
/// orange).
pub const RED: Rgb = Rgb::hex(0xD93A2B);
/// Lime `#5F9E20`: a comparison hue between ochre and bluish green.
pub const LIME: Rgb = Rgb::hex(0x5F9E20);
/// Cyan `#0098A8`: a comparison hue between bluish green and mid blue.
pub const CYAN: Rgb = Rgb::hex(0x0098A8);
/// Violet `#8A6BE0`: a comparison hue between mid blue and reddish purple.
pub const VIOLET: Rgb = Rgb::hex(0x8A6BE0);
/// Magenta `#B455C8`: a comparison hue between violet and reddish purple.
pub const MAGENTA: Rgb = Rgb::hex(0xB455C8);

/// The palette's colours with the word a caption uses for them.
const NAMES: [(Rgb, &str); 18] = [
    (BLACK, "black"),
    (ORANGE, "orange"),
    (SKY_BLUE, "sky-blue"),
    (BLUISH_GREEN, "bluish-green"),
    (YELLOW, "yellow"),
    (BLUE, "blue"),
    (VERMILLION, "vermillion"),
    (REDDISH_PURPLE, "reddish-purple"),
    (GREY_LIGHT, "light grey"),
    (GREY_DARK, "dark grey"),
    (WHITE, "white"),
    (MID_BLUE, "mid blue"),
    (OCHRE, "ochre"),
    (RED, "red"),
    (LIME, "lime"),
    (CYAN, "cyan"),
    (VIOLET, "violet"),
    (MAGENTA, "magenta"),
];

impl Rgb {
    /// The word for this colour in captions (`light grey`), so that a caption names the colour
    /// actually drawn; `colour` for one outside the palette.
    pub fn name(self) -> &'static str {
        NAMES
            .iter()
            .find(|(c, _)| *c == self)
            .map_or("colour", |(_, n)| *n)
    }
}

/// This scene's ε_N curve.
pub const SCENE: Rgb = ORANGE;
/// Critical-speed markers (g_s) of this scene: the colour of its curve.
pub const CRITICAL: Rgb = SCENE;
/// The family of curves over a swept parameter, in order (repeats after four).
pub const FAMILY: [Rgb; 4] = [MID_BLUE, BLUISH_GREEN, REDDISH_PURPLE, OCHRE];
/// The clean-surface curve (no layer, no adhesion).
pub const CLEAN: Rgb = GREY_LIGHT;
/// The experimental context: the Bridges et al. (1984) law and the microgravity boxes.
pub const EXPERIMENT: Rgb = VERMILLION;

/// The hues of the comparisons drawn over the ε_N chart (measured laws and other models), in
/// order; with three broken strokes they give each comparison its own style
/// (`explorer::figures::overlay_style`). None shares a hue with the family or this scene.
pub const OVERLAYS: [Rgb; 5] = [RED, CYAN, VIOLET, LIME, MAGENTA];
/// A curve pinned to compare with later edits.
pub const PINNED: Rgb = GREY_DARK;

/// Figure series colours by index ([`crate::figure::Series::color`]): the family first, then the
/// roles at [`SERIES_SCENE`], [`SERIES_CLEAN`], [`SERIES_EXPERIMENT`], the comparisons from
/// [`SERIES_OVERLAY`] and the pinned curve at [`SERIES_PINNED`].
pub const SERIES: [Rgb; 14] = [
    FAMILY[0],
    FAMILY[1],
    FAMILY[2],
    FAMILY[3],
    SCENE,
    BLUE,
    CLEAN,
    EXPERIMENT,
    OVERLAYS[0],
    OVERLAYS[1],
    OVERLAYS[2],
    OVERLAYS[3],
    OVERLAYS[4],
    PINNED,
];
/// Index of [`SCENE`] in [`SERIES`].
pub const SERIES_SCENE: usize = 4;
/// Index of [`BLUE`] in [`SERIES`]: the ring card's ε_cr line and impact-speed marker.
pub const SERIES_RING: usize = 5;
/// Index of [`CLEAN`] in [`SERIES`].
pub const SERIES_CLEAN: usize = 6;
/// Index of [`EXPERIMENT`] in [`SERIES`].
pub const SERIES_EXPERIMENT: usize = 7;
/// Index of the first of [`OVERLAYS`] in [`SERIES`].
pub const SERIES_OVERLAY: usize = 8;
/// Index of [`PINNED`] in [`SERIES`].
pub const SERIES_PINNED: usize = 13;

/// Colour of a stick-map class.
pub const fn class(c: StickClass) -> Rgb {
    match c {
        StickClass::Rolling => SKY_BLUE,
        StickClass::Sliding => YELLOW,
        StickClass::RollingStop => BLUISH_GREEN,
        StickClass::SlidingGap => GREY_LIGHT,
        StickClass::Aggregation => VERMILLION,
        StickClass::NormalStickOnly => REDDISH_PURPLE,
        StickClass::Undefined => GREY_DARK,
    }
}

/// The palette as JSON for the web page: `{"scene":"#E69F00",…,"family":[…],"series":[…],
/// "classes":{"rolling":"#56B4E9",…}}`.
#[cfg(feature = "alloc")]
pub fn palette_json() -> alloc::string::String {
    use alloc::format;
    use alloc::string::String;
    let hex = |c: Rgb| format!("\"#{:02X}{:02X}{:02X}\"", c.r, c.g, c.b);
    let list = |cs: &[Rgb]| {
        let items: alloc::vec::Vec<String> = cs.iter().map(|c| hex(*c)).collect();
        format!("[{}]", items.join(","))
    };
    let classes: alloc::vec::Vec<String> = StickClass::ALL
        .iter()
        .map(|c| format!("\"{}\":{}", c.name(), hex(class(*c))))
        .collect();
    format!(
        "{{\"scene\":{},\"critical\":{},\"clean\":{},\"experiment\":{},\"pinned\":{},\"overlays\":{},\"family\":{},\"series\":{},\"classes\":{{{}}}}}",
        hex(SCENE),
        hex(CRITICAL),
        hex(CLEAN),
        hex(EXPERIMENT),
        hex(PINNED),
        list(&OVERLAYS),
        list(&FAMILY),
        list(&SERIES),
        classes.join(",")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Machado, Oliveira & Fernandes (2009) deuteranopia (severity 1) on linear RGB, back to sRGB.
    fn deuteranopia(c: Rgb) -> [f64; 3] {
        const M: [[f64; 3]; 3] = [
            [0.367_322, 0.860_646, -0.227_968],
            [0.280_085, 0.672_501, 0.047_413],
            [-0.011_820, 0.042_940, 0.968_881],
        ];
        let lin = |c: u8| {
            let c = f64::from(c) / 255.0;
            if c <= 0.040_45 {
                c / 12.92
            } else {
                libm::pow((c + 0.055) / 1.055, 2.4)
            }
        };
        let enc = |c: f64| {
            let c = c.clamp(0.0, 1.0);
            255.0
                * if c <= 0.003_130_8 {
                    12.92 * c
                } else {
                    1.055 * libm::pow(c, 1.0 / 2.4) - 0.055
                }
        };
        let v = [lin(c.r), lin(c.g), lin(c.b)];
        let mut out = [0.0; 3];
        for (k, row) in M.iter().enumerate() {
            out[k] = enc(row[0] * v[0] + row[1] * v[1] + row[2] * v[2]);
        }
        out
    }

    fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
        libm::sqrt((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2))
    }

    #[test]
    fn classes_stay_apart_under_deuteranopia() {
        let all = StickClass::ALL;
        for (i, a) in all.iter().enumerate() {
            for b in &all[i + 1..] {
                let d = dist(deuteranopia(class(*a)), deuteranopia(class(*b)));
                assert!(d > 45.0, "{a:?} vs {b:?}: {d}");
            }
        }
        // Sticking must never be mistaken for rolling (issue 12, item 16).
        let d = dist(
            deuteranopia(class(StickClass::Aggregation)),
            deuteranopia(class(StickClass::Rolling)),
        );
        assert!(d > 150.0, "{d}");
        for c in all {
            if c != StickClass::Aggregation {
                let d = dist(
                    deuteranopia(class(StickClass::Aggregation)),
                    deuteranopia(class(c)),
                );
                assert!(d > 100.0, "aggregation vs {c:?}: {d}");
            }
        }
    }

    #[test]
    fn terminal_text_roles_read_on_dark_backgrounds() {
        for c in [SCENE, CRITICAL, CLEAN, EXPERIMENT]
            .into_iter()
            .chain(FAMILY)
            .chain(
                StickClass::ALL
                    .iter()
                    .map(|c| class(*c))
                    .filter(|c| *c != GREY_DARK),
            )
        {
            assert!(c.contrast(BLACK) >= 4.5, "{c:?}: {}", c.contrast(BLACK));
        }
        assert!(BLUE.contrast(BLACK) < 4.5, "the check can fail");
        // Letters on every class colour are legible.
        for c in StickClass::ALL {
            let bg = class(c);
            assert!(bg.text_on().contrast(bg) >= 4.5, "{c:?}");
        }
    }

    /// Issue 22: the γ = 0.5 family member was yellow on white (1.3:1). Every family and
    /// comparison line reads on the white plot area of the figures, the exports and the page (its
    /// dark theme keeps the plot white), and as text on a dark terminal.
    #[test]
    fn family_and_comparison_lines_read_on_white_and_on_black_issue_22() {
        for c in FAMILY.into_iter().chain(OVERLAYS) {
            assert!(
                c.contrast(WHITE) >= 3.0,
                "{c:?} on white: {}",
                c.contrast(WHITE)
            );
            assert!(
                c.contrast(BLACK) >= 4.0,
                "{c:?} on black: {}",
                c.contrast(BLACK)
            );
        }
        for c in FAMILY {
            assert!(c.contrast(BLACK) >= 4.5, "{c:?}");
        }
        // The check can fail: the old fourth member.
        assert!(YELLOW.contrast(WHITE) < 1.5);
        // Within the family the hues stay apart under deuteranopia.
        for (i, a) in FAMILY.iter().enumerate() {
            for b in &FAMILY[i + 1..] {
                let d = dist(deuteranopia(*a), deuteranopia(*b));
                assert!(d > 40.0, "{a:?} vs {b:?}: {d}");
            }
        }
    }

    /// The hue angle of `c` in degrees (HSL/HSV hue, 0…360).
    fn hue(c: Rgb) -> f64 {
        let (r, g, b) = (f64::from(c.r), f64::from(c.g), f64::from(c.b));
        let max = r.max(g).max(b);
        let min = r.min(g).min(b);
        let d = max - min;
        let h = if d == 0.0 {
            0.0
        } else if max == r {
            60.0 * ((g - b) / d)
        } else if max == g {
            60.0 * ((b - r) / d + 2.0)
        } else {
            60.0 * ((r - g) / d + 4.0)
        };
        (h + 360.0) % 360.0
    }

    fn hue_gap(a: Rgb, b: Rgb) -> f64 {
        let d = (hue(a) - hue(b)).abs();
        d.min(360.0 - d)
    }

    /// Issue 37 item 8: no comparison shares a hue with a family member or with this scene (the
    /// family and the comparisons are on one chart; on a terminal the stroke barely shows), and the
    /// comparisons' hues stay apart from each other.
    #[test]
    fn issue_37_no_comparison_shares_a_hue_with_the_family() {
        for o in OVERLAYS {
            for f in FAMILY.into_iter().chain([SCENE]) {
                let gap = hue_gap(o, f);
                assert!(gap >= 20.0, "{o:?} vs {f:?}: {gap:.0}°");
            }
        }
        for (i, a) in OVERLAYS.iter().enumerate() {
            for b in &OVERLAYS[i + 1..] {
                let gap = hue_gap(*a, *b);
                assert!(gap >= 30.0, "{a:?} vs {b:?}: {gap:.0}°");
            }
        }
        // The check can fail: the old comparison blue beside the family's mid blue (10°).
        assert!(hue_gap(BLUE, MID_BLUE) < 20.0);
        // Every comparison hue has a caption word.
        for o in OVERLAYS {
            assert_ne!(o.name(), "colour", "{o:?}");
        }
    }

    #[test]
    fn roles_are_distinct() {
        assert_ne!(
            CLEAN, EXPERIMENT,
            "clean surface and experiments share a colour"
        );
        for f in FAMILY {
            assert!(![SCENE, CLEAN, EXPERIMENT].contains(&f), "{f:?}");
        }
        assert_eq!(SERIES[SERIES_SCENE], SCENE);
        assert_eq!(SERIES[SERIES_CLEAN], CLEAN);
        assert_eq!(SERIES[SERIES_EXPERIMENT], EXPERIMENT);
    }

    #[test]
    fn json_names_every_role_and_class() {
        let j = palette_json();
        assert!(j.starts_with("{\"scene\":\"#E69F00\""), "{j}");
        for c in StickClass::ALL {
            assert!(j.contains(&alloc::format!("\"{}\":\"#", c.name())), "{j}");
        }
        assert!(j.contains("\"family\":[\"#3A7DC9\",\"#009E73\",\"#CC79A7\",\"#A08C00\"]"));
    }
}
