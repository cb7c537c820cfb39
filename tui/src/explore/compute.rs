//! The data behind one frame: ε_N curves (current scene, a family over a swept parameter, the clean
//! surface) and the stick map. Pure functions of a [`Request`]; the worker thread calls [`compute`].

use rime_core::sweep::{StickMap, log_space};
use rime_core::{Accuracy, Contact, Normal, Scene};
use std::time::{Duration, Instant};

/// Number of speeds on each ε_N curve.
pub const CURVE_POINTS: usize = 241;
/// Grid size of the stick map (`n × n`).
pub const MAP_POINTS: usize = 81;

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

/// Every sweepable parameter, in the order `s` cycles through them.
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

    /// The current value of the swept parameter in `scene`.
    pub fn current(&self, scene: &Scene) -> f64 {
        match self.path {
            "grains.radius" => scene.grains.radius_1,
            "bulk.damping.time" => scene.damping_time(),
            p => match scene.get(p) {
                Ok(rime_core::params::Value::Number(v)) => v,
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
            RELATIVE.iter().map(|f| f * c).collect()
        } else {
            vec![1e-5, 1e-4, 1e-3, 1e-2]
        }
    }

    /// `scene` with the swept parameter set to `v` (None if the value is rejected).
    pub fn apply(&self, scene: &Scene, v: f64) -> Option<Scene> {
        let mut s = *scene;
        if self.path == "grains.radius" {
            s.set_number("grains.radius_1", v).ok()?;
            s.set_number("grains.radius_2", v).ok()?;
        } else {
            s.set_number(self.path, v).ok()?;
        }
        Some(s)
    }
}

/// What the worker is asked to compute.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Request {
    /// Increases with every request; results of older requests are dropped.
    pub generation: u64,
    /// The scene.
    pub scene: Scene,
    /// Accuracy level.
    pub accuracy: Accuracy,
    /// Index into [`SWEEPS`].
    pub sweep: usize,
    /// Upper end of both stick-map axes \[m/s\], or `None` for automatic.
    pub map_max: Option<f64>,
}

/// One member of the family of curves.
#[derive(Debug, Clone, PartialEq)]
pub struct Member {
    /// Value of the swept parameter.
    pub value: f64,
    /// ε_N at the curve speeds (0 when stuck, NaN when it could not be computed).
    pub eps: Vec<f64>,
}

/// Everything one frame shows.
#[derive(Debug, Clone, PartialEq)]
pub struct FrameData {
    /// The request's generation.
    pub generation: u64,
    /// The scene the data belong to.
    pub scene: Scene,
    /// Accuracy used.
    pub accuracy: Accuracy,
    /// Index into [`SWEEPS`].
    pub sweep: usize,
    /// Derived constants (None if the scene cannot be evaluated).
    pub contact: Option<Contact>,
    /// Log-spaced impact speeds \[m/s\].
    pub g: Vec<f64>,
    /// The current scene's result at each speed (None where it failed).
    pub current: Vec<Option<Normal>>,
    /// ε_N of the clean surface (no layer, no adhesion), when the scene has a layer or adhesion.
    pub clean: Option<Vec<f64>>,
    /// The family of curves.
    pub family: Vec<Member>,
    /// The stick map (None without friction).
    pub map: Option<StickMap>,
    /// Upper end of the stick map's axes \[m/s\].
    pub map_max: f64,
    /// A problem to show (e.g. the contact could not be derived).
    pub error: Option<String>,
    /// Notes to show beside the views (e.g. a range cut to the speed limit).
    pub notes: Vec<String>,
    /// Wall time of the computation.
    pub elapsed: Duration,
}

/// The chart's decades (the one range policy of [`rime_core::explorer::range`]).
pub fn speed_range(contact: Option<&Contact>) -> (i32, i32) {
    rime_core::explorer::range::chart_decades(contact)
}

fn eps_curve(
    scene: &Scene,
    g: &[f64],
    accuracy: Accuracy,
    cancelled: &dyn Fn() -> bool,
) -> Option<Vec<f64>> {
    let Ok(contact) = Contact::new(scene) else {
        return Some(vec![f64::NAN; g.len()]);
    };
    let mut out = Vec::with_capacity(g.len());
    for (k, &gi) in g.iter().enumerate() {
        if k % 32 == 31 && cancelled() {
            return None;
        }
        out.push(contact.normal(gi, accuracy).map_or(f64::NAN, |n| n.eps));
    }
    Some(out)
}

/// Computes a frame. Returns `None` as soon as `cancelled()` says a newer request is waiting
/// (checked between curves and every few points).
pub fn compute(req: &Request, cancelled: &dyn Fn() -> bool) -> Option<FrameData> {
    let start = Instant::now();
    let scene = req.scene;
    let sweep = SWEEPS.get(req.sweep).copied().unwrap_or(SWEEPS[3]);
    let contact = Contact::new(&scene);
    let (lo, hi) = speed_range(contact.as_ref().ok());
    let mut g = vec![0.0; CURVE_POINTS];
    log_space(10f64.powi(lo), 10f64.powi(hi), &mut g);
    let mut data = FrameData {
        generation: req.generation,
        scene,
        accuracy: req.accuracy,
        sweep: req.sweep,
        contact: contact.as_ref().ok().copied(),
        g,
        current: vec![None; CURVE_POINTS],
        clean: None,
        family: Vec::new(),
        map: None,
        map_max: req.map_max.unwrap_or(1.0),
        error: None,
        notes: Vec::new(),
        elapsed: Duration::ZERO,
    };
    let contact = match contact {
        Ok(c) => c,
        Err(e) => {
            data.error = Some(e.to_string());
            data.elapsed = start.elapsed();
            return Some(data);
        }
    };
    for (k, &gi) in data.g.iter().enumerate() {
        if k % 32 == 31 && cancelled() {
            return None;
        }
        data.current[k] = contact.normal(gi, req.accuracy).ok();
    }
    if scene.layer.is_some() || scene.adhesion.is_some() {
        let clean = Scene {
            layer: None,
            adhesion: None,
            ..scene
        };
        data.clean = Some(eps_curve(&clean, &data.g, req.accuracy, cancelled)?);
    }
    if sweep.available(&scene) {
        for v in sweep.values(&scene) {
            if cancelled() {
                return None;
            }
            if let Some(s) = sweep.apply(&scene, v) {
                let eps = eps_curve(&s, &data.g, req.accuracy, cancelled)?;
                data.family.push(Member { value: v, eps });
            }
        }
    }
    if cancelled() {
        return None;
    }
    data.map_max = match req.map_max {
        Some(max) => max,
        None => {
            let range = rime_core::explorer::range::auto_map_range(&contact);
            data.notes.extend(range.note().map(String::from));
            range.max
        }
    };
    if contact.friction.is_some() {
        match StickMap::new(&contact, data.map_max, MAP_POINTS, req.accuracy) {
            Ok(m) => data.map = Some(m),
            Err(e) => data.error = Some(format!("stick map: {e}")),
        }
    }
    data.elapsed = start.elapsed();
    Some(data)
}
