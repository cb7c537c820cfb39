//! One frame's units computed by two page workers (issue 26): the worker asked for the frame
//! plans it, computes its share of the units and the rest of the plan ([`Pending`]), takes the
//! other worker's share ([`ShareRun`], sent between the workers as a flat array of numbers and a
//! line of JSON) and assembles the frame, computing itself whatever share did not come. The frame is
//! the one [`crate::frame::frame`] computes, bit for bit: each unit's output does not depend on
//! which worker computed it, and the core assembles the outputs in the plan's order.
//!
//! Only the units that are lists of numbers travel (a curve's points, a model's ε_N, the stick
//! map's rows); the stick threshold and the overlays' labels stay with the frame's worker.

use crate::frame::{Frame, LAYER_MEMO, View, pack_frame, prepare};
use rime_core::explorer::frame::{Output, Plan, Request, Unit};
use rime_core::normal::{Normal, Status};

/// Numbers per point of a curve: present, ε_N, status code, t_c, ξ_max, error estimate,
/// right-hand-side evaluations.
const PER_POINT: usize = 7;

/// Whether a unit is computed by either worker (its output is a list of numbers).
fn shareable(u: &Unit) -> bool {
    matches!(
        u,
        Unit::Curve { .. } | Unit::OverlayPoints { .. } | Unit::MapRows { .. }
    )
}

/// The units worker `share` of `of` computes: every `of`-th shareable unit, from its `share`-th
/// (interleaved, so both shares mix cheap and dear parts of the frame).
fn assigned(units: &[Unit], share: usize, of: usize) -> Vec<usize> {
    units
        .iter()
        .enumerate()
        .filter(|(_, u)| shareable(u))
        .enumerate()
        .filter(|(k, _)| k % of.max(1) == share)
        .map(|(_, (i, _))| i)
        .collect()
}

/// How many numbers a unit's output has (its speeds or rows).
fn unit_len(u: &Unit) -> usize {
    match *u {
        Unit::Curve { from, to, .. }
        | Unit::OverlayPoints { from, to, .. }
        | Unit::MapRows { from, to } => to.saturating_sub(from),
        Unit::Threshold | Unit::Overlay(_) => 0,
    }
}

/// A share of a frame's units as it travels between workers.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Share {
    /// The outputs' numbers, concatenated.
    pub numbers: Vec<f64>,
    /// `{"units": [{"i", "k", "n", …}]}`: each output's unit index, kind and length, and its
    /// words (a curve's first failure, a map's error, its evaluation count).
    pub meta: String,
}

/// A share's words: each output's unit index, kind and length (`{"units": [{"i", "k", "n", …}]}`).
#[derive(serde::Serialize, serde::Deserialize)]
struct ShareMeta {
    units: Vec<UnitMeta>,
}

/// One output of a share: its unit's index in the plan and what it is.
#[derive(serde::Serialize, serde::Deserialize)]
struct UnitMeta {
    i: usize,
    #[serde(flatten)]
    kind: UnitKind,
}

/// What an output is (`"k"`) with its length `n` (checked against the plan) and its words.
#[derive(serde::Serialize, serde::Deserialize)]
#[serde(tag = "k", rename_all = "lowercase")]
enum UnitKind {
    /// A curve's points ([`PER_POINT`] numbers each) and its first failure.
    Curve { n: usize, first: Option<String> },
    /// An overlay's ε_N.
    Points { n: usize },
    /// Stick-map rows with their evaluation count, or the map's error (no numbers).
    Rows {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        n: Option<usize>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        evals: Option<usize>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        error: Option<String>,
    },
}

fn encode(items: &[(usize, &Output)]) -> Share {
    let mut numbers = Vec::new();
    let mut meta = Vec::with_capacity(items.len());
    for (i, out) in items {
        match out {
            Output::Curve(points, first) => {
                for p in points {
                    match p {
                        Some(n) => numbers.extend_from_slice(&[
                            1.0,
                            n.eps,
                            f64::from(n.status.code()),
                            n.t_c,
                            n.xi_max,
                            n.error_estimate,
                            n.rhs_evaluations as f64,
                        ]),
                        None => numbers.extend_from_slice(&[0.0; PER_POINT]),
                    }
                }
                meta.push(UnitMeta {
                    i: *i,
                    kind: UnitKind::Curve {
                        n: points.len(),
                        first: first.clone(),
                    },
                });
            }
            Output::OverlayPoints(eps) => {
                numbers.extend_from_slice(eps);
                meta.push(UnitMeta {
                    i: *i,
                    kind: UnitKind::Points { n: eps.len() },
                });
            }
            Output::MapRows(Ok((eps, evaluations))) => {
                numbers.extend_from_slice(eps);
                meta.push(UnitMeta {
                    i: *i,
                    kind: UnitKind::Rows {
                        n: Some(eps.len()),
                        evals: Some(*evaluations),
                        error: None,
                    },
                });
            }
            Output::MapRows(Err(e)) => meta.push(UnitMeta {
                i: *i,
                kind: UnitKind::Rows {
                    n: None,
                    evals: None,
                    error: Some(e.clone()),
                },
            }),
            // Never assigned to a share (see `shareable`).
            Output::Threshold(_) | Output::Overlay(_) => {}
        }
    }
    Share {
        numbers,
        // Serializing these plain structs cannot fail; an empty meta is refused by `decode`.
        meta: serde_json::to_string(&ShareMeta { units: meta }).unwrap_or_default(),
    }
}

/// The outputs of a share for the plan's `units`, or why they cannot be used (a share of another
/// plan: an index, kind or length that does not match).
fn decode(share: &Share, units: &[Unit]) -> Result<Vec<(usize, Output)>, String> {
    let meta: ShareMeta = serde_json::from_str(&share.meta).map_err(|e| format!("share: {e}"))?;
    let mut at = 0usize;
    let mut take = |n: usize| -> Result<&[f64], String> {
        let s = share
            .numbers
            .get(at..at + n)
            .ok_or("share: fewer numbers than its units")?;
        at += n;
        Ok(s)
    };
    let mut out = Vec::with_capacity(meta.units.len());
    for UnitMeta { i, kind } in meta.units {
        let unit = units.get(i).ok_or("share: unit index beyond the plan")?;
        let n = match &kind {
            UnitKind::Curve { n, .. } | UnitKind::Points { n } => Some(*n),
            UnitKind::Rows { n, .. } => *n,
        };
        if n.is_some_and(|n| n != unit_len(unit)) {
            return Err(format!(
                "share: unit {i} has {n:?} numbers, the plan {}",
                unit_len(unit)
            ));
        }
        let output = match (kind, unit) {
            (UnitKind::Curve { first, .. }, Unit::Curve { .. }) => {
                let raw = take(PER_POINT * unit_len(unit))?;
                let mut points = Vec::with_capacity(unit_len(unit));
                for p in raw.chunks_exact(PER_POINT) {
                    points.push(if p[0] == 0.0 {
                        None
                    } else {
                        let status = *Status::ALL
                            .get(p[2] as usize)
                            .ok_or("share: unknown status code")?;
                        Some(Normal {
                            eps: p[1],
                            status,
                            t_c: p[3],
                            xi_max: p[4],
                            error_estimate: p[5],
                            rhs_evaluations: p[6] as usize,
                        })
                    });
                }
                Output::Curve(points, first)
            }
            (UnitKind::Points { .. }, Unit::OverlayPoints { .. }) => {
                Output::OverlayPoints(take(unit_len(unit))?.to_vec())
            }
            (UnitKind::Rows { error, evals, .. }, Unit::MapRows { .. }) => match error {
                Some(e) => Output::MapRows(Err(e)),
                None => {
                    let evaluations = evals.ok_or("share: rows without evals")?;
                    Output::MapRows(Ok((take(unit_len(unit))?.to_vec(), evaluations)))
                }
            },
            (kind, _) => {
                let k = match kind {
                    UnitKind::Curve { .. } => "curve",
                    UnitKind::Points { .. } => "points",
                    UnitKind::Rows { .. } => "rows",
                };
                return Err(format!("share: unit {i} is not a {k}"));
            }
        };
        out.push((i, output));
    }
    Ok(out)
}

/// The plan of `scene` seen through `view` and its units (`None`: the frame ended while being
/// planned, e.g. a scene without a contact; that frame is the second element).
type Planned = (
    View,
    Request,
    Result<(Plan, Vec<Unit>), rime_core::explorer::frame::Frame>,
);

fn plan(scene_json: &str, view_json: &str) -> Result<Planned, String> {
    let (view, req) = prepare(scene_json, view_json)?;
    let planned = match Plan::new(&req) {
        Ok(plan) => {
            let units = plan.units(Plan::UNIT_POINTS);
            Ok((plan, units))
        }
        Err(frame) => Err(*frame),
    };
    Ok((view, req, planned))
}

/// A helper's share computed a unit at a time, so that the helping worker can stop between two
/// units (a newer edit's preview must not wait behind a stale share).
#[derive(Debug)]
pub struct ShareRun {
    planned: Option<(Plan, Vec<Unit>)>,
    todo: Vec<usize>,
    outputs: Vec<(usize, Output)>,
}

impl ShareRun {
    /// Plans the frame and lists the units of worker `share` of `of`.
    pub fn begin(
        scene_json: &str,
        view_json: &str,
        share: usize,
        of: usize,
    ) -> Result<ShareRun, String> {
        let (_, _, planned) = plan(scene_json, view_json)?;
        let (planned, mut todo) = match planned {
            Ok((plan, units)) => {
                let todo = assigned(&units, share, of);
                (Some((plan, units)), todo)
            }
            Err(_) => (None, Vec::new()),
        };
        todo.reverse(); // popped from the end: in plan order
        Ok(ShareRun {
            planned,
            todo,
            outputs: Vec::new(),
        })
    }

    /// Computes the next unit; false when none is left.
    pub fn step(&mut self) -> Result<bool, String> {
        let (Some((plan, units)), Some(i)) = (&self.planned, self.todo.pop()) else {
            return Ok(false);
        };
        let out = plan
            .run_with(&units[i], &|| false, &LAYER_MEMO)
            .ok_or("share: cancelled")?;
        self.outputs.push((i, out));
        Ok(!self.todo.is_empty())
    }

    /// The share as it travels (the units computed so far).
    pub fn finish(self) -> Share {
        let refs: Vec<(usize, &Output)> = self.outputs.iter().map(|(i, o)| (*i, o)).collect();
        encode(&refs)
    }
}

/// A frame being computed by its worker with another's help: [`Pending::run_own`] computes its
/// units, [`Pending::accept`] takes the helper's share, [`Pending::finish`] computes whatever is
/// still missing and packs the frame.
#[derive(Debug)]
pub struct Pending {
    view: View,
    req: Request,
    planned: Option<(Plan, Vec<Unit>)>,
    early: Option<rime_core::explorer::frame::Frame>,
    outputs: Vec<Option<Output>>,
    helped: Vec<usize>,
}

impl Pending {
    /// Plans the frame of `scene` seen through `view`, with `of − 1` helpers (shares 1..of).
    pub fn begin(scene_json: &str, view_json: &str, of: usize) -> Result<Pending, String> {
        let (view, req, planned) = plan(scene_json, view_json)?;
        let (planned, early, outputs, helped) = match planned {
            Ok((plan, units)) => {
                let helped = (1..of.max(1))
                    .flat_map(|s| assigned(&units, s, of))
                    .collect();
                let outputs = vec![None; units.len()];
                (Some((plan, units)), None, outputs, helped)
            }
            Err(frame) => (None, Some(frame), Vec::new(), Vec::new()),
        };
        Ok(Pending {
            view,
            req,
            planned,
            early,
            outputs,
            helped,
        })
    }

    /// Computes this worker's units: every unit not assigned to a helper.
    pub fn run_own(&mut self) -> Result<(), String> {
        while self.run_next()? {}
        Ok(())
    }

    /// Computes this worker's next unit; false when none is left (so that the worker can stop
    /// between two units when its frame has become stale).
    pub fn run_next(&mut self) -> Result<bool, String> {
        let Some((plan, units)) = &self.planned else {
            return Ok(false);
        };
        let next =
            (0..units.len()).find(|i| self.outputs[*i].is_none() && !self.helped.contains(i));
        let Some(i) = next else {
            return Ok(false);
        };
        let out = plan
            .run_with(&units[i], &|| false, &LAYER_MEMO)
            .ok_or("frame: cancelled")?;
        self.outputs[i] = Some(out);
        Ok(true)
    }

    /// Takes a helper's share; false (and nothing taken) when it is not a share of this plan.
    pub fn accept(&mut self, share: &Share) -> bool {
        let Some((_, units)) = &self.planned else {
            return false;
        };
        match decode(share, units) {
            Ok(outputs) => {
                for (i, out) in outputs {
                    if self.helped.contains(&i) {
                        self.outputs[i] = Some(out);
                    }
                }
                true
            }
            Err(_) => false,
        }
    }

    /// How many units are still missing (a helper's share that did not come).
    pub fn missing(&self) -> usize {
        self.outputs.iter().filter(|o| o.is_none()).count()
    }

    /// Computes what is still missing and packs the frame.
    pub fn finish(mut self) -> Result<Frame, String> {
        self.helped.clear();
        self.run_own()?;
        let f = match (self.planned, self.early) {
            (Some((plan, units)), _) => {
                let outputs = self.outputs.into_iter().flatten().collect();
                plan.assemble(&units, outputs)
            }
            (None, Some(frame)) => frame,
            (None, None) => return Err("frame: not planned".into()),
        };
        pack_frame(&self.view, &self.req, &f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::frame::frame;

    /// Worker `share` of `of`'s outputs, all at once (the helping worker runs them a unit per turn).
    fn share(scene_json: &str, view_json: &str, share: usize, of: usize) -> Result<Share, String> {
        let mut run = ShareRun::begin(scene_json, view_json, share, of)?;
        while run.step()? {}
        Ok(run.finish())
    }

    fn scene(preset: rime_core::Preset, set: &[(&str, &str)]) -> String {
        let mut ex = crate::explorer::Explorer::new();
        ex.set_json(&serde_json::to_string(&preset.scene()).unwrap())
            .unwrap();
        for (k, v) in set {
            ex.set(k, v).unwrap();
        }
        ex.to_json().unwrap()
    }

    /// Bit for bit (a failed point is NaN in both).
    fn assert_same(a: &Frame, b: &Frame, what: &str) {
        assert_eq!(
            (&a.json, &a.codes, &a.records),
            (&b.json, &b.codes, &b.records),
            "{what}"
        );
        let bits = |f: &Frame| f.numbers.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(a), bits(b), "{what}");
    }

    fn split(scene: &str, view: &str, share_ok: bool) -> Frame {
        let helper = share(scene, view, 1, 2).unwrap();
        let mut p = Pending::begin(scene, view, 2).unwrap();
        p.run_own().unwrap();
        if share_ok {
            assert!(p.accept(&helper));
            assert_eq!(p.missing(), 0, "the helper's share fills the frame");
        }
        p.finish().unwrap()
    }

    #[test]
    fn a_frame_split_over_two_workers_is_the_frame_bit_for_bit_issue_26() {
        use rime_core::Preset::*;
        let cases = [
            (
                scene(IceFrost, &[]),
                r#"{"accuracy": "precise", "date": "D"}"#,
            ),
            (
                scene(IceSticky, &[]),
                r#"{"accuracy": "integrated", "points": 61, "mapN": 21, "date": "D"}"#,
            ),
            (
                scene(IceFrost, &[("layer.reading", "literal")]),
                r#"{"accuracy": "precise", "points": 41, "mapN": 11, "date": "D"}"#,
            ),
            (
                scene(Ice, &[]),
                r#"{"accuracy": "precise", "overlays": ["model:brilliantov2007", "atlas:bridges1984"], "date": "D"}"#,
            ),
            // Failing parts travel as failures (a gap every 40th speed, the whole map).
            (
                scene(IceFrost, &[]),
                r#"{"fail": ["curve", "map"], "date": "D"}"#,
            ),
        ];
        for (scene, view) in &cases {
            let whole = frame(scene, view).unwrap();
            for share_ok in [true, false] {
                let parts = split(scene, view, share_ok);
                assert_same(
                    &parts,
                    &whole,
                    &format!("{view}, helper's share taken: {share_ok}"),
                );
            }
        }
    }

    #[test]
    fn a_frame_without_helpers_unit_by_unit_is_the_frame_issue_26() {
        // A refinement on its own (of = 1), a unit per call (so that a stale one can stop).
        let s = scene(rime_core::Preset::IceSticky, &[]);
        let view = r#"{"accuracy": "precise", "overlays": ["model:brilliantov2007"], "date": "D"}"#;
        let mut p = Pending::begin(&s, view, 1).unwrap();
        let mut steps = 0;
        while p.run_next().unwrap() {
            steps += 1;
        }
        assert!(steps > 10 && p.missing() == 0, "{steps} units");
        assert_same(&p.finish().unwrap(), &frame(&s, view).unwrap(), view);
    }

    #[test]
    fn a_share_of_another_plan_is_refused_and_the_frame_computed_whole_issue_26() {
        let s = scene(rime_core::Preset::IceFrost, &[]);
        let view = r#"{"accuracy": "fast", "date": "D"}"#;
        let other = share(&s, r#"{"accuracy": "fast", "points": 17}"#, 1, 2).unwrap();
        let mut p = Pending::begin(&s, view, 2).unwrap();
        p.run_own().unwrap();
        assert!(
            !p.accept(&other),
            "a share of a plan with other lengths is refused"
        );
        assert!(!p.accept(&Share {
            numbers: vec![],
            meta: "not json".into()
        }));
        assert!(p.missing() > 0);
        assert_same(&p.finish().unwrap(), &frame(&s, view).unwrap(), view);
    }

    #[test]
    fn a_refused_request_is_refused_alike_issue_26() {
        // The page's scene and view are checked when parsed (naming the field): the split path
        // refuses them with the frame's own words.
        let s = scene(rime_core::Preset::Ice, &[]);
        for view in [
            r#"{"from": 1.0, "to": 0.5}"#,
            r#"{"points": 1}"#,
            r#"{"bogus": 1}"#,
        ] {
            let whole = frame(&s, view).unwrap_err();
            assert_eq!(Pending::begin(&s, view, 2).unwrap_err(), whole);
            assert_eq!(share(&s, view, 1, 2).unwrap_err(), whole);
        }
    }

    #[test]
    fn issue_36_a_shares_words_keep_their_keys_and_come_back_whole() {
        use rime_core::explorer::frame::CurveOf;
        let units = [
            Unit::Curve {
                of: CurveOf::Scene,
                from: 0,
                to: 2,
            },
            Unit::OverlayPoints {
                k: 0,
                from: 3,
                to: 6,
            },
            Unit::MapRows { from: 0, to: 2 },
            Unit::MapRows { from: 2, to: 4 },
        ];
        let rebound = Normal {
            eps: 0.5,
            status: Status::ALL[1],
            t_c: f64::INFINITY,
            xi_max: 1e-9,
            error_estimate: 1e-6,
            rhs_evaluations: 42,
        };
        let outputs = [
            Output::Curve(vec![Some(rebound), None], Some("g = 1 m/s: why".into())),
            Output::OverlayPoints(vec![0.1, f64::NAN, 0.3]),
            Output::MapRows(Ok((vec![0.25, -0.5], 7))),
            Output::MapRows(Err("map: no".into())),
        ];
        let items: Vec<(usize, &Output)> = outputs.iter().enumerate().collect();
        let share = encode(&items);
        // The words travel as JSON with these keys (the page's workers pass them on unread).
        let meta: serde_json::Value = serde_json::from_str(&share.meta).unwrap();
        let keys = |j: &serde_json::Value| {
            let mut k: Vec<String> = j.as_object().unwrap().keys().cloned().collect();
            k.sort();
            k
        };
        assert_eq!(keys(&meta), ["units"]);
        let list = meta["units"].as_array().unwrap();
        assert_eq!(keys(&list[0]), ["first", "i", "k", "n"]);
        assert_eq!((&list[0]["k"], &list[0]["n"]), (&"curve".into(), &2.into()));
        assert_eq!(keys(&list[1]), ["i", "k", "n"]);
        assert_eq!(list[1]["k"], "points");
        assert_eq!(keys(&list[2]), ["evals", "i", "k", "n"]);
        assert_eq!(
            (&list[2]["k"], &list[2]["evals"]),
            (&"rows".into(), &7.into())
        );
        assert_eq!(keys(&list[3]), ["error", "i", "k"]);
        // 2 points × PER_POINT, 3 overlay values, 2 map values, none for the failed rows.
        assert_eq!(share.numbers.len(), 2 * PER_POINT + 3 + 2);
        let back = decode(&share, &units).unwrap();
        assert_eq!(back.len(), outputs.len());
        for ((i, got), (j, want)) in back.iter().zip(items) {
            assert_eq!(*i, j);
            match (got, want) {
                // NaN is not equal to itself: compare the bits.
                (Output::OverlayPoints(a), Output::OverlayPoints(b)) => {
                    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                    assert_eq!(bits(a), bits(b));
                }
                _ => assert_eq!(got, want),
            }
        }
        // A share whose kinds do not match the plan's units is refused, naming the unit.
        let swapped = [
            units[1].clone(),
            units[0].clone(),
            units[2].clone(),
            units[3].clone(),
        ];
        let err = decode(&share, &swapped).unwrap_err();
        assert!(err.starts_with("share: unit 0"), "{err}");
    }
}
