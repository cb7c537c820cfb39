//! Issue 14: the exported C and no_std Rust laws against the core at Precise (the independent
//! reference: the generated files share the tables, not the code) over |g| in [1e-12, 1e3] m/s, with
//! negative speeds, NaN, every preset (the literal layer reading is refused), the runtime-parameter
//! variant, ε_T with its class, and the exported kinematics (momentum conserved, the core's result).

use crate::bin::rime_binary;
use rime_core::kinematics::{GrainState, Vector3, collide};
use rime_core::scene::{LayerReading, Preset};
use rime_core::{Accuracy, Contact, Scene};
use rime_tests::rel;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("rime-exported-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn export(dir: &Path, args: &[&str]) {
    let out = Command::new(rime_binary())
        .args(["export", "--points", "16", "--out"])
        .arg(dir)
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Runs `exe mode` with `input` on stdin; returns stdout.
fn run(exe: &Path, mode: &str, input: &str) -> String {
    let mut child = Command::new(exe)
        .arg(mode)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(input.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    assert!(out.status.success(), "{} {mode}", exe.display());
    String::from_utf8(out.stdout).unwrap()
}

/// The probe's modes: `n` reads g and prints ε_N(g) ε_N(−g); `t` reads (g_n, g_t) and prints
/// ε_T and the class; `k` reads two grains and a normal and prints them after `rime_resolve`; `z`
/// prints ε_N(NaN). `CALL_N(g)`/`CALL_T(a, b, &cls)`/`CONTACT` adapt to the runtime variant.
const C_PROBE: &str = r#"
#include <stdio.h>
#include <math.h>
#include "rime_eps.h"
int main(int argc, char **argv) {
    double a, b;
    if (argc < 2) return 2;
    if (argv[1][0] == 'n') while (scanf("%lf", &a) == 1) printf("%.17g %.17g\n", CALL_N(a), CALL_N(-a));
    if (argv[1][0] == 't') while (scanf("%lf %lf", &a, &b) == 2) { int cls = -1; double e = CALL_T(a, b, &cls); printf("%.17g %d\n", e, cls); }
    if (argv[1][0] == 'z') printf("%.17g %.17g\n", CALL_N(NAN), CALL_T(NAN, 1.0, NULL));
    if (argv[1][0] == 'i') printf("%.17g %.17g\n", CALL_N(INFINITY), CALL_N(-INFINITY));
    if (argv[1][0] == 'k') {
        struct rime_grain g[2]; double n[3];
        for (int k = 0; k < 2; k++)
            if (scanf("%lf %lf %lf %lf %lf %lf %lf %lf %lf", &g[k].mass, &g[k].radius, &g[k].inertia_factor,
                      &g[k].velocity[0], &g[k].velocity[1], &g[k].velocity[2], &g[k].spin[0], &g[k].spin[1], &g[k].spin[2]) != 9) return 3;
        if (scanf("%lf %lf %lf", &n[0], &n[1], &n[2]) != 3) return 3;
        int cls = -1, rc = rime_resolve(&g[0], &g[1], n, CONTACT, &cls);
        for (int k = 0; k < 2; k++)
            printf("%.17g %.17g %.17g %.17g %.17g %.17g\n", g[k].velocity[0], g[k].velocity[1], g[k].velocity[2], g[k].spin[0], g[k].spin[1], g[k].spin[2]);
        printf("%d %d\n", rc, cls);
    }
    return 0;
}
"#;

const RUST_PROBE: &str = r#"
mod generated { include!("rime_eps.rs"); }
use generated::*;
use std::io::Read;
fn main() {
    let mode = std::env::args().nth(1).unwrap();
    let mut input = String::new();
    std::io::stdin().read_to_string(&mut input).unwrap();
    let v: Vec<f64> = input.split_whitespace().map(|s| s.parse().unwrap()).collect();
    match mode.as_str() {
        "n" => for &g in &v { println!("{:?} {:?}", call_n(g), call_n(-g)); },
        "t" => for p in v.chunks(2) { let (e, c) = call_t(p[0], p[1]); println!("{:?} {}", e, c as u8); },
        "z" => println!("{:?} {:?}", call_n(f64::NAN), call_t(f64::NAN, 1.0).0),
        "i" => println!("{:?} {:?}", call_n(f64::INFINITY), call_n(f64::NEG_INFINITY)),
        "k" => {
            let grain = |w: &[f64]| RimeGrain { mass: w[0], radius: w[1], inertia_factor: w[2],
                velocity: [w[3], w[4], w[5]], spin: [w[6], w[7], w[8]] };
            let (mut i, mut j) = (grain(&v[0..9]), grain(&v[9..18]));
            let class = rime_resolve(&mut i, &mut j, [v[18], v[19], v[20]], &contact()).unwrap();
            for g in [i, j] {
                println!("{:?} {:?} {:?} {:?} {:?} {:?}", g.velocity[0], g.velocity[1], g.velocity[2], g.spin[0], g.spin[1], g.spin[2]);
            }
            println!("0 {}", class as u8);
        }
        _ => std::process::exit(2),
    }
}
"#;

/// Compiled probes (C, Rust) of one export.
fn probes(dir: &Path, runtime: Option<[f64; 6]>) -> [PathBuf; 2] {
    // The C probe's CALL_N/CALL_T/CONTACT and the Rust probe's call_n/call_t/contact.
    let (call_n, call_t, contact_define, rust_glue) = match runtime {
        None => (
            "rime_eps_n((g))".to_string(),
            "rime_eps_t(a, b, c)".to_string(),
            "#define CONTACT &RIME_SCENE_CONTACT\n".to_string(),
            "fn call_n(g: f64) -> f64 { rime_eps_n(g) }\n\
             fn call_t(a: f64, b: f64) -> (f64, RimeStickClass) { rime_eps_t(a, b) }\n\
             fn contact() -> RimeContact { RIME_SCENE_CONTACT }\n"
                .to_string(),
        ),
        Some(p) => {
            let args = p.map(|v| format!("{v:?}")).join(", ");
            (
                format!("rime_eps_n((g), {args})"),
                format!("rime_eps_t(a, b, {args}, c)"),
                format!(
                    "static const struct rime_contact *probe_contact(void) {{ static struct rime_contact c; rime_contact_init(&c, {args}); return &c; }}\n#define CONTACT probe_contact()\n"
                ),
                format!(
                    "fn call_n(g: f64) -> f64 {{ rime_eps_n(g, {args}) }}\n\
                     fn call_t(a: f64, b: f64) -> (f64, RimeStickClass) {{ rime_eps_t(a, b, {args}) }}\n\
                     fn contact() -> RimeContact {{ rime_contact({args}).unwrap() }}\n"
                ),
            )
        }
    };
    let c_src = format!(
        "#include \"rime_eps.h\"\n#define CALL_N(g) {call_n}\n#define CALL_T(a, b, c) {call_t}\n{contact_define}{C_PROBE}"
    );
    std::fs::write(dir.join("probe.c"), c_src).unwrap();
    let c_exe = dir.join("probe-c");
    let cc = Command::new("cc")
        .args(["-O2", "-std=c99", "-Wall", "-Werror", "-o"])
        .arg(&c_exe)
        .arg(dir.join("probe.c"))
        .arg(dir.join("rime_eps.c"))
        .arg("-I")
        .arg(dir)
        .arg("-lm")
        .status()
        .expect("a C compiler (cc) is needed for this test");
    assert!(
        cc.success(),
        "generated C does not compile: {}",
        dir.display()
    );
    // The generated Rust is no_std: it compiles as a #![no_std] library on its own.
    let lib = dir.join("nostd.rs");
    std::fs::write(&lib, "#![no_std]\ninclude!(\"rime_eps.rs\");\n").unwrap();
    let status = Command::new("rustc")
        .args([
            "--edition",
            "2021",
            "--crate-type",
            "rlib",
            "-D",
            "warnings",
            "-A",
            "dead_code",
            "--out-dir",
        ])
        .arg(dir)
        .arg(&lib)
        .status()
        .unwrap();
    assert!(
        status.success(),
        "generated Rust is not no_std: {}",
        dir.display()
    );
    std::fs::write(dir.join("probe.rs"), format!("{RUST_PROBE}\n{rust_glue}")).unwrap();
    let rs_exe = dir.join("probe-rs");
    let status = Command::new("rustc")
        .args([
            "-C",
            "opt-level=1",
            "--edition",
            "2021",
            "-A",
            "warnings",
            "-o",
        ])
        .arg(&rs_exe)
        .arg(dir.join("probe.rs"))
        .status()
        .unwrap();
    assert!(
        status.success(),
        "generated Rust does not compile: {}",
        dir.display()
    );
    [c_exe, rs_exe]
}

/// Speeds on an irrational log step over [1e-12, 1e3] m/s, both ends included.
fn speeds() -> Vec<f64> {
    let mut g: Vec<f64> = (0..)
        .map(|k| 1e-12 * 10f64.powf(k as f64 * 0.0071 * std::f64::consts::SQRT_2))
        .take_while(|&g| g < 1e3)
        .collect();
    g.push(1e3);
    g
}

fn lines_of(text: &str) -> Vec<Vec<f64>> {
    text.lines()
        .map(|l| l.split_whitespace().map(|v| v.parse().unwrap()).collect())
        .collect()
}

/// Worst relative error of ε_N (in units of the allowed error, and raw) against the core at Precise.
/// The allowed error is the level's bound times the adhesion amplification 1/(1 − r²) that the
/// core's own error estimate carries (Eq. (17) near its threshold).
fn check_eps_n(exe: &Path, contact: &Contact, bound: f64, what: &str) -> f64 {
    let g = speeds();
    let input: String = g.iter().map(|v| format!("{v:?}\n")).collect();
    let rows = lines_of(&run(exe, "n", &input));
    assert_eq!(rows.len(), g.len(), "{what}");
    let mut worst = 0.0f64;
    for (row, &g) in rows.iter().zip(&g) {
        let reference = contact.normal(g, Accuracy::Precise).unwrap();
        let want = contact.eps_n(g, Accuracy::Precise).unwrap();
        assert_eq!(row[0], row[1], "{what}: ε_N(−g) ≠ ε_N(g) at g = {g:e}");
        if want == 0.0 {
            assert_eq!(row[0], 0.0, "{what}: g = {g:e} sticks in the core");
            continue;
        }
        // Below the bounds' domain (ε_N < 1e-6) the core promises no error, but the export and
        // the core evaluate the same tables: they must still agree to the level's bound.
        let amplification = if reference.error_estimate.is_finite() {
            reference.error_estimate / Accuracy::Precise.error_bound()
        } else {
            1.0
        };
        let err = rel(row[0], want);
        assert!(
            err <= bound * amplification,
            "{what}: g = {g:e}: {} vs {want} (rel {err:.2e}, allowed {:.2e})",
            row[0],
            bound * amplification
        );
        worst = worst.max(err / amplification);
    }
    let z = lines_of(&run(exe, "z", ""));
    assert!(
        z[0][0].is_nan() && z[0][1].is_nan(),
        "{what}: NaN in must give NaN out"
    );
    worst
}

/// ε_T and its class on a grid of (g_N, g_T), including the axes; worst relative error.
fn check_eps_t(exe: &Path, contact: &Contact, bound: f64, what: &str) -> f64 {
    let axis: Vec<f64> = std::iter::once(0.0)
        .chain((0..24).map(|k| 1e-12 * 10f64.powf(k as f64 * 0.65 + 0.013)))
        .collect();
    let pairs: Vec<(f64, f64)> = axis
        .iter()
        .flat_map(|&a| axis.iter().map(move |&b| (a, b)))
        .collect();
    let input: String = pairs
        .iter()
        .map(|(a, b)| format!("{a:?} {b:?}\n"))
        .collect();
    let rows = lines_of(&run(exe, "t", &input));
    assert_eq!(rows.len(), pairs.len());
    let friction = contact.friction.unwrap();
    let mut worst = 0.0f64;
    for (row, &(g_n, g_t)) in rows.iter().zip(&pairs) {
        let want = contact.tangential(g_n, g_t, Accuracy::Precise).unwrap();
        let class = rime_core::StickClass::ALL[row[1] as usize];
        assert_eq!(class, want.class, "{what}: class at ({g_n:e}, {g_t:e})");
        let amp = |g: f64| {
            if g == 0.0 {
                1.0
            } else {
                let e = contact.normal(g, Accuracy::Precise).unwrap().error_estimate;
                if e.is_finite() { e / 1e-10 } else { 1.0 }
            }
        };
        // How an ε_N error of `bound` propagates: directly on the rolling branch, through
        // μ g_N ε_N/(κ g_T ε_T) on the sliding one (Eq. (23)).
        let scale = if rime_core::tangential::is_rolling(g_n, g_t, &friction) {
            want.eps_t.abs() * amp(g_t)
        } else if want.eps_t != 0.0 {
            want.eps_t.abs()
                + friction.coefficient * g_n * want.eps_n * amp(g_n)
                    / (friction.kappa * g_t * want.eps_t.abs())
        } else {
            0.0
        };
        let err = (row[0] - want.eps_t).abs();
        assert!(
            err <= bound * scale + 1e-300,
            "{what}: ε_T({g_n:e}, {g_t:e}) = {} vs {}",
            row[0],
            want.eps_t
        );
        if want.eps_t != 0.0 {
            worst = worst.max(err / scale);
        }
    }
    worst
}

/// The exported `rime_resolve` on an oblique, spinning pair against the core's collide with the
/// core's ε (Precise), and momentum / angular momentum conservation from the probe's own output.
fn check_kinematics(exe: &Path, contact: &Contact, bound: f64, what: &str) -> f64 {
    let i = GrainState {
        mass: contact.mass_1,
        radius: 0.02,
        inertia_factor: 0.4,
        velocity: Vector3::new(-0.004, 0.0011, 0.0003),
        spin: Vector3::new(0.01, -0.03, 0.02),
    };
    let j = GrainState {
        mass: contact.mass_2,
        radius: 0.02,
        inertia_factor: 0.4,
        velocity: Vector3::new(0.002, -0.0004, 0.0001),
        spin: Vector3::new(-0.02, 0.01, 0.005),
    };
    let n = Vector3::new(1.0, 0.2, -0.1).normalize();
    let fmt = |g: &GrainState| {
        format!(
            "{:?} {:?} {:?} {:?} {:?} {:?} {:?} {:?} {:?}\n",
            g.mass,
            g.radius,
            g.inertia_factor,
            g.velocity[0],
            g.velocity[1],
            g.velocity[2],
            g.spin[0],
            g.spin[1],
            g.spin[2]
        )
    };
    let input = format!("{}{}{:?} {:?} {:?}\n", fmt(&i), fmt(&j), n[0], n[1], n[2]);
    let rows = lines_of(&run(exe, "k", &input));
    assert_eq!(rows[2][0], 0.0, "{what}: rime_resolve failed");
    let after = |k: usize, base: &GrainState| GrainState {
        velocity: Vector3::new(rows[k][0], rows[k][1], rows[k][2]),
        spin: Vector3::new(rows[k][3], rows[k][4], rows[k][5]),
        ..*base
    };
    let (i2, j2) = (after(0, &i), after(1, &j));
    // Conservation, from the probe's numbers alone: touching centres x_j = 0, x_i = (a_i + a_j) n.
    let xi = n * (i.radius + j.radius);
    let momenta = |a: &GrainState, b: &GrainState| {
        let p = a.velocity * a.mass + b.velocity * b.mass;
        let l = xi.cross(&(a.velocity * a.mass))
            + a.spin * a.moment_of_inertia()
            + b.spin * b.moment_of_inertia();
        (p, l)
    };
    let ((p0, l0), (p1, l1)) = (momenta(&i, &j), momenta(&i2, &j2));
    assert!(
        (p1 - p0).norm() <= 1e-14 * p0.norm(),
        "{what}: momentum {p0} → {p1}"
    );
    assert!(
        (l1 - l0).norm() <= 1e-14 * l0.norm(),
        "{what}: angular momentum {l0} → {l1}"
    );
    // The core's outcome with the core's ε at Precise.
    let g = rime_core::kinematics::relative_surface_velocity(&i, &j, &n);
    let (g_n, g_t) = rime_core::kinematics::decompose(&g, &n);
    let t = contact
        .tangential(g_n.abs(), g_t.norm(), Accuracy::Precise)
        .unwrap();
    let (mut ci, mut cj) = (i, j);
    collide(&mut ci, &mut cj, &n, t.eps_n, t.eps_t).unwrap();
    assert_eq!(
        rows[2][1] as usize,
        StickClassIndex::of(t.class),
        "{what}: class"
    );
    let mut worst = 0.0f64;
    for (got, want, before) in [(&i2, &ci, &i), (&j2, &cj, &j)] {
        let dv = (got.velocity - want.velocity).norm() / (want.velocity - before.velocity).norm();
        let dw = (got.spin - want.spin).norm() / (want.spin - before.spin).norm();
        worst = worst.max(dv).max(dw);
    }
    // The change of velocity and spin inherits ε's relative error (times |1+ε| / |1−ε| ≤ ~10 here).
    assert!(worst <= 10.0 * bound, "{what}: kinematics off by {worst:e}");
    worst
}

struct StickClassIndex;
impl StickClassIndex {
    fn of(c: rime_core::StickClass) -> usize {
        rime_core::StickClass::ALL
            .iter()
            .position(|&x| x == c)
            .unwrap()
    }
}

fn scenes() -> Vec<(String, Vec<&'static str>, Scene)> {
    let mut out: Vec<(String, Vec<&'static str>, Scene)> = Preset::ALL
        .iter()
        .map(|p| (p.name().to_string(), vec!["--preset", p.name()], p.scene()))
        .collect();
    let mut zero_overlap = Preset::Ice.scene();
    zero_overlap.contact_end = rime_core::scene::ContactEnd::ZeroOverlap;
    out.push((
        "ice+zero_overlap".into(),
        vec!["--set", "contact_end=zero_overlap"],
        zero_overlap,
    ));
    out
}

#[test]
fn exported_laws_meet_the_level_bound_at_every_speed() {
    let mut report = Vec::new();
    for (name, args, scene) in scenes() {
        let contact = Contact::new(&scene).unwrap();
        for (level, bound) in [("fast", 1e-6), ("precise", 1e-10)] {
            let dir = scratch(&format!("{name}-{level}"));
            let mut a = args.clone();
            a.extend(["--accuracy", level]);
            export(&dir, &a);
            for (lang, exe) in ["C", "Rust"].into_iter().zip(probes(&dir, None)) {
                let what = format!("{name} {level} {lang}");
                let n = check_eps_n(&exe, &contact, bound, &what);
                let t = check_eps_t(&exe, &contact, bound, &what);
                let k = check_kinematics(&exe, &contact, bound, &what);
                report.push(format!(
                    "{what}: eps_n {n:.2e}, eps_t {t:.2e}, resolve {k:.2e}"
                ));
            }
            std::fs::remove_dir_all(&dir).unwrap();
        }
    }
    println!("worst relative errors against the core at Precise, |g| in [1e-12, 1e3] m/s:");
    for line in report {
        println!("  {line}");
    }
}

#[test]
fn runtime_parameters_reproduce_the_core_for_other_grains() {
    // Exported from ice-frost with adhesion; evaluated for another radius, A, layer and γ.
    let dir = scratch("runtime");
    export(
        &dir,
        &[
            "--preset",
            "ice-frost",
            "--set",
            "adhesion=on",
            "--accuracy",
            "precise",
            "--runtime-params",
            "true",
        ],
    );
    let mut scene = Preset::IceFrost.scene();
    scene.grains.radius_2 = 0.05;
    scene.bulk.damping = rime_core::scene::Damping::Time(3e-4);
    let layer = scene.layer.as_mut().unwrap();
    layer.thickness = 2e-6;
    layer.viscosity = 500.0;
    scene.adhesion = Some(rime_core::scene::Adhesion {
        surface_energy: 0.05,
        ..Default::default()
    });
    let contact = Contact::new(&scene).unwrap();
    let params = [3e-4, scene.grains.radius_1, 0.05, 2e-6, 500.0, 0.05];
    for (lang, exe) in ["C", "Rust"].into_iter().zip(probes(&dir, Some(params))) {
        let what = format!("runtime {lang}");
        check_eps_n(&exe, &contact, 1e-10, &what);
        check_eps_t(&exe, &contact, 1e-10, &what);
        check_kinematics(&exe, &contact, 1e-10, &what);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_literal_layer_reading_is_refused_by_name() {
    let dir = scratch("literal");
    let out = Command::new(rime_binary())
        .args([
            "export",
            "--preset",
            "ice-frost",
            "--set",
            "layer.reading=literal",
            "--out",
        ])
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("layer.reading") && err.lines().count() == 1,
        "{err}"
    );
    assert!(!dir.join("rime_eps.c").exists());
    let _ = LayerReading::Literal;
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Issue 22: ε_N(±∞) of the exported C and Rust laws is 0 (the limit, ε_N ∝ g^(−1/3)) with
/// adhesion on, as in every other scene; it was NaN (0·∞ in the rebound-speed test).
#[test]
fn exported_law_at_infinite_speed_is_zero_with_adhesion_issue_22() {
    for preset in ["ice-sticky", "ice-frost", "ice"] {
        let dir = scratch(&format!("infinity-{preset}"));
        export(&dir, &["--preset", preset, "--accuracy", "fast"]);
        for (lang, exe) in ["C", "Rust"].into_iter().zip(probes(&dir, None)) {
            let z = lines_of(&run(&exe, "i", ""));
            assert_eq!(z, vec![vec![0.0, 0.0]], "{preset} {lang}: ε_N(±∞)");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
