//! `rime collision`: one collision's time course, phases and energy ledger (docs/cli.md,
//! docs/physics.md#collision).

use crate::args::{Common, Format, number, speed};
use crate::output::{num, table};
use crate::scene_io::{CliError, CliResult, err};

/// Arguments of `rime collision`.
#[derive(Debug, Clone)]
pub struct Args {
    /// Normal impact speed \[m/s\].
    pub g: f64,
    /// Tangential speed \[m/s\], for an oblique impact.
    pub gt: Option<f64>,
    /// Evenly spaced samples over the contact.
    pub points: usize,
}

/// Parses the flags of `rime collision`.
pub fn parse(get: &dyn Fn(&str) -> Option<String>) -> CliResult<Args> {
    let g = speed(
        "--g",
        &get("--g").ok_or_else(|| CliError::input("--g: required (m/s)"))?,
        false,
    )?;
    let gt = get("--gt").map(|t| speed("--gt", &t, true)).transpose()?;
    let points = match get("--points") {
        None => 400,
        Some(p) => {
            let n = number("--points", &p)?;
            if !(n.fract() == 0.0 && (2.0..=1e6).contains(&n)) {
                return err(format!("--points: {p} must be an integer in [2, 1000000]"));
            }
            n as usize
        }
    };
    Ok(Args { g, gt, points })
}

/// Runs `rime collision`.
// Long by design: one trajectory's three outputs (JSON, CSV, table) side by side so that their
// fields stay in step.
pub fn run(common: &Common, args: &Args) -> CliResult<String> {
    let contact = crate::args::contact(common)?;
    let tr = contact
        .collision(args.g, args.points, common.accuracy)
        .map_err(|e| CliError::input(format!("--g {}: {e}", args.g)))?;
    let oblique = match args.gt {
        None => None,
        Some(gt) => {
            if contact.friction.is_none() {
                return err("--gt: the scene has no friction (--set friction=on)");
            }
            let grains = &common.scene.grains;
            Some(
                contact
                    .oblique(
                        grains.radius_1,
                        grains.radius_2,
                        args.g,
                        gt,
                        common.accuracy,
                    )
                    .map_err(|e| CliError::input(format!("--gt {gt}: {e}")))?,
            )
        }
    };
    let l = &tr.ledger;
    let ledger = [
        ("kinetic_in", l.kinetic_in, "J"),
        ("kinetic_out", l.kinetic_out, "J"),
        ("dissipated_bulk", l.dissipated_bulk, "J"),
        ("dissipated_layer", l.dissipated_layer, "J"),
        ("elastic_retained", l.elastic_retained, "J"),
        ("adhesion", l.adhesion, "J"),
        ("closure", l.closure, "1"),
    ];
    let tangential = oblique.map(|o| {
        // Units as docs/cli.md gives them (issue 37: the table's tangential rows had none).
        [
            ("eps_t", o.eps_t, ""),
            ("energy_before", o.energy_before, "J"),
            ("energy_after", o.energy_after, "J"),
            ("friction_work", o.friction_work, "J"),
            ("spin_change_1", o.spin_change[0], "rad/s"),
            ("spin_change_2", o.spin_change[1], "rad/s"),
        ]
    });
    Ok(match common.format {
        Format::Json => {
            // The core's record of this collision (field names are a contract, docs/cli.md).
            let record =
                rime_core::explorer::records::CollisionRecord::new(args.g, &tr, oblique.as_ref());
            let v = serde_json::to_value(&record).map_err(|e| CliError::input(e.to_string()))?;
            crate::output::pretty_json(&v, &COLLISION_KEYS)
        }
        Format::Csv => {
            let mut s = String::from("t [s],xi [m],xi_dot [m/s],force [N]\n");
            for i in 0..tr.t.len() {
                s.push_str(&format!(
                    "{},{},{},{}\n",
                    num(tr.t[i]),
                    num(tr.xi[i]),
                    num(tr.xi_dot[i]),
                    num(tr.force[i])
                ));
            }
            // The rest as `# name,value,unit` comment lines after the series.
            s.push_str(&format!("# status,{},\n", tr.status.name()));
            s.push_str(&format!("# eps_n,{},1\n", num(tr.eps_n)));
            s.push_str(&format!("# t_c,{},s\n", num(tr.t_c)));
            s.push_str(&format!("# xi_max,{},m\n", num(tr.xi_max)));
            for p in &tr.phases {
                s.push_str(&format!("# phase.{},{},s\n", p.name, num(p.t)));
            }
            for (k, v, u) in ledger {
                s.push_str(&format!("# ledger.{k},{},{u}\n", num(v)));
            }
            if let (Some(t), Some(o)) = (tangential, oblique) {
                s.push_str(&format!("# tangential.class,{},\n", o.class.name()));
                for (k, v, u) in t {
                    s.push_str(&format!("# tangential.{k},{},{u}\n", num(v)));
                }
            }
            s
        }
        Format::Table => {
            let mut rows: Vec<Vec<String>> = vec![
                vec!["status".into(), tr.status.name().into(), String::new()],
                vec!["eps_n".into(), num(tr.eps_n), String::new()],
                vec!["t_c".into(), num(tr.t_c), "s".into()],
                vec!["xi_max".into(), num(tr.xi_max), "m".into()],
            ];
            rows.extend(
                tr.phases
                    .iter()
                    .map(|p| vec![p.name.to_string(), num(p.t), "s".into()]),
            );
            rows.extend(
                ledger
                    .iter()
                    .map(|(k, v, u)| vec![k.to_string(), num(*v), u.to_string()]),
            );
            if let (Some(t), Some(o)) = (tangential, oblique) {
                rows.push(vec!["class".into(), o.class.name().into(), String::new()]);
                rows.extend(
                    t.iter()
                        .map(|(k, v, u)| vec![k.to_string(), num(*v), u.to_string()]),
                );
            }
            table(
                &["quantity", "value", "unit"],
                &crate::output::human_value_rows(rows),
            )
        }
    })
}

/// The JSON keys in the order docs/cli.md lists them (issue 37 C5: they were sorted): the impact
/// speed, the series, the phases, the four values of `rime eps`, the ledger, the tangential part.
const COLLISION_KEYS: [(&str, &[&str]); 4] = [
    (
        "",
        &[
            "g",
            "t",
            "xi",
            "xi_dot",
            "force",
            "phases",
            "t_c",
            "xi_max",
            "eps_n",
            "status",
            "resolved",
            "ledger",
            "tangential",
        ],
    ),
    ("phases", &["name", "t"]),
    (
        "ledger",
        &[
            "kinetic_in",
            "kinetic_out",
            "dissipated_bulk",
            "dissipated_layer",
            "elastic_retained",
            "adhesion",
            "closure",
        ],
    ),
    (
        "tangential",
        &[
            "eps_t",
            "class",
            "energy_before",
            "energy_after",
            "friction_work",
            "spin_change",
        ],
    ),
];
