//! One frame's units computed by two page workers (issue 26): the worker asked for the frame
//! plans it, computes its share of the units and the rest of the plan ([`Pending`]), takes the
//! other worker's share ([`ShareRun`]) and assembles the frame, computing itself whatever share
//! did not come. The frame is the one [`super::page::frame`] computes, bit for bit: each unit's
//! output does not depend on which worker computed it, and the core assembles the outputs in the
//! plan's order.
//!
//! A share crosses between the workers in the wire form (`rime_core::wire`) of its outputs, read
//! back by the wire's generic reader ([`crate::wire_read::from_wire`]): no codec of its own. Only
//! the units that are lists of numbers travel (a curve's points, a model's ε_N, the stick map's
//! rows); the stick threshold and the overlays' labels stay with the frame's worker.

use super::frame::{FAILED, Frame, Output, Plan, Request, Unit};
use super::page::{PageWire, View, page_wire, prepare};
use crate::normal::memo::LayerMemo;
use crate::normal::{Normal, Status};
use crate::wire::{F64s, U8s, Wire, to_wire};
use crate::wire_read::from_wire;
use alloc::boxed::Box;
use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec::Vec;
use serde::{Deserialize, Serialize};

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

/// A share's outputs as they cross, each with its unit's index in the plan.
type Outputs = Vec<(usize, Part)>;

/// A shareable unit's output in its crossing form.
#[derive(Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
enum Part {
    /// A curve's points and its first failure.
    Curve {
        points: Points,
        first: Option<String>,
    },
    /// A model overlay's ε_N (NaN where the model failed).
    Points(F64s),
    /// Stick-map rows with the right-hand-side evaluations spent, or the map's error.
    Rows(Result<(F64s, usize), String>),
}

/// A curve's points by column, every number in the buffers (an infinite `t_c` included); a gap
/// has the status code [`FAILED`].
#[derive(Serialize, Deserialize)]
struct Points {
    status: U8s,
    eps: F64s,
    t_c: F64s,
    xi_max: F64s,
    error_estimate: F64s,
    rhs_evaluations: Vec<usize>,
}

impl Points {
    fn new(points: &[Option<Normal>]) -> Points {
        let column = |f: fn(&Normal) -> f64| {
            F64s(
                points
                    .iter()
                    .map(|p| p.as_ref().map_or(f64::NAN, f))
                    .collect(),
            )
        };
        Points {
            status: U8s(points
                .iter()
                .map(|p| p.map_or(FAILED, |n| n.status.code()))
                .collect()),
            eps: column(|n| n.eps),
            t_c: column(|n| n.t_c),
            xi_max: column(|n| n.xi_max),
            error_estimate: column(|n| n.error_estimate),
            rhs_evaluations: points
                .iter()
                .map(|p| p.map_or(0, |n| n.rhs_evaluations))
                .collect(),
        }
    }

    fn normals(self, n: usize) -> Result<Vec<Option<Normal>>, String> {
        let columns = [
            &self.eps.0,
            &self.t_c.0,
            &self.xi_max.0,
            &self.error_estimate.0,
        ];
        if self.status.0.len() != n
            || self.rhs_evaluations.len() != n
            || columns.iter().any(|c| c.len() != n)
        {
            return Err(format!(
                "share: a curve's columns do not hold its {n} points"
            ));
        }
        (0..n)
            .map(|i| match self.status.0[i] {
                FAILED => Ok(None),
                code => {
                    let status = *Status::ALL
                        .get(usize::from(code))
                        .ok_or_else(|| format!("share: unknown status code {code}"))?;
                    Ok(Some(Normal {
                        eps: self.eps.0[i],
                        status,
                        t_c: self.t_c.0[i],
                        xi_max: self.xi_max.0[i],
                        error_estimate: self.error_estimate.0[i],
                        rhs_evaluations: self.rhs_evaluations[i],
                    }))
                }
            })
            .collect()
    }
}

/// The crossing form of a shareable output (`None` for the others, which never travel).
fn part(out: &Output) -> Option<Part> {
    Some(match out {
        Output::Curve(points, first) => Part::Curve {
            points: Points::new(points),
            first: first.clone(),
        },
        Output::OverlayPoints(eps) => Part::Points(F64s(eps.clone())),
        Output::MapRows(rows) => Part::Rows(
            rows.as_ref()
                .map(|(eps, evaluations)| (F64s(eps.clone()), *evaluations))
                .map_err(Clone::clone),
        ),
        Output::Threshold(_) | Output::Overlay(_) => return None,
    })
}

/// A share in its wire form.
fn encode(items: &[(usize, &Output)]) -> Result<Wire, String> {
    let outputs: Outputs = items
        .iter()
        .filter_map(|(i, out)| part(out).map(|p| (*i, p)))
        .collect();
    to_wire(&outputs).map_err(|e| format!("share: {e}"))
}

/// The outputs of a share for the plan's `units`, or why they cannot be used (a share of another
/// plan: an index, kind or length that does not match).
fn decode(share: &Wire, units: &[Unit]) -> Result<Vec<(usize, Output)>, String> {
    let outputs: Outputs = from_wire(share).map_err(|e| format!("share: {e}"))?;
    outputs
        .into_iter()
        .map(|(i, part)| {
            let unit = units.get(i).ok_or("share: unit index beyond the plan")?;
            let n = unit_len(unit);
            let len = match &part {
                Part::Curve { points, .. } => Some(points.status.0.len()),
                Part::Points(eps) => Some(eps.0.len()),
                Part::Rows(Ok((eps, _))) => Some(eps.0.len()),
                Part::Rows(Err(_)) => None,
            };
            if len.is_some_and(|len| len != n) {
                return Err(format!("share: unit {i} has {len:?} numbers, the plan {n}"));
            }
            let output = match (part, unit) {
                (Part::Curve { points, first }, Unit::Curve { .. }) => {
                    Output::Curve(points.normals(n)?, first)
                }
                (Part::Points(eps), Unit::OverlayPoints { .. }) => Output::OverlayPoints(eps.0),
                (Part::Rows(rows), Unit::MapRows { .. }) => {
                    Output::MapRows(rows.map(|(eps, evaluations)| (eps.0, evaluations)))
                }
                (part, _) => {
                    let k = match part {
                        Part::Curve { .. } => "curve",
                        Part::Points(_) => "points",
                        Part::Rows(_) => "rows",
                    };
                    return Err(format!("share: unit {i} is not a {k}"));
                }
            };
            Ok((i, output))
        })
        .collect()
}

/// The plan of a request and its units, or the frame that ended while being planned (e.g. a scene
/// without a contact).
type Planned = Result<(Plan, Vec<Unit>), Box<Frame>>;

fn plan(req: &Request) -> Planned {
    match Plan::new(req) {
        Ok(plan) => {
            let units = plan.units(Plan::UNIT_POINTS);
            Ok((plan, units))
        }
        Err(frame) => Err(frame),
    }
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
    /// Plans the frame of `scene_json` seen through `view_json` and lists the units of worker
    /// `share` of `of`.
    pub fn begin(
        scene_json: &str,
        view_json: &str,
        share: usize,
        of: usize,
    ) -> Result<ShareRun, String> {
        let (_, req) = prepare(scene_json, view_json)?;
        let (planned, mut todo) = match plan(&req) {
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
    pub fn step(&mut self, memo: &dyn LayerMemo) -> Result<bool, String> {
        let (Some((plan, units)), Some(i)) = (&self.planned, self.todo.pop()) else {
            return Ok(false);
        };
        let out = plan
            .run_with(&units[i], &|| false, memo)
            .ok_or("share: cancelled")?;
        self.outputs.push((i, out));
        Ok(!self.todo.is_empty())
    }

    /// The share as it travels (the units computed so far), in its wire form.
    pub fn finish(self) -> Result<Wire, String> {
        let refs: Vec<(usize, &Output)> = self.outputs.iter().map(|(i, o)| (*i, o)).collect();
        encode(&refs)
    }
}

/// A frame being computed by its worker with another's help: [`Pending::run_next`] computes its
/// units, [`Pending::accept`] takes the helper's share, [`Pending::finish`] computes whatever is
/// still missing and packs the frame.
#[derive(Debug)]
pub struct Pending {
    view: View,
    req: Request,
    planned: Planned,
    outputs: Vec<Option<Output>>,
    helped: Vec<usize>,
}

impl Pending {
    /// Plans the frame of `scene_json` seen through `view_json`, with `of − 1` helpers (shares
    /// 1..of).
    pub fn begin(scene_json: &str, view_json: &str, of: usize) -> Result<Pending, String> {
        let (view, req) = prepare(scene_json, view_json)?;
        let planned = plan(&req);
        let (outputs, helped) = match &planned {
            Ok((_, units)) => (
                (0..units.len()).map(|_| None).collect(),
                (1..of.max(1))
                    .flat_map(|s| assigned(units, s, of))
                    .collect(),
            ),
            Err(_) => (Vec::new(), Vec::new()),
        };
        Ok(Pending {
            view,
            req,
            planned,
            outputs,
            helped,
        })
    }

    /// Computes this worker's next unit (every unit not assigned to a helper); false when none is
    /// left (so that the worker can stop between two units when its frame has become stale).
    pub fn run_next(&mut self, memo: &dyn LayerMemo) -> Result<bool, String> {
        let Ok((plan, units)) = &self.planned else {
            return Ok(false);
        };
        let next =
            (0..units.len()).find(|i| self.outputs[*i].is_none() && !self.helped.contains(i));
        let Some(i) = next else {
            return Ok(false);
        };
        let out = plan
            .run_with(&units[i], &|| false, memo)
            .ok_or("frame: cancelled")?;
        self.outputs[i] = Some(out);
        Ok(true)
    }

    /// Takes a helper's share; false (and nothing taken) when it is not a share of this plan.
    pub fn accept(&mut self, share: &Wire) -> bool {
        let Ok((_, units)) = &self.planned else {
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
    pub fn finish(mut self, memo: &dyn LayerMemo) -> Result<PageWire, String> {
        self.helped.clear();
        while self.run_next(memo)? {}
        let f = match self.planned {
            Ok((plan, units)) => {
                let outputs = self.outputs.into_iter().flatten().collect();
                plan.assemble(&units, outputs)
            }
            Err(frame) => *frame,
        };
        page_wire(&self.view, &self.req, &f).map_err(|e| e.to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::normal::memo::NoMemo;
    use alloc::vec;

    fn frame(scene: &str, view: &str) -> Result<PageWire, String> {
        super::super::page::frame(scene, view, &NoMemo)
    }

    /// Worker `share` of `of`'s outputs, all at once (the helping worker runs them a unit per turn).
    fn share(scene_json: &str, view_json: &str, share: usize, of: usize) -> Result<Wire, String> {
        let mut run = ShareRun::begin(scene_json, view_json, share, of)?;
        while run.step(&NoMemo)? {}
        run.finish()
    }

    fn scene(preset: crate::Preset, set: &[(&str, &str)]) -> String {
        let mut ex = super::super::session::Session::new();
        ex.set_json(&serde_json::to_string(&preset.scene()).unwrap())
            .unwrap();
        for (k, v) in set {
            ex.set(k, v).unwrap();
        }
        ex.to_json().unwrap()
    }

    /// Bit for bit (a failed point is NaN in both).
    fn assert_same(a: &PageWire, b: &PageWire, what: &str) {
        assert_eq!(
            (&a.wire.json, &a.wire.codes, &a.records),
            (&b.wire.json, &b.wire.codes, &b.records),
            "{what}"
        );
        let bits = |f: &PageWire| {
            f.wire
                .numbers
                .iter()
                .map(|x| x.to_bits())
                .collect::<Vec<_>>()
        };
        assert_eq!(bits(a), bits(b), "{what}");
    }

    fn split(scene: &str, view: &str, share_ok: bool) -> PageWire {
        let helper = share(scene, view, 1, 2).unwrap();
        let mut p = Pending::begin(scene, view, 2).unwrap();
        while p.run_next(&NoMemo).unwrap() {}
        if share_ok {
            assert!(p.accept(&helper));
            assert_eq!(p.missing(), 0, "the helper's share fills the frame");
        }
        p.finish(&NoMemo).unwrap()
    }

    #[test]
    fn a_frame_split_over_two_workers_is_the_frame_bit_for_bit_issue_26() {
        use crate::Preset::*;
        let cases = [
            (
                scene(IceFrost, &[]),
                r#"{"accuracy": "precise", "date": "D"}"#,
            ),
            (
                scene(IceSticky, &[]),
                r#"{"accuracy": "integrated", "points": 61, "map_n": 21, "date": "D"}"#,
            ),
            (
                scene(IceFrost, &[("layer.reading", "literal")]),
                r#"{"accuracy": "precise", "points": 41, "map_n": 11, "date": "D"}"#,
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
        let s = scene(crate::Preset::IceSticky, &[]);
        let view = r#"{"accuracy": "precise", "overlays": ["model:brilliantov2007"], "date": "D"}"#;
        let mut p = Pending::begin(&s, view, 1).unwrap();
        let mut steps = 0;
        while p.run_next(&NoMemo).unwrap() {
            steps += 1;
        }
        assert!(steps > 10 && p.missing() == 0, "{steps} units");
        assert_same(&p.finish(&NoMemo).unwrap(), &frame(&s, view).unwrap(), view);
    }

    #[test]
    fn a_share_of_another_plan_is_refused_and_the_frame_computed_whole_issue_26() {
        let s = scene(crate::Preset::IceFrost, &[]);
        let view = r#"{"accuracy": "fast", "date": "D"}"#;
        let other = share(&s, r#"{"accuracy": "fast", "points": 17}"#, 1, 2).unwrap();
        let mut p = Pending::begin(&s, view, 2).unwrap();
        while p.run_next(&NoMemo).unwrap() {}
        assert!(
            !p.accept(&other),
            "a share of a plan with other lengths is refused"
        );
        assert!(!p.accept(&Wire {
            json: "not json".into(),
            ..Wire::default()
        }));
        assert!(p.missing() > 0);
        assert_same(&p.finish(&NoMemo).unwrap(), &frame(&s, view).unwrap(), view);
    }

    #[test]
    fn a_refused_request_is_refused_alike_issue_26() {
        // The page's scene and view are checked when parsed (naming the field): the split path
        // refuses them with the frame's own words.
        let s = scene(crate::Preset::Ice, &[]);
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

    fn json_list(v: &[usize]) -> serde_json::Value {
        serde_json::Value::from(v.to_vec())
    }

    #[test]
    fn issue_36_a_share_crosses_in_the_derived_wire_and_comes_back_whole() {
        use crate::explorer::frame::CurveOf;
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
        let share = encode(&items).unwrap();
        // The derived wire: each output tagged by kind with its unit's index, its numbers in the
        // buffers (a curve by column: ε_N, t_c, ξ_max, error estimate; its statuses as codes,
        // FAILED in a gap), its words in the JSON.
        let j: serde_json::Value = serde_json::from_str(&share.json).unwrap();
        let list = j.as_array().unwrap();
        assert_eq!(list.len(), 4);
        assert_eq!(list[0][0], 0);
        assert_eq!(list[0][1]["curve"]["first"], "g = 1 m/s: why");
        assert_eq!(
            list[0][1]["curve"]["points"]["rhs_evaluations"],
            json_list(&[42, 0])
        );
        assert!(list[1][1]["points"]["$f64"].is_array());
        assert_eq!(list[2][1]["rows"]["Ok"][1], 7);
        assert_eq!(list[3][1]["rows"]["Err"], "map: no");
        assert_eq!(share.codes, [1, FAILED]);
        // 2 points × 4 columns, 3 overlay values, 2 map values, none for the failed rows.
        assert_eq!(share.numbers.len(), 2 * 4 + 3 + 2);
        assert_eq!(
            share.numbers[2],
            f64::INFINITY,
            "an infinite t_c crosses as it is"
        );
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
