//! What a surface asks the explorer to compute: one [`Request`], with its defaults and limits as
//! associated constants, written once for every surface.
//!
//! The command line's flags, the terminal's state, the page's link and view (through the wasm
//! binding) all become a `Request`, and [`Request::validate`] is the one check: a surface refuses
//! exactly what the core refuses. With the `serde` feature a request reads and writes its wire form
//! (camelCase keys, unknown keys refused, every key optional): `{"scene": {…}, "accuracy":
//! "precise", "from": 1e-7, "to": 10, "points": 241, "mapMax": null, "mapN": 81, "family": true,
//! "sweep": "bulk.viscosity.shear", "overlays": ["atlas:bridges1984"], "fail": []}`. Older forms
//! still load: `balanced` for `integrated`, `map_n`/`map_max` for `mapN`/`mapMax`.
//!
//! # Examples
//!
//! ```
//! use rime_core::explorer::request::Request;
//! use rime_core::{Accuracy, Preset};
//!
//! let mut request = Request::new(Preset::Ice.scene(), Accuracy::Fast);
//! assert_eq!(request.points, Request::POINTS);
//! request.map_n = Request::MAX_MAP_N + 1;
//! let refused = request.validate().unwrap_err().to_string();
//! assert!(refused.starts_with("map_n"), "{refused}");
//! ```

use super::frame::{Overlay, SWEEPS};
use super::limits::{MAX_CURVE_POINTS, MAX_MAP_SIDE, SPEED_MAX, SPEED_MIN, chart_speed_is_valid};
use crate::{Accuracy, Scene, error::Error};
use alloc::string::String;
use alloc::vec::Vec;

/// Parts of a frame that a request can make fail on purpose (to test how a surface shows failures).
pub const FORCIBLE: [&str; 4] = ["curve", "family", "marker", "map"];

/// What a surface asks to see.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(try_from = "wire::Wire", into = "wire::Wire")
)]
pub struct Request {
    /// The scene.
    pub scene: Scene,
    /// Accuracy level.
    pub accuracy: Accuracy,
    /// Index into [`SWEEPS`]; `None` for [`super::frame::Sweep::default_for`] the scene.
    pub sweep: Option<usize>,
    /// Whether to compute the family of curves.
    pub family: bool,
    /// Chart speeds \[m/s\] (`None`: the decades of [`super::range::chart_decades`]).
    pub speeds: Option<(f64, f64)>,
    /// Points per curve.
    pub points: usize,
    /// Upper end of both stick-map axes \[m/s\]; `None` for [`super::range::auto_map_range`].
    pub map_max: Option<f64>,
    /// Stick-map side (`map_n²` cells).
    pub map_n: usize,
    /// Parts to fail on purpose (see [`FORCIBLE`]).
    pub fail: Vec<String>,
    /// Measured laws and other models to draw over the chart.
    pub overlays: Vec<Overlay>,
}

impl Request {
    /// Points per ε_N curve of the default view (every surface: terminal, page, `rime figures
    /// --explorer`).
    pub const POINTS: usize = 241;
    /// Stick-map side of the default view (`MAP_N²` cells).
    pub const MAP_N: usize = 81;
    /// Most points on one curve.
    pub const MAX_POINTS: usize = MAX_CURVE_POINTS;
    /// Largest stick-map side.
    pub const MAX_MAP_N: usize = MAX_MAP_SIDE;
    /// Fastest speed of a chart or a map \[m/s\] (the models' own limit).
    pub const SPEED_MAX: f64 = SPEED_MAX;
    /// Slowest end of a chart's speed range \[m/s\].
    pub const SPEED_MIN: f64 = SPEED_MIN;

    /// The default view of a scene at an accuracy: [`Request::POINTS`] points on the chart's
    /// decades, a [`Request::MAP_N`]² map.
    pub fn new(scene: Scene, accuracy: Accuracy) -> Request {
        Request {
            scene,
            accuracy,
            sweep: None,
            family: true,
            speeds: None,
            points: Request::POINTS,
            map_max: None,
            map_n: Request::MAP_N,
            fail: Vec::new(),
            overlays: Vec::new(),
        }
    }

    /// Checks the request's own fields; errors name the field. The scene is checked where it is
    /// evaluated, and a map range the models refuse fails the map part alone (see
    /// [`super::frame::compute`]).
    pub fn validate(&self) -> crate::Result<()> {
        if let Some((from, to)) = self.speeds {
            for (field, g) in [("from", from), ("to", to)] {
                if !chart_speed_is_valid(g) {
                    return Err(Error::OutOfRange {
                        field,
                        value: g,
                        expected: "a speed in [1e-12, 1e6] m/s",
                    });
                }
            }
            if from >= to {
                return Err(Error::OutOfRange {
                    field: "to",
                    value: to,
                    expected: "greater than from",
                });
            }
        }
        if !(2..=Request::MAX_POINTS).contains(&self.points) {
            return Err(Error::OutOfRange {
                field: "points",
                value: self.points as f64,
                expected: "a count in [2, 20000]",
            });
        }
        if !(2..=Request::MAX_MAP_N).contains(&self.map_n) {
            return Err(Error::OutOfRange {
                field: "map_n",
                value: self.map_n as f64,
                expected: "a count in [2, 1000]",
            });
        }
        if self.sweep.is_some_and(|k| k >= SWEEPS.len()) {
            return Err(Error::InvalidValue {
                field: "sweep",
                expected: "one of the sweepable parameters",
            });
        }
        if self.fail.iter().any(|p| !FORCIBLE.contains(&p.as_str())) {
            return Err(Error::InvalidValue {
                field: "fail",
                expected: "parts among curve, family, marker, map",
            });
        }
        Ok(())
    }

    /// Whether `part` (one of [`FORCIBLE`]) is to fail on purpose.
    pub(crate) fn forced(&self, part: &str) -> bool {
        self.fail.iter().any(|p| p == part)
    }
}

#[cfg(feature = "serde")]
mod wire {
    //! The serde form of a [`Request`]: keys as the page's link has always written them.
    use super::{Request, SWEEPS};
    use crate::explorer::frame::{Overlay, Sweep};
    use crate::{Accuracy, Preset, Scene};
    use alloc::format;
    use alloc::string::{String, ToString};
    use alloc::vec::Vec;

    #[derive(serde::Serialize, serde::Deserialize)]
    #[serde(deny_unknown_fields, rename_all = "camelCase")]
    pub struct Wire {
        #[serde(default = "default_scene")]
        scene: Scene,
        #[serde(default = "default_accuracy")]
        accuracy: String,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        sweep: Option<String>,
        #[serde(default = "yes")]
        family: bool,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        from: Option<f64>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        to: Option<f64>,
        #[serde(default = "default_points")]
        points: usize,
        // `map_max`/`map_n`: the snake-case keys of views written before the one request.
        #[serde(default, alias = "map_max")]
        map_max: Option<f64>,
        #[serde(default = "default_map_n", alias = "map_n")]
        map_n: usize,
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        fail: Vec<String>,
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        overlays: Vec<String>,
    }

    fn default_scene() -> Scene {
        Preset::Ice.scene()
    }
    fn default_accuracy() -> String {
        Accuracy::default().name().to_string()
    }
    fn yes() -> bool {
        true
    }
    fn default_points() -> usize {
        Request::POINTS
    }
    fn default_map_n() -> usize {
        Request::MAP_N
    }

    impl TryFrom<Wire> for Request {
        type Error = String;

        fn try_from(w: Wire) -> Result<Request, String> {
            let accuracy = Accuracy::parse(&w.accuracy).map_err(|e| e.to_string())?;
            let sweep = match w.sweep {
                None => None,
                Some(path) => {
                    Some(SWEEPS.iter().position(|s| s.path == path).ok_or_else(|| {
                        let known: Vec<&str> = SWEEPS.iter().map(|s: &Sweep| s.path).collect();
                        format!("sweep: {path:?} is not one of {}", known.join(", "))
                    })?)
                }
            };
            // A bad speed is named before a missing partner.
            for (field, g) in [("from", w.from), ("to", w.to)] {
                if let Some(g) = g
                    && !crate::explorer::limits::chart_speed_is_valid(g)
                {
                    return Err(format!(
                        "{field}: a speed in [1e-12, 1e6] m/s (got {})",
                        crate::error::Number(g)
                    ));
                }
            }
            let speeds = match (w.from, w.to) {
                (None, None) => None,
                (Some(from), Some(to)) => Some((from, to)),
                (Some(_), None) => return Err("to: needed with from".into()),
                (None, Some(_)) => return Err("from: needed with to".into()),
            };
            let overlays = w
                .overlays
                .iter()
                .map(|o| Overlay::parse(o).map_err(|e| format!("{e} (got {o:?})")))
                .collect::<Result<Vec<_>, _>>()?;
            let request = Request {
                scene: w.scene,
                accuracy,
                sweep,
                family: w.family,
                speeds,
                points: w.points,
                map_max: w.map_max,
                map_n: w.map_n,
                fail: w.fail,
                overlays,
            };
            request.validate().map_err(|e| wire_field(&e.to_string()))?;
            Ok(request)
        }
    }

    /// The validation message with the field spelled as in the wire form (`map_n` → `mapN`).
    fn wire_field(message: &str) -> String {
        for (core, wire) in [("map_n", "mapN"), ("map_max", "mapMax")] {
            if let Some(rest) = message.strip_prefix(core) {
                return format!("{wire}{rest}");
            }
        }
        message.to_string()
    }

    impl From<Request> for Wire {
        fn from(r: Request) -> Wire {
            Wire {
                scene: r.scene,
                accuracy: match r.accuracy {
                    Accuracy::Tolerance(t) => format!("{}", crate::error::Number(t)),
                    named => named.name().to_string(),
                },
                sweep: r
                    .sweep
                    .and_then(|k| SWEEPS.get(k))
                    .map(|s| s.path.to_string()),
                family: r.family,
                from: r.speeds.map(|s| s.0),
                to: r.speeds.map(|s| s.1),
                points: r.points,
                map_max: r.map_max,
                map_n: r.map_n,
                fail: r.fail,
                overlays: r.overlays.iter().map(Overlay::key).collect(),
            }
        }
    }
}
