//! What a surface asks the explorer to compute: one [`Request`], with its defaults and limits as
//! associated constants, written once for every surface.
//!
//! The command line's flags, the terminal's state, the page's link and view (through the wasm
//! binding) all become a `Request`, and [`Request::validate`] is the one check: a surface refuses
//! exactly what the core refuses. With the `serde` feature a request reads and writes its wire form
//! (snake_case keys, as every file record; unknown keys refused, every key optional): `{"scene":
//! {…}, "accuracy": "precise", "from": 1e-7, "to": 10, "points": 241, "map_max": null, "map_n": 81,
//! "family": true,
//! "sweep": "bulk.viscosity.shear", "overlays": ["atlas:bridges1984"], "fail": []}`. Older forms
//! still load: `balanced` for `integrated`, the page's links' `mapN`/`mapMax` (issue 36) for
//! `map_n`/`map_max`.
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

use super::limits::{MAX_CURVE_POINTS, MAX_MAP_SIDE, SPEED_MAX, SPEED_MIN, chart_speed_is_valid};
use crate::scene::params::Value;
use crate::{Accuracy, Scene, error::Error};
use alloc::format;
use alloc::string::String;
use alloc::vec::Vec;

/// A parameter that the chart's family of curves can sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sweep {
    /// Parameter path (`grains.radius` sets both radii).
    pub path: &'static str,
    /// Short symbol for legends.
    pub symbol: &'static str,
    /// SI unit.
    pub unit: &'static str,
    /// Fixed values (the paper's figures), or `None` for multiples of the current value.
    pub values: Option<&'static [f64]>,
}

/// Multiples of the current value used when a sweep has no fixed values.
pub const RELATIVE: [f64; 4] = [0.1, 0.3, 3.0, 10.0];

/// Every sweepable parameter, in the order the explorer cycles through them.
pub const SWEEPS: [Sweep; 6] = [
    Sweep {
        path: "layer.viscosity",
        symbol: "η*",
        unit: "Pa s",
        values: Some(&[500.0, 1000.0, 2000.0, 5000.0]),
    },
    Sweep {
        path: "layer.thickness",
        symbol: "D",
        unit: "m",
        values: Some(&[0.5e-6, 1e-6, 2e-6, 5e-6]),
    },
    Sweep {
        path: "adhesion.surface_energy",
        symbol: "γ",
        unit: "J/m²",
        values: Some(&[0.05, 0.1, 0.2, 0.5]),
    },
    Sweep {
        path: "bulk.damping.time",
        symbol: "A",
        unit: "s",
        values: None,
    },
    Sweep {
        path: "grains.radius",
        symbol: "R₁=R₂",
        unit: "m",
        values: None,
    },
    Sweep {
        path: "bulk.youngs_modulus",
        symbol: "Y",
        unit: "Pa",
        values: None,
    },
];

impl Sweep {
    /// Whether the sweep applies to `scene` (layer/adhesion sweeps need the effect on).
    pub fn available(&self, scene: &Scene) -> bool {
        if self.path.starts_with("layer.") {
            scene.layer.is_some()
        } else if self.path.starts_with("adhesion.") {
            scene.adhesion.is_some()
        } else {
            true
        }
    }

    /// The default sweep for a scene: η* with a layer, γ with adhesion, else the damping time.
    pub fn default_for(scene: &Scene) -> usize {
        if scene.layer.is_some() {
            0
        } else if scene.adhesion.is_some() {
            2
        } else {
            3
        }
    }

    /// The current value of the swept parameter in `scene` (NaN when it has none).
    pub fn current(&self, scene: &Scene) -> f64 {
        match self.path {
            "grains.radius" => scene.grains.radius_1,
            "bulk.damping.time" => scene.damping_time(),
            p => match scene.get(p) {
                Ok(Value::Number(v)) => v,
                _ => f64::NAN,
            },
        }
    }

    /// The family's values for `scene`.
    pub fn values(&self, scene: &Scene) -> Vec<f64> {
        if let Some(v) = self.values {
            return v.to_vec();
        }
        let c = self.current(scene);
        if c.is_finite() && c > 0.0 {
            // Rounded to 12 significant digits: 3 × 1e-4 is the 3e-4 a user would type, not
            // 3.0000000000000003e-4 (which data files and legends would then show).
            RELATIVE
                .iter()
                .map(|f| crate::explorer::format::round_sig(f * c, 12))
                .collect()
        } else {
            alloc::vec![1e-5, 1e-4, 1e-3, 1e-2]
        }
    }

    /// `scene` with the swept parameter set to `v`.
    pub fn apply(&self, scene: &Scene, v: f64) -> crate::Result<Scene> {
        let mut s = *scene;
        if self.path == "grains.radius" {
            s.set_number("grains.radius_1", v)?;
            s.set_number("grains.radius_2", v)?;
        } else {
            s.set_number(self.path, v)?;
        }
        Ok(s)
    }
}

/// Something drawn over the ε_N chart beside the scene's own model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Overlay {
    /// A measured law or range of the data atlas ([`crate::data::atlas`]), drawn only over its measured
    /// speeds; `radius` for entries that need one (the scene's reduced radius when `None`).
    Atlas(&'static crate::data::atlas::Entry),
    /// Another collision model on the same scene ([`crate::models`]), with its characteristic speeds.
    Model(crate::models::Model),
}

impl Overlay {
    /// Parses `atlas:ID` or `model:NAME` (the form surfaces store in links and flags).
    pub fn parse(text: &str) -> crate::Result<Overlay> {
        let bad = Error::InvalidValue {
            field: "overlays",
            expected: "atlas:ID (see rime data) or model:NAME (see rime compare --list)",
        };
        match text.split_once(':') {
            Some(("atlas", id)) => crate::data::atlas::find(id).map(Overlay::Atlas).ok_or(bad),
            Some(("model", name)) => crate::models::Model::from_name(name)
                .map(Overlay::Model)
                .ok_or(bad),
            _ => Err(bad),
        }
    }

    /// `atlas:ID` or `model:NAME`.
    pub fn key(&self) -> String {
        match self {
            Overlay::Atlas(e) => format!("atlas:{}", e.id),
            Overlay::Model(m) => format!("model:{}", m.name()),
        }
    }
}

/// The comparisons a surface cycles through (the terminal's `c`): nothing, the measured laws and
/// ranges of the data atlas (each only over the speeds it was measured at, with the scene's rms
/// score), the other collision models on the same grains (with their characteristic speeds).
pub const COMPARISONS: [(&str, &[&str]); 3] = [
    ("no comparison", &[]),
    (
        "measured ice",
        &[
            "atlas:bridges1984",
            "atlas:hatzes1988_frost",
            "atlas:supulver1995",
            "atlas:heisselmann2010",
            "atlas:hill2015",
        ],
    ),
    (
        "other models",
        &[
            "model:brilliantov2007",
            "model:muller_poschel2011",
            "model:thornton1997",
        ],
    ),
];

/// The overlays of comparison `set` ([`COMPARISONS`]) for `scene`: thornton1997 only where the
/// scene has the plasticity section it needs (elsewhere it is left out, not an error).
pub fn comparison(set: usize, scene: &Scene) -> Vec<Overlay> {
    COMPARISONS
        .get(set)
        .map(|(_, keys)| {
            keys.iter()
                .filter_map(|k| Overlay::parse(k).ok())
                .filter(|o| {
                    !matches!(o, Overlay::Model(crate::models::Model::Thornton1997))
                        || scene.plasticity.is_some()
                })
                .collect()
        })
        .unwrap_or_default()
}

/// An end of a chart's speed range, or an error naming `field` (see [`chart_speed_is_valid`]).
/// What a chart's speed must be, as errors write it (the test of [`CHART_SPEED_DOMAIN`] checks it).
///
/// [`CHART_SPEED_DOMAIN`]: super::limits::CHART_SPEED_DOMAIN
pub(crate) const CHART_SPEED_EXPECTED: &str = "a speed in [1e-12, 1e6] m/s";

fn check_chart_speed(field: &'static str, g: f64) -> crate::Result<()> {
    if chart_speed_is_valid(g) {
        Ok(())
    } else {
        Err(Error::OutOfRange {
            field,
            value: g,
            expected: CHART_SPEED_EXPECTED,
        })
    }
}

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
            check_chart_speed("from", from)?;
            check_chart_speed("to", to)?;
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
    use super::{Overlay, Sweep};
    use super::{Request, SWEEPS};
    use crate::{Accuracy, Preset, Scene};
    use alloc::format;
    use alloc::string::{String, ToString};
    use alloc::vec::Vec;

    #[derive(serde::Serialize, serde::Deserialize)]
    #[serde(deny_unknown_fields)]
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
        // `mapMax`/`mapN`: the keys of the views and links written before issue 36.
        #[serde(default, alias = "mapMax")]
        map_max: Option<f64>,
        #[serde(default = "default_map_n", alias = "mapN")]
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
                if let Some(g) = g {
                    super::check_chart_speed(field, g).map_err(|e| e.to_string())?;
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
            request.validate().map_err(|e| e.to_string())?;
            Ok(request)
        }
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
