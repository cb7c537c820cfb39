//! Records: the one CSV contract of every surface (docs/cli.md#records).
//!
//! `rime curve --format csv`, `rime map --format csv`, the terminal's `x` export and the web page's
//! downloads all write these functions' output, so the same scene, speeds and level give the same
//! bytes everywhere (an end-to-end test compares them). Numbers are [`cell`]: the shortest text
//! that reads back to the same double; column names are the JSON field names with units in
//! brackets. Downloads and exports put [`context`] (`# ` lines: version, level, scene, citation)
//! before the header, so a file can be reproduced from itself; the command line leaves it out
//! (pipes want bare CSV), and readers skip it with `comment="#"`.

use super::frame::{Frame, SWEEPS};
use crate::figure::sweep::StickMap;
use crate::normal::Normal;
use crate::scene::params::{PARAMETERS, Value};
use alloc::format;
use alloc::string::String;
use core::fmt::Write as _;

/// Header of ε_N records (`rime eps`, `rime curve`, the explorer's curve).
pub const CURVE_HEADER: [&str; 6] = [
    "g_n [m/s]",
    "eps_n",
    "status",
    "t_c [s]",
    "xi_max [m]",
    "error_estimate",
];

/// Header of tangential records (`rime tangential`).
pub const TANGENTIAL_HEADER: [&str; 5] = ["g_n [m/s]", "g_t [m/s]", "eps_t", "eps_n", "class"];

/// One normal-restitution record (`rime eps`, `rime curve`, the explorer's curve): the JSON object
/// (field names are a contract, docs/cli.md) and the CSV row ([`CURVE_HEADER`]).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct EpsRecord {
    /// Impact speed \[m/s\].
    pub g_n: f64,
    /// ε_N.
    pub eps_n: f64,
    /// `rebound`, `stuck_in_layer`, `stuck_by_adhesion` or `overdamped`.
    pub status: &'static str,
    /// Contact duration \[s\]; `null` when the grains stick (they come to rest asymptotically).
    pub t_c: Option<f64>,
    /// Maximum compression \[m\].
    pub xi_max: f64,
    /// Bound on the relative error of `eps_n` at the chosen accuracy; `null` where ε_N < 1e-6,
    /// outside the bound's domain.
    pub error_estimate: Option<f64>,
}

impl EpsRecord {
    /// The record of a core result at impact speed `g_n`.
    pub fn new(g_n: f64, n: &Normal) -> Self {
        EpsRecord {
            g_n,
            eps_n: n.eps,
            status: n.status.name(),
            t_c: n.t_c.is_finite().then_some(n.t_c),
            xi_max: n.xi_max,
            error_estimate: n.error_estimate.is_finite().then_some(n.error_estimate),
        }
    }

    /// Its CSV cells, in the order of [`CURVE_HEADER`].
    pub fn cells(&self) -> [String; 6] {
        let opt = |v: Option<f64>| v.map(cell).unwrap_or_default();
        [
            cell(self.g_n),
            cell(self.eps_n),
            self.status.into(),
            opt(self.t_c),
            cell(self.xi_max),
            opt(self.error_estimate),
        ]
    }
}

/// One tangential record (`rime tangential`): JSON object and CSV row ([`TANGENTIAL_HEADER`]).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct TangentialRecord {
    /// Normal impact speed \[m/s\].
    pub g_n: f64,
    /// Tangential speed \[m/s\].
    pub g_t: f64,
    /// ε_T.
    pub eps_t: f64,
    /// ε_N(g_N).
    pub eps_n: f64,
    /// Stick-map class (docs/physics.md#decision-7).
    pub class: &'static str,
}

impl TangentialRecord {
    /// The record of a core result at `(g_n, g_t)`.
    pub fn new(g_n: f64, g_t: f64, t: &crate::Tangential) -> Self {
        TangentialRecord {
            g_n,
            g_t,
            eps_t: t.eps_t,
            eps_n: t.eps_n,
            class: t.class.name(),
        }
    }

    /// Its CSV cells, in the order of [`TANGENTIAL_HEADER`].
    pub fn cells(&self) -> [String; 5] {
        [
            cell(self.g_n),
            cell(self.g_t),
            cell(self.eps_t),
            cell(self.eps_n),
            self.class.into(),
        ]
    }
}

/// A stick map as one JSON object (`rime map`; its CSV is [`map_csv`]).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct MapRecord {
    /// Grid speeds \[m/s\], 0 to max inclusive.
    pub g: alloc::vec::Vec<f64>,
    /// `class[i][j]` at g_N = `g[i]`, g_T = `g[j]`.
    pub class: alloc::vec::Vec<alloc::vec::Vec<&'static str>>,
    /// `eps_t[i][j]` at g_N = `g[i]`, g_T = `g[j]`.
    pub eps_t: alloc::vec::Vec<alloc::vec::Vec<f64>>,
    /// ε_N at `g[i]`.
    pub eps_n: alloc::vec::Vec<f64>,
}

/// Header of comparison records (`rime compare`).
pub const COMPARE_HEADER: [&str; 4] = ["model", "g_n [m/s]", "eps_n", "status"];
/// Header of characteristic-speed records (`rime compare`).
pub const SPEED_HEADER: [&str; 4] = ["model", "name", "value [m/s]", "status"];

/// ε_N of one model or measured law at one speed (`rime compare`).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct CompareRecord {
    /// The model's name or the atlas law's id.
    pub model: &'static str,
    /// Impact speed \[m/s\].
    pub g_n: f64,
    /// ε_N.
    pub eps_n: f64,
    /// The model's status, or `measured` / `extrapolated` for a law.
    pub status: &'static str,
}

impl CompareRecord {
    /// Its CSV cells, in the order of [`COMPARE_HEADER`].
    pub fn cells(&self) -> [String; 4] {
        [
            self.model.into(),
            cell(self.g_n),
            cell(self.eps_n),
            self.status.into(),
        ]
    }
}

/// A model's characteristic speed (`g_cr`, `v_yield`, …) or a law's measured range
/// (`rime compare`).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SpeedRecord {
    /// The model's name or the atlas law's id.
    pub model: &'static str,
    /// The speed's name.
    pub name: &'static str,
    /// The speed \[m/s\]; `None` (JSON null, an empty cell) where a physical status stands in its
    /// place.
    pub value: Option<f64>,
    /// `value`, or `always_sticks` (g_cr: the grains stick at every accepted speed).
    pub status: &'static str,
}

impl SpeedRecord {
    /// Its CSV cells, in the order of [`SPEED_HEADER`].
    pub fn cells(&self) -> [String; 4] {
        [
            self.model.into(),
            self.name.into(),
            self.value.map(cell).unwrap_or_default(),
            self.status.into(),
        ]
    }
}

/// `rime compare`'s output: every model's and law's ε_N at every speed, then their
/// characteristic speeds (JSON `{"records": […], "characteristic_speeds": […]}`; CSV: the two
/// tables one after the other, a blank line between).
#[derive(Debug, Clone, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct CompareOutput {
    /// ε_N of each model or law at each speed, model by model.
    pub records: alloc::vec::Vec<CompareRecord>,
    /// The models' characteristic speeds and the laws' measured ranges.
    pub characteristic_speeds: alloc::vec::Vec<SpeedRecord>,
}

impl CompareOutput {
    /// Both tables as CSV, each with its header ([`COMPARE_HEADER`], [`SPEED_HEADER`]).
    pub fn csv(&self) -> String {
        let mut s = COMPARE_HEADER.join(",") + "\n";
        for r in &self.records {
            s.push_str(&(r.cells().join(",") + "\n"));
        }
        s.push('\n');
        s.push_str(&(SPEED_HEADER.join(",") + "\n"));
        for c in &self.characteristic_speeds {
            s.push_str(&(c.cells().join(",") + "\n"));
        }
        s
    }
}

/// One collision as `rime collision` writes it in JSON (field names are a contract, docs/cli.md):
/// the trajectory's samples, phases, ending and energy ledger, and with a tangential speed the
/// oblique impact's tangential side.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct CollisionRecord<'a> {
    /// Normal impact speed \[m/s\].
    pub g: f64,
    /// Sample times \[s\].
    pub t: &'a [f64],
    /// Overlap ξ \[m\].
    pub xi: &'a [f64],
    /// ξ' \[m/s\].
    pub xi_dot: &'a [f64],
    /// Normal force \[N\].
    pub force: &'a [f64],
    /// The named instants.
    pub phases: &'a [crate::collision::Phase],
    /// Contact duration \[s\]; `null` when the grains stick.
    pub t_c: Option<f64>,
    /// Maximum compression \[m\].
    pub xi_max: f64,
    /// ε_N.
    pub eps_n: f64,
    /// How the collision ended.
    pub status: &'static str,
    /// Whether the contact ended inside the integration.
    pub resolved: bool,
    /// Where the impact energy went \[J\] (closure: relative).
    pub ledger: crate::collision::Ledger,
    /// The tangential side of an oblique impact (`--gt`).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub tangential: Option<ObliqueRecord>,
}

impl<'a> CollisionRecord<'a> {
    /// The record of trajectory `t` at impact speed `g`, with the oblique impact's side if any.
    pub fn new(
        g: f64,
        t: &'a crate::collision::Trajectory,
        oblique: Option<&crate::collision::Oblique>,
    ) -> Self {
        CollisionRecord {
            g,
            t: &t.t,
            xi: &t.xi,
            xi_dot: &t.xi_dot,
            force: &t.force,
            phases: &t.phases,
            t_c: t.t_c.is_finite().then_some(t.t_c),
            xi_max: t.xi_max,
            eps_n: t.eps_n,
            status: t.status.name(),
            resolved: t.resolved,
            ledger: t.ledger,
            tangential: oblique.map(ObliqueRecord::new),
        }
    }
}

/// The tangential side of an oblique impact in a [`CollisionRecord`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ObliqueRecord {
    /// ε_T of Eq. (26).
    pub eps_t: f64,
    /// The stick-map class.
    pub class: &'static str,
    /// Tangential kinetic energy before \[J\].
    pub energy_before: f64,
    /// After \[J\].
    pub energy_after: f64,
    /// Work of the friction impulse \[J\].
    pub friction_work: f64,
    /// Change of each grain's spin \[rad/s\].
    pub spin_change: [f64; 2],
}

impl ObliqueRecord {
    /// The record of an oblique impact's tangential side.
    pub fn new(o: &crate::collision::Oblique) -> Self {
        ObliqueRecord {
            eps_t: o.eps_t,
            class: o.class.name(),
            energy_before: o.energy_before,
            energy_after: o.energy_after,
            friction_work: o.friction_work,
            spin_change: o.spin_change,
        }
    }
}

/// One entry of the data atlas as `rime data` lists it (field names are a contract, docs/cli.md).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct AtlasRecord {
    /// The entry's id.
    pub id: &'static str,
    /// `law`, `range` or `threshold`.
    pub kind: &'static str,
    /// The source.
    pub citation: crate::data::atlas::Citation,
    /// What was measured.
    pub material: &'static str,
    /// The law as published.
    pub formula: &'static str,
    /// Units of the formula.
    pub units: &'static str,
    /// Measured impact speeds \[m/s\].
    pub valid_speed: [f64; 2],
    /// Grain radii \[m\].
    pub radius: [f64; 2],
    /// Temperatures \[K\].
    pub temperature: [f64; 2],
    /// The experiment's geometry.
    pub geometry: &'static str,
    /// How the law is clamped.
    pub clamp: &'static str,
    /// Where in the source.
    pub source: &'static str,
    /// What was checked against the source.
    pub verified: &'static str,
    /// Entries it disagrees with.
    pub conflicts_with: &'static str,
}

impl AtlasRecord {
    /// The record of an atlas entry.
    pub fn new(e: &crate::data::atlas::Entry) -> Self {
        AtlasRecord {
            id: e.id,
            kind: e.kind.name(),
            citation: e.citation,
            material: e.material,
            formula: e.formula,
            units: e.units,
            valid_speed: e.valid_speed,
            radius: e.radius,
            temperature: e.temperature,
            geometry: e.geometry.name(),
            clamp: e.clamp,
            source: e.source,
            verified: e.verified,
            conflicts_with: e.conflicts_with,
        }
    }
}

/// Header of a measured law's records (`rime data --law`).
pub const LAW_HEADER: [&str; 3] = ["g_n [m/s]", "eps_n", "extrapolated"];

/// A measured law at one speed (`rime data --law`).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct LawRecord {
    /// Impact speed \[m/s\].
    pub g_n: f64,
    /// ε_N of the law.
    pub eps_n: f64,
    /// Whether `g_n` lies outside the speeds the law was measured at.
    pub extrapolated: bool,
}

impl LawRecord {
    /// The record of a law's evaluation.
    pub fn new(e: &crate::data::atlas::Evaluation) -> Self {
        LawRecord {
            g_n: e.g,
            eps_n: e.eps,
            extrapolated: e.extrapolated,
        }
    }

    /// Its CSV cells, in the order of [`LAW_HEADER`].
    pub fn cells(&self) -> [String; 3] {
        [
            cell(self.g_n),
            cell(self.eps_n),
            alloc::string::ToString::to_string(&self.extrapolated),
        ]
    }
}

/// One sticking threshold as `rime stick` writes it in JSON (field names are a contract,
/// docs/cli.md).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct StickRecord {
    /// Grain radius \[m\].
    pub radius: f64,
    /// Temperature \[K\].
    pub temperature: f64,
    /// γ(T) as the source gives it \[J/m²\].
    pub gamma_source: f64,
    /// The paper's γ used in Eq. (12) and (15) \[J/m²\].
    pub gamma: f64,
    /// How γ(T) was read.
    pub convention: &'static str,
    /// Eq. (15) alone \[m/s\].
    pub v_elastic: f64,
    /// The full model's sticking threshold \[m/s\]; `null` when the grains stick at every speed.
    pub v_stick: Option<f64>,
    /// The scene's damping time used by `v_stick` \[s\].
    pub damping_time: f64,
    /// The measured threshold where the row lies in its measured regime \[m/s\].
    pub measured_v_stick: Option<f64>,
}

impl StickRecord {
    /// The record of threshold `t` of a table with `damping_time`, read with `convention`; with
    /// the measured µm-ice threshold where `t` lies inside the measurement's radii and
    /// temperatures (the atlas' `gundlach2015`).
    pub fn new(
        t: &crate::applications::stick::Threshold,
        convention: crate::applications::stick::Convention,
        damping_time: f64,
    ) -> Self {
        let measured = crate::applications::stick::in_measured_regime(t);
        StickRecord {
            radius: t.radius,
            temperature: t.temperature,
            gamma_source: t.gamma_source,
            gamma: t.gamma,
            convention: convention.name(),
            v_elastic: t.v_elastic,
            v_stick: t.v_stick,
            damping_time,
            measured_v_stick: measured.then_some(crate::applications::stick::MEASURED_UM_ICE),
        }
    }
}

/// One fitted parameter in a [`FitRecord`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FitParamRecord {
    /// The parameter's path.
    pub param: &'static str,
    /// Its fitted value (SI).
    pub value: f64,
    /// Its SI unit.
    pub unit: &'static str,
    /// Its standard error; `null` where the fit cannot give one.
    pub standard_error: Option<f64>,
}

/// A fit of the scene to data as `rime fit` writes it in JSON (field names are a contract,
/// docs/cli.md). With one parameter its fields are repeated at the top level.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FitRecord<'a> {
    /// What was fitted to (the file or the law).
    pub source: &'a str,
    /// The fitted parameters.
    pub params: alloc::vec::Vec<FitParamRecord>,
    /// Their correlation matrix, where the fit gives one.
    pub correlation: &'a Option<alloc::vec::Vec<alloc::vec::Vec<f64>>>,
    /// Root-mean-square residual of ε.
    pub rms_error: f64,
    /// χ² per degree of freedom (unscaled without uncertainties).
    pub reduced_chi2: f64,
    /// Degrees of freedom.
    pub dof: usize,
    /// Data points.
    pub points: usize,
    /// Whether the data's σ column weighted the fit.
    pub weighted: bool,
    /// The data file's header line.
    pub header: &'a Option<String>,
    /// The unit the speeds were read in.
    pub g_unit: &'a str,
    /// Whether that unit was assumed (no unit in the header).
    pub g_unit_assumed: bool,
    /// Misfit warnings.
    pub warnings: &'a [String],
    /// Residuals ε_data − ε_fit.
    pub residuals: &'a [f64],
    /// The runs test on the residuals' signs.
    pub runs_test: Option<crate::fit::scene::RunsTest>,
    /// Whether χ² is scaled by the data's uncertainties.
    pub chi2_scaled: bool,
    /// The fitted scene.
    pub scene: crate::Scene,
    /// The one parameter's fields at the top level (a fit of one parameter).
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub single: Option<FitParamRecord>,
}

impl<'a> FitRecord<'a> {
    /// The record of fit `f` of `points` to `source`.
    pub fn new(
        f: &'a crate::fit::scene::SceneFit,
        points: &'a crate::fit::scene::Points,
        source: &'a str,
    ) -> Self {
        let params: alloc::vec::Vec<FitParamRecord> = f
            .params
            .iter()
            .map(|p| FitParamRecord {
                param: p.path,
                value: p.value,
                unit: p.unit,
                standard_error: p.standard_error,
            })
            .collect();
        let single = match params.as_slice() {
            [one] => Some(*one),
            _ => None,
        };
        FitRecord {
            source,
            params,
            correlation: &f.correlation,
            rms_error: f.rms_error,
            reduced_chi2: f.reduced_chi2,
            dof: f.dof,
            points: points.g.len(),
            weighted: f.weighted,
            header: &points.header,
            g_unit: points.g_unit.as_deref().unwrap_or("m/s"),
            g_unit_assumed: points.g_unit.is_none(),
            warnings: &f.warnings,
            residuals: &f.residuals,
            runs_test: f.runs_test,
            chi2_scaled: f.weighted,
            scene: f.scene,
            single,
        }
    }
}

/// Header of the tidal appendix's records (`rime tidal`).
pub const TIDAL_HEADER: [&str; 3] = ["name", "value", "unit"];

/// The tidal appendix (Eq. (A.1)–(A.7)) of one input as `rime tidal` writes it: its named values
/// with their units (the CSV rows and the JSON fields), whether the pair stays in contact, and the
/// verdict.
#[derive(Debug, Clone, PartialEq)]
pub struct TidalRecord {
    /// `(name, value, unit)`; `None` where the appendix has no value (no `r_max`).
    pub values: alloc::vec::Vec<(&'static str, Option<f64>, &'static str)>,
    /// Whether the surface force holds the pair together (Eq. (A.4)).
    pub stays_in_contact: bool,
    /// The verdict in words.
    pub verdict: String,
}

impl TidalRecord {
    /// The record of `input` and its result `t`.
    pub fn new(
        input: &crate::applications::tidal::TidalInput,
        t: &crate::applications::tidal::Tidal,
    ) -> Self {
        TidalRecord {
            values: alloc::vec![
                ("planet_mass", Some(input.planet_mass), "kg"),
                ("distance", Some(input.distance), "m"),
                ("radius", Some(input.radius), "m"),
                ("density", Some(input.density), "kg/m³"),
                ("surface_energy", Some(input.surface_energy), "J/m²"),
                ("grain_mass", Some(t.mass), "kg"),
                ("delta_f", Some(t.delta_f), "N"),
                ("delta_f_approx", Some(t.delta_f_approx), "N"),
                ("surface_force", Some(t.surface_force), "N"),
                ("surface_force_paper", Some(t.surface_force_paper), "N"),
                ("gravity", Some(t.gravity), "N"),
                ("d_roche", Some(t.d_roche), "m"),
                ("d_min", Some(t.d_min), "m"),
                ("r_max", t.r_max, "m"),
                // The core's verdict: above 1 the pair stays in contact (Eq. (A.4)).
                ("hold_margin", Some(t.margin()), ""),
            ],
            stays_in_contact: t.holds(),
            verdict: t.verdict(),
        }
    }

    /// The CSV rows, in the order of [`TIDAL_HEADER`] (an empty cell where there is no value).
    pub fn rows(&self) -> alloc::vec::Vec<[String; 3]> {
        self.values
            .iter()
            .map(|(k, v, u)| [(*k).into(), v.map(cell).unwrap_or_default(), (*u).into()])
            .collect()
    }
}

/// JSON: one object, every value by its name (`null` where there is none), then
/// `stays_in_contact` and `verdict`.
#[cfg(feature = "serde")]
impl serde::Serialize for TidalRecord {
    fn serialize<S: serde::Serializer>(&self, s: S) -> core::result::Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut m = s.serialize_map(Some(self.values.len() + 2))?;
        for (k, v, _) in &self.values {
            m.serialize_entry(k, v)?;
        }
        m.serialize_entry("stays_in_contact", &self.stays_in_contact)?;
        m.serialize_entry("verdict", &self.verdict)?;
        m.end()
    }
}

/// A ring's equilibrium as `rime ring` writes it (field names are a contract, docs/cli.md): the
/// named values with their units (`smooth.*`, `rough.*` for the two predictions), the verdicts,
/// and the note on a damping time set for another grain size.
#[derive(Debug, Clone, PartialEq)]
pub struct RingOutput {
    /// `(name, value, unit)`; `None` where there is no value.
    pub values: alloc::vec::Vec<(String, Option<f64>, &'static str)>,
    /// `(name, word)`: the verdict, each prediction's, and which prediction applies.
    pub verdicts: [(&'static str, &'static str); 4],
    /// Whether the ring reaches a steady state (an equilibrium or the monolayer floor).
    pub equilibrium: bool,
    /// The verdict in words.
    pub verdict_words: &'static str,
    /// What A describes when it was set for, or scaled from, another grain size.
    pub damping_note: Option<String>,
    /// The ring's kinematic viscosity (issue 38), when added by [`RingOutput::with_viscosity`]:
    /// its numbers are also in `values` as `viscosity.*`.
    pub viscosity: Option<crate::applications::ring_sizes::Viscosity>,
}

impl RingOutput {
    /// The output of `rec` with its damping note.
    pub fn new(rec: &crate::applications::ring::RingRecord, damping_note: Option<String>) -> Self {
        let p = rec.prediction();
        let mut values: alloc::vec::Vec<(String, Option<f64>, &'static str)> = alloc::vec![
            ("tau".into(), Some(rec.tau), "1"),
            ("omega".into(), Some(rec.omega), "1/s"),
            ("radius".into(), Some(rec.radius), "m"),
            ("eps_cr_dilute".into(), Some(rec.eps_cr), "1"),
            ("eps_cr".into(), Some(p.eps_cr), "1"),
            (
                "velocity_dispersion".into(),
                Some(p.velocity_dispersion),
                "m/s"
            ),
            (
                "velocity_dispersion_r_omega".into(),
                Some(p.velocity_dispersion / (rec.radius * rec.omega)),
                "1",
            ),
            ("thickness".into(), Some(p.thickness), "m"),
            ("mean_impact_speed".into(), Some(p.mean_impact_speed), "m/s"),
            ("eps_effective".into(), Some(p.eps_effective), "1"),
            (
                "equilibration_orbits".into(),
                Some(p.equilibration_orbits),
                "orbits"
            ),
            ("floor_dispersion".into(), Some(rec.floor_dispersion), "m/s"),
            ("damping_time".into(), Some(rec.damping_time), "s"),
            ("scaled_damping_time".into(), rec.scaled_damping_time, "s"),
        ];
        for (label, pred) in [("smooth", &rec.smooth), ("rough", &rec.rough)] {
            let fields: [(&str, f64, &'static str); 7] = [
                ("velocity_dispersion", pred.velocity_dispersion, "m/s"),
                ("thickness", pred.thickness, "m"),
                ("mean_impact_speed", pred.mean_impact_speed, "m/s"),
                ("eps_effective", pred.eps_effective, "1"),
                ("eps_cr", pred.eps_cr, "1"),
                ("sticking_fraction", pred.sticking_fraction, "1"),
                ("equilibration_orbits", pred.equilibration_orbits, "orbits"),
            ];
            for (k, v, u) in fields {
                values.push((format!("{label}.{k}"), Some(v), u));
            }
        }
        RingOutput {
            values,
            verdicts: [
                ("verdict", p.verdict.name()),
                ("smooth.verdict", rec.smooth.verdict.name()),
                ("rough.verdict", rec.rough.verdict.name()),
                ("prediction", if rec.friction { "rough" } else { "smooth" }),
            ],
            equilibrium: p.verdict.is_equilibrium(),
            verdict_words: p.verdict.words(),
            damping_note,
            viscosity: None,
        }
    }

    /// With the ring's viscosity `v` (`viscosity.translational`, `.collisional`, `.total` in m²/s,
    /// `.dlnnu_dlntau`, and the word `.overstability`), as a ring of many sizes writes it.
    pub fn with_viscosity(mut self, v: crate::applications::ring_sizes::Viscosity) -> Self {
        for (k, x, u) in [
            ("translational", v.translational, "m²/s"),
            ("collisional", v.collisional, "m²/s"),
            ("total", v.total, "m²/s"),
            ("dlnnu_dlntau", v.dlnnu_dlntau, "1"),
        ] {
            self.values.push((format!("viscosity.{k}"), Some(x), u));
        }
        self.viscosity = Some(v);
        self
    }
}

/// JSON: the top-level values and verdicts by name, `smooth` and `rough` as nested objects, then
/// `damping_note`, `equilibrium` and `verdict_words`.
#[cfg(feature = "serde")]
impl serde::Serialize for RingOutput {
    fn serialize<S: serde::Serializer>(&self, s: S) -> core::result::Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        struct Nested<'a>(alloc::vec::Vec<(&'a str, Value<'a>)>);
        enum Value<'a> {
            Number(Option<f64>),
            Word(&'a str),
        }
        impl serde::Serialize for Value<'_> {
            fn serialize<S: serde::Serializer>(
                &self,
                s: S,
            ) -> core::result::Result<S::Ok, S::Error> {
                match self {
                    Value::Number(v) => v.serialize(s),
                    Value::Word(w) => w.serialize(s),
                }
            }
        }
        impl serde::Serialize for Nested<'_> {
            fn serialize<S: serde::Serializer>(
                &self,
                s: S,
            ) -> core::result::Result<S::Ok, S::Error> {
                let mut m = s.serialize_map(Some(self.0.len()))?;
                for (k, v) in &self.0 {
                    m.serialize_entry(k, v)?;
                }
                m.end()
            }
        }
        let entries = self
            .values
            .iter()
            .map(|(k, v, _)| (k.as_str(), Value::Number(*v)))
            .chain(self.verdicts.iter().map(|(k, w)| (*k, Value::Word(w))));
        let mut top = alloc::vec::Vec::new();
        let mut nested = [
            ("smooth", Nested(alloc::vec::Vec::new())),
            ("rough", Nested(alloc::vec::Vec::new())),
            ("viscosity", Nested(alloc::vec::Vec::new())),
        ];
        for (k, v) in entries {
            match k.split_once('.') {
                Some((outer, inner)) => {
                    if let Some((_, n)) = nested.iter_mut().find(|(n, _)| *n == outer) {
                        n.0.push((inner, v));
                    }
                }
                None => top.push((k, v)),
            }
        }
        let mut m = s.serialize_map(None)?;
        for (k, v) in &top {
            m.serialize_entry(k, v)?;
        }
        if let Some(v) = &self.viscosity {
            nested[2]
                .1
                .0
                .push(("overstability", Value::Word(v.overstability)));
        }
        for (k, n) in &nested {
            if !n.0.is_empty() {
                m.serialize_entry(k, n)?;
            }
        }
        m.serialize_entry("damping_note", &self.damping_note)?;
        m.serialize_entry("equilibrium", &self.equilibrium)?;
        m.serialize_entry("verdict_words", &self.verdict_words)?;
        m.end()
    }
}

/// Header of stick-map records (`rime map`, the explorer's map).
pub const MAP_HEADER: [&str; 4] = ["g_n [m/s]", "g_t [m/s]", "eps_t", "class"];

/// What each file of records holds: the first context line of a download or export.
pub const CURVE_WHAT: &str = "ε_N records of this scene (rime curve)";
/// See [`CURVE_WHAT`].
pub const FAMILY_WHAT: &str = "every ε_N curve of the chart";
/// See [`CURVE_WHAT`].
pub const MAP_WHAT: &str = "stick-map records (rime map); class sliding_gap is an artifact of the printed Eq. (23), not a regime (docs/physics.md#decision-6)";

/// The paper every record comes from.
pub const CITATION: &str = "J.-M. Hertzsch (2002), A model for surface effects in slow collisions of icy grains, Planet. Space Sci. 50, 1387";

/// A number in a record: the shortest form that reads back to the same double (`0`, `0.01`, `1`,
/// `1e-5`, `2.5e-12`; never `0e0`), by the one rule of [`super::format::shortest`] (plain between
/// 1e-4 and 1e6, scientific outside); empty for a value that is not finite (a record never holds
/// `NaN`).
pub fn cell(v: f64) -> String {
    if !v.is_finite() {
        String::new()
    } else if v == 0.0 {
        "0".into()
    } else {
        super::format::shortest(v)
    }
}

/// The cells of one ε_N record at speed `g`: `status` is `error` and the numbers empty where the
/// point could not be computed. `t_c` is empty where the grains stick (they come to rest
/// asymptotically).
pub fn curve_cells(g: f64, normal: Option<&Normal>) -> [String; 6] {
    match normal {
        Some(n) => EpsRecord::new(g, n).cells(),
        None => [
            cell(g),
            String::new(),
            "error".into(),
            String::new(),
            String::new(),
            String::new(),
        ],
    }
}

fn line(s: &mut String, cells: &[String]) {
    s.push_str(&cells.join(","));
    s.push('\n');
}

/// ε_N records on speeds `g` (header, then one line per speed).
pub fn curve_csv(g: &[f64], points: &[Option<Normal>]) -> String {
    let mut s = String::new();
    s.push_str(&CURVE_HEADER.join(","));
    s.push('\n');
    for (k, &gk) in g.iter().enumerate() {
        line(
            &mut s,
            &curve_cells(gk, points.get(k).and_then(|p| p.as_ref())),
        );
    }
    s
}

/// Stick-map records, row-major: g_N outer, g_T inner (header, then one line per cell).
pub fn map_csv(map: &StickMap) -> String {
    let n = map.n();
    let mut s = String::new();
    s.push_str(&MAP_HEADER.join(","));
    s.push('\n');
    for i in 0..n {
        for j in 0..n {
            let k = i * n + j;
            let (Some(c), Some(e)) = (map.class.get(k), map.eps_t.get(k)) else {
                continue;
            };
            let _ = writeln!(
                s,
                "{},{},{},{}",
                cell(map.g[i]),
                cell(map.g[j]),
                cell(*e),
                c.name()
            );
        }
    }
    s
}

/// The frame's ε_N curve as records ([`curve_csv`] on the frame's speeds).
pub fn frame_curve_csv(frame: &Frame) -> String {
    let none = alloc::vec![None; frame.g.len()];
    let points = frame.curve.as_ref().map_or(&none[..], |c| &c.points[..]);
    curve_csv(&frame.g, points)
}

/// The frame's stick map as records, or `None` without one (no friction, or the map failed).
pub fn frame_map_csv(frame: &Frame) -> Option<String> {
    frame.map.as_ref().and_then(|m| m.map.as_ref()).map(map_csv)
}

/// Every ε_N curve of the frame side by side: `g_n [m/s]`, `eps_n` (this scene), `eps_n clean`
/// (without layer and adhesion, when the scene has either), one `eps_n [p=v]` column per family
/// member (`this scene` marked) and one `eps_n:KEY` per overlay drawn on the frame's speeds
/// ([`overlay_column`]). Empty cells where a value is missing.
pub fn family_csv(frame: &Frame) -> String {
    family_csv_pinned(frame, None)
}

/// [`family_csv`] with the pinned curve a surface draws (the terminal's `P`, the page's pin) as
/// its last column, `eps_n [pinned: <label>]`: the table has every curve the figure draws.
pub fn family_csv_pinned(frame: &Frame, pinned: Option<&super::frame::Pinned>) -> String {
    family_csv_drawn(
        frame,
        &Drawn {
            pinned,
            ..Drawn::default()
        },
    )
}

/// What a surface draws on the ε_N chart beside the frame's own curves, for [`family_csv_drawn`].
#[derive(Debug, Clone, Default)]
pub struct Drawn<'a> {
    /// The pinned curve.
    pub pinned: Option<&'a super::frame::Pinned>,
    /// Whether the chart shows the experiments: the Bridges et al. 1984 law over its measured
    /// speeds when no comparison is on ([`crate::figure::experiments`]).
    pub experiments: bool,
    /// The ring card's ε_cr line (τ, ε_cr) when it is on the chart.
    pub ring_eps_cr: Option<(f64, f64)>,
}

/// A column of [`family_csv_drawn`]: its header, its speeds and its values at them.
type Column<'a> = (String, &'a [f64], alloc::borrow::Cow<'a, [f64]>);

/// Every ε_N curve the chart draws (issue 37 F2.5: the all-curves CSV left out the measured laws
/// and the ring's ε_cr line): [`family_csv`]'s columns, then each measured law drawn over its own
/// speeds (`eps_n:bridges1984`: a comparison, or the experiments' law), the pinned curve
/// (`eps_n [pinned: <label>]`) and the ring's line (`eps_cr [ring τ = 0.5]`, on every row inside
/// the frame's speeds). A curve over other speeds than the frame's has its speeds as rows of
/// their own, merged in order, with the other columns' cells empty there: nothing interpolated.
pub fn family_csv_drawn(frame: &Frame, drawn: &Drawn) -> String {
    let sweep = SWEEPS.get(frame.sweep).map_or("p", |s| s.symbol);
    let unit = SWEEPS.get(frame.sweep).map_or("", |s| s.unit);
    // Each column: header, speeds, values (ε_N at those speeds).
    let mut columns: alloc::vec::Vec<Column<'_>> = alloc::vec::Vec::new();
    let g: &[f64] = &frame.g;
    let nan = || alloc::borrow::Cow::Owned(alloc::vec![f64::NAN; g.len()]);
    columns.push((
        "eps_n".into(),
        g,
        frame.curve.as_ref().map_or_else(nan, |c| c.eps().into()),
    ));
    if let Some(clean) = frame.clean.as_ref() {
        columns.push(("eps_n clean surfaces".into(), g, clean.eps().into()));
    }
    for m in &frame.family {
        let Some(curve) = m.curve.as_ref() else {
            continue;
        };
        let mark = if m.is_scene { " (this scene)" } else { "" };
        let unit = if unit.is_empty() {
            String::new()
        } else {
            format!(" {unit}")
        };
        columns.push((
            format!("eps_n [{sweep} = {}{unit}]{mark}", cell(m.value)),
            g,
            curve.eps().into(),
        ));
    }
    // A measured range is a box, not a curve: its two corners are no ε_N at two speeds.
    for o in frame.overlays.iter().filter(|o| !o.band) {
        columns.push((
            overlay_column(&o.overlay),
            &o.g,
            alloc::borrow::Cow::Borrowed(&o.eps[..]),
        ));
    }
    // The experiments' law, as the chart draws it (only without comparisons), named as its
    // comparison is.
    let experiment = if drawn.experiments && frame.overlays.is_empty() {
        let (g0, g1) = (
            g.first().copied().unwrap_or(1e-7),
            g.last().copied().unwrap_or(10.0),
        );
        crate::figure::experiments::bridges_measured(g0, g1, 0)
    } else {
        None
    };
    let experiment_points: Option<(alloc::vec::Vec<f64>, alloc::vec::Vec<f64>)> =
        experiment.map(|s| s.points.iter().copied().unzip());
    if let Some((eg, ee)) = &experiment_points {
        columns.push((
            format!("eps_n:{}", crate::figure::experiments::BRIDGES_ID),
            eg,
            alloc::borrow::Cow::Borrowed(&ee[..]),
        ));
    }
    if let Some(p) = drawn.pinned {
        // A comma in the label would split the column.
        columns.push((
            format!("eps_n [pinned: {}]", p.label.replace(',', ";")),
            &p.g,
            alloc::borrow::Cow::Borrowed(&p.eps[..]),
        ));
    }
    let ring = drawn
        .ring_eps_cr
        .map(|(tau, eps_cr)| (format!("eps_cr [ring τ = {}]", cell(tau)), eps_cr));
    let mut s = String::from("g_n [m/s]");
    for (header, _, _) in &columns {
        let _ = write!(s, ",{header}");
    }
    if let Some((header, _)) = &ring {
        let _ = write!(s, ",{header}");
    }
    s.push('\n');
    // Rows: every column's speeds merged in order, one row per distinct speed; each column
    // advances past the speeds it has.
    let (lo, hi) = (
        g.first().copied().unwrap_or(f64::NAN),
        g.last().copied().unwrap_or(f64::NAN),
    );
    let mut at = alloc::vec![0usize; columns.len()];
    loop {
        let next = columns
            .iter()
            .zip(&at)
            .filter_map(|((_, cg, _), &k)| cg.get(k).copied())
            .fold(f64::INFINITY, f64::min);
        if next == f64::INFINITY {
            break;
        }
        s.push_str(&cell(next));
        for ((_, cg, eps), k) in columns.iter().zip(at.iter_mut()) {
            s.push(',');
            if cg.get(*k) == Some(&next) {
                if let Some(e) = eps.get(*k) {
                    s.push_str(&cell(*e));
                }
                *k += 1;
            }
        }
        if let Some((_, eps_cr)) = &ring {
            s.push(',');
            if (lo..=hi).contains(&next) {
                s.push_str(&cell(*eps_cr));
            }
        }
        s.push('\n');
    }
    s
}

/// The column of an overlay: `eps_n:` and its short key (`eps_n:brilliantov2007`,
/// `eps_n:bridges1984`), easy to index in pandas; the citation is on a `# ` context line.
pub fn overlay_column(overlay: &super::frame::Overlay) -> String {
    match overlay {
        super::frame::Overlay::Atlas(e) => format!("eps_n:{}", e.id),
        super::frame::Overlay::Model(m) => format!("eps_n:{}", m.name()),
    }
}

/// The scene as `path = value` pairs of its active parameters (numbers in SI, shortest form),
/// one line: what a reader needs to rebuild it with `rime --set`.
pub fn scene_line(scene: &crate::Scene) -> String {
    let mut parts = alloc::vec::Vec::new();
    for p in PARAMETERS {
        match scene.get(p.path) {
            Ok(Value::Number(v)) => parts.push(format!(
                "{}={}",
                p.path,
                crate::explorer::format::shortest(v)
            )),
            Ok(Value::Choice(c)) => parts.push(format!("{}={c}", p.path)),
            Ok(Value::Enabled(false)) => parts.push(format!("{}=off", p.path)),
            Ok(Value::Enabled(true)) | Ok(Value::Inactive) | Err(_) => {}
        }
    }
    parts.join(" ")
}

/// `# ` lines that make a downloaded file reproducible from itself: what it holds, the program
/// and version, the level, the scene, the date (given by the caller: the core has no clock) and
/// the citation.
pub fn context(frame: &Frame, what: &str, version: &str, date: &str) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# {what}");
    let _ = writeln!(
        s,
        "# rime {version}, level {}, {date}",
        frame.request.accuracy.name()
    );
    let _ = writeln!(s, "# scene: {}", scene_line(&frame.request.scene));
    let _ = writeln!(s, "# model: {CITATION}");
    // What each overlay column holds (the header carries only its short key).
    for o in frame.overlays.iter().filter(|o| o.g == frame.g) {
        let _ = writeln!(s, "# {}: {}", overlay_column(&o.overlay), o.label);
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells_read_back_to_the_same_double() {
        for v in [
            1e-5,
            0.01,
            1.0,
            2.5e-12,
            0.1 + 0.2,
            123456.789,
            1e6,
            999.9999,
            -3e-9,
        ] {
            let c = cell(v);
            assert_eq!(c.parse::<f64>().ok(), Some(v), "{c}");
        }
        assert_eq!(cell(0.0), "0");
        assert_eq!(cell(-0.0), "0");
        assert_eq!(cell(f64::NAN), "");
        assert_eq!(cell(f64::INFINITY), "");
        assert_eq!(cell(1e-5), "1e-5");
    }

    #[test]
    fn records_messages_and_labels_write_a_number_alike_issue_21() {
        // One rule: records, error messages and the explorer's shortest form agreed everywhere but
        // at 1e-4 ≤ |v| < 1e-3 before (records wrote 5e-4, messages 0.0005).
        for v in [
            5e-4,
            1e-4,
            9.99e-5,
            0.00123,
            1e6,
            999999.5,
            -2.5e-4,
            3.0000000000000003e-4,
        ] {
            let message = alloc::format!("{}", crate::error::Number(v));
            assert_eq!(cell(v), message, "{v}");
            assert_eq!(cell(v), super::super::format::shortest(v), "{v}");
            assert_eq!(cell(v).parse::<f64>().ok(), Some(v));
        }
    }

    #[test]
    fn overlay_columns_are_short_keys_with_the_citation_in_the_context_issue_22() {
        use crate::explorer::frame::{Overlay, Request, compute};
        let mut req = Request::new(crate::Preset::IceSticky.scene(), crate::Accuracy::Fast);
        req.points = 12;
        req.map_n = 3;
        req.overlays = ["model:brilliantov2007", "model:muller_poschel2011"]
            .iter()
            .map(|k| Overlay::parse(k).unwrap())
            .collect();
        let frame = compute(&req, &|| false).unwrap();
        let csv = family_csv(&frame);
        let header: alloc::vec::Vec<&str> = csv.lines().next().unwrap().split(',').collect();
        for key in ["eps_n:brilliantov2007", "eps_n:muller_poschel2011"] {
            assert!(header.contains(&key), "{header:?}");
            // One token: no spaces, quotes or semicolons for pandas to trip over.
            assert!(
                key.chars()
                    .all(|c| c.is_ascii_alphanumeric() || "_:".contains(c))
            );
        }
        // Every row has as many cells as the header.
        assert!(csv.lines().all(|l| l.split(',').count() == header.len()));
        // The citation is in the context lines, beside the key.
        let ctx = context(&frame, FAMILY_WHAT, "test", "2026-11-25");
        let line = ctx
            .lines()
            .find(|l| l.starts_with("# eps_n:brilliantov2007: "))
            .unwrap_or_else(|| panic!("{ctx}"));
        assert!(line.contains("Brilliantov"), "{line}");
    }
}
