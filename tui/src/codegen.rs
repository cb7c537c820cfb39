//! `rime export`'s code generators: the master curve itself in C99 and no_std Rust
//! (docs/physics.md#decision-14), and a REBOUND collision handler with its Python recipe.
//!
//! The generated files evaluate exactly what [`Contact::eps_n`] evaluates at the chosen level: the
//! level's Chebyshev table of ln ε (coarse for 1e-6, fine for 1e-10), the asymptotes of
//! `rime_core::master` beyond it, and the offset layer and adhesion in closed form.

use crate::scene_io::{CliResult, err};
use rime_core::master::{self, Resolution, U_MIN};
use rime_core::scene::{AdhesionModulus, ContactEnd, LayerReading, SlidingLaw};
use rime_core::{Accuracy, Contact, Scene};

/// Everything the generators bake in.
pub struct Law {
    resolution: Resolution,
    scene: Scene,
    contact: Contact,
    /// `(segments, degree, rows)`: the ln ε coefficients of the chosen table.
    table: (usize, usize, String),
    u_max: f64,
    segments_per_unit: f64,
    /// The scene JSON, for the files' header comment.
    scene_json: String,
    /// True: A, radii, layer and γ are runtime arguments of `rime_eps_n`/`rime_eps_t`.
    runtime_params: bool,
}

/// The table level of an accuracy: Precise (or a tolerance finer than 1e-6) gets the fine table.
pub fn resolution(accuracy: Accuracy) -> Resolution {
    match accuracy {
        Accuracy::Precise => Resolution::Fine,
        Accuracy::Tolerance(t) if t < 1e-6 => Resolution::Fine,
        _ => Resolution::Coarse,
    }
}

fn rows<const D: usize>(t: &master::Table<D>) -> (usize, usize, String) {
    let text = t
        .coefficients
        .iter()
        .map(|seg| {
            let c: Vec<String> = seg[0].iter().map(|v| format!("{v:e}")).collect();
            format!("    @OPEN@{}@CLOSE@,", c.join(", "))
        })
        .collect::<Vec<_>>()
        .join("\n");
    (t.coefficients.len(), D, text)
}

impl Law {
    /// Collects the constants; refuses the literal layer reading, which has no table.
    pub fn new(
        scene: &Scene,
        accuracy: Accuracy,
        scene_json: &str,
        runtime_params: bool,
    ) -> CliResult<Law> {
        if scene
            .layer
            .is_some_and(|l| l.reading == LayerReading::Literal)
        {
            return err(
                "layer.reading: the literal reading has no master-curve table and cannot be \
                 exported; use \"offset\" or turn the layer off",
            );
        }
        let contact = Contact::new(scene)?;
        let resolution = resolution(accuracy);
        let (table, u_max, segment) = match (scene.contact_end, resolution) {
            (ContactEnd::ForceZero, Resolution::Fine) => {
                let t = &master::FORCE_ZERO_FINE;
                (rows(t), t.u_max, t.segments_per_unit)
            }
            (ContactEnd::ZeroOverlap, Resolution::Fine) => {
                let t = &master::ZERO_OVERLAP_FINE;
                (rows(t), t.u_max, t.segments_per_unit)
            }
            (ContactEnd::ForceZero, Resolution::Coarse) => {
                let t = &master::FORCE_ZERO_COARSE;
                (rows(t), t.u_max, t.segments_per_unit)
            }
            (ContactEnd::ZeroOverlap, Resolution::Coarse) => {
                let t = &master::ZERO_OVERLAP_COARSE;
                (rows(t), t.u_max, t.segments_per_unit)
            }
        };
        Ok(Law {
            resolution,
            scene: *scene,
            contact,
            table,
            u_max,
            segments_per_unit: segment,
            scene_json: scene_json.to_string(),
            runtime_params,
        })
    }

    fn level(&self) -> (&'static str, &'static str) {
        match self.resolution {
            Resolution::Fine => ("precise", "1e-10"),
            Resolution::Coarse => ("fast", "1e-6"),
        }
    }

    /// Fills the placeholders shared by the C and Rust templates.
    fn fill(&self, template: &str, comment: &str) -> String {
        let (level, bound) = self.level();
        let friction = self.scene.friction;
        let lit = |v: f64| format!("{v:?}");
        let scene: Vec<String> = self
            .scene_json
            .lines()
            .map(|l| format!("{comment}{l}"))
            .collect();
        let zero_overlap = self.scene.contact_end == ContactEnd::ZeroOverlap;
        let walton = friction.is_some_and(|f| f.sliding_law == SlidingLaw::Walton);
        let modulus_factor = match self.scene.adhesion.map(|a| a.modulus) {
            Some(AdhesionModulus::Consistent) => 0.5,
            _ => 1.0,
        };
        let end = if zero_overlap {
            "zero-overlap"
        } else {
            "force-zero"
        };
        let pairs: [(&str, String); 21] = [
            ("@LEVEL@", level.to_string()),
            ("@BOUND@", bound.to_string()),
            ("@SCENE@", scene.join("\n")),
            ("@SEGMENTS@", self.table.0.to_string()),
            ("@DEGREE@", self.table.1.to_string()),
            ("@END@", end.to_string()),
            ("@U_MIN@", lit(U_MIN)),
            ("@U_MAX@", lit(self.u_max)),
            ("@SEGMENTS_PER_UNIT@", lit(self.segments_per_unit)),
            (
                "@SMALL_DELTA_SLOPE@",
                lit(rime_core::analytic::SMALL_DELTA_SLOPE),
            ),
            ("@ZERO_OVERLAP@", (zero_overlap as u8).to_string()),
            ("@ZERO_OVERLAP_BOOL@", zero_overlap.to_string()),
            (
                "@CREEP_K@",
                lit(rime_core::normal::viscoelastic::ZERO_OVERLAP_CREEP_COEFFICIENT),
            ),
            ("@LOG10E_FIFTH@", lit(0.2 * core::f64::consts::LOG10_E)),
            ("@DENSITY@", lit(self.scene.grains.density)),
            ("@YOUNGS@", lit(self.scene.bulk.youngs_modulus)),
            ("@POISSON@", lit(self.scene.bulk.poisson_ratio)),
            ("@ADHESION_MODULUS_FACTOR@", lit(modulus_factor)),
            ("@MU@", lit(friction.map_or(0.0, |f| f.coefficient))),
            ("@KAPPA@", lit(friction.map_or(2.0 / 7.0, |f| f.kappa))),
            ("@WALTON@", (walton as u8).to_string()),
        ];
        let mut out = template.replace("@WALTON_BOOL@", &walton.to_string());
        for (key, value) in pairs {
            out = out.replace(key, &value);
        }
        out
    }

    /// The scene's contact as literals: (log10 δ coefficient, layer g_s, adhesion g_s).
    fn scene_contact(&self) -> [String; 3] {
        let c = &self.contact;
        [
            format!("{:?}", c.log10_delta_coefficient),
            format!("{:?}", c.layer.map_or(0.0, |l| l.critical_velocity)),
            format!("{:?}", c.adhesion.map_or(0.0, |a| a.critical_velocity)),
        ]
    }

    /// The runtime arguments' defaults (the scene's values), for comments and the recipe.
    pub fn runtime_defaults(&self) -> [f64; 6] {
        let s = &self.scene;
        [
            s.damping_time(),
            s.grains.radius_1,
            s.grains.radius_2,
            s.layer.map_or(0.0, |l| l.thickness),
            s.layer.map_or(0.0, |l| l.viscosity),
            s.adhesion.map_or(0.0, |a| a.surface_energy),
        ]
    }

    /// `rime_eps.h`.
    pub fn c_header(&self) -> String {
        let signatures = if self.runtime_params {
            "/* eps_N and eps_T with the pair's constants as arguments (A [s], radii [m], layer thickness\n\
             * [m] and viscosity [Pa s], gamma [J/m^2]; NaN for invalid ones). Each call derives the\n\
             * contact; rime_contact_init + rime_eps_n_at do it once. */\n\
             double rime_eps_n(double g, double damping_time, double radius_1, double radius_2,\n\
             \x20                 double layer_thickness, double layer_viscosity, double surface_energy);\n\
             double rime_eps_t(double g_n, double g_t, double damping_time, double radius_1,\n\
             \x20                 double radius_2, double layer_thickness, double layer_viscosity,\n\
             \x20                 double surface_energy, int *stick_class);\n"
        } else {
            "/* The exported scene's eps_N(|g|) and eps_T(|g_n|, |g_t|). */\n\
             double rime_eps_n(double g);\n\
             double rime_eps_t(double g_n, double g_t, int *stick_class);\n\
             /* The exported scene's contact. */\n\
             extern const struct rime_contact RIME_SCENE_CONTACT;\n"
        };
        self.fill(include_str!("codegen/rime_eps.h.in"), " * ")
            .replace("@SIGNATURES@", signatures)
    }

    /// `rime_eps.c`.
    pub fn c_source(&self) -> String {
        let wrappers = if self.runtime_params {
            "double rime_eps_n(double g, double damping_time, double radius_1, double radius_2,\n\
             \x20                 double layer_thickness, double layer_viscosity, double surface_energy) {\n\
             \x20   struct rime_contact c;\n\
             \x20   if (rime_contact_init(&c, damping_time, radius_1, radius_2, layer_thickness,\n\
             \x20                         layer_viscosity, surface_energy)) return NAN;\n\
             \x20   return rime_eps_n_at(g, &c);\n}\n\n\
             double rime_eps_t(double g_n, double g_t, double damping_time, double radius_1,\n\
             \x20                 double radius_2, double layer_thickness, double layer_viscosity,\n\
             \x20                 double surface_energy, int *stick_class) {\n\
             \x20   struct rime_contact c;\n\
             \x20   if (rime_contact_init(&c, damping_time, radius_1, radius_2, layer_thickness,\n\
             \x20                         layer_viscosity, surface_energy)) {\n\
             \x20       if (stick_class) *stick_class = RIME_UNDEFINED;\n\
             \x20       return NAN;\n\
             \x20   }\n\
             \x20   return rime_eps_t_at(g_n, g_t, &c, stick_class);\n}\n"
                .to_string()
        } else {
            let [a, b, c] = self.scene_contact();
            format!(
                "const struct rime_contact RIME_SCENE_CONTACT = {{ {a}, {b}, {c} }};\n\n\
                 double rime_eps_n(double g) {{ return rime_eps_n_at(g, &RIME_SCENE_CONTACT); }}\n\n\
                 double rime_eps_t(double g_n, double g_t, int *stick_class) {{\n\
                 \x20   return rime_eps_t_at(g_n, g_t, &RIME_SCENE_CONTACT, stick_class);\n}}\n"
            )
        };
        let table = self.table.2.replace("@OPEN@", "{").replace("@CLOSE@", "}");
        self.fill(include_str!("codegen/rime_eps.c.in"), " * ")
            .replace("@WRAPPERS@", &wrappers)
            .replace("@C_TABLE@", &table)
    }

    /// `rime_eps.rs`.
    pub fn rust_source(&self) -> String {
        let table = self.table.2.replace("@OPEN@", "[").replace("@CLOSE@", "]");
        let wrappers = if self.runtime_params {
            "/// eps_N with the pair's constants as arguments (NaN for invalid ones); [`rime_contact`] +\n\
             /// [`rime_eps_n_at`] derive the contact once.\n\
             pub fn rime_eps_n(g: f64, damping_time: f64, radius_1: f64, radius_2: f64,\n\
             \x20   layer_thickness: f64, layer_viscosity: f64, surface_energy: f64) -> f64 {\n\
             \x20   match rime_contact(damping_time, radius_1, radius_2, layer_thickness, layer_viscosity, surface_energy) {\n\
             \x20       Ok(c) => rime_eps_n_at(g, &c),\n\
             \x20       Err(_) => f64::NAN,\n\
             \x20   }\n}\n\n\
             /// eps_T and the stick class with the pair's constants as arguments.\n\
             #[allow(clippy::too_many_arguments)]\n\
             pub fn rime_eps_t(g_n: f64, g_t: f64, damping_time: f64, radius_1: f64, radius_2: f64,\n\
             \x20   layer_thickness: f64, layer_viscosity: f64, surface_energy: f64) -> (f64, RimeStickClass) {\n\
             \x20   match rime_contact(damping_time, radius_1, radius_2, layer_thickness, layer_viscosity, surface_energy) {\n\
             \x20       Ok(c) => rime_eps_t_at(g_n, g_t, &c),\n\
             \x20       Err(_) => (f64::NAN, RimeStickClass::Undefined),\n\
             \x20   }\n}\n"
                .to_string()
        } else {
            let [a, b, c] = self.scene_contact();
            format!(
                "/// The exported scene's contact.\n\
                 pub const RIME_SCENE_CONTACT: RimeContact = RimeContact {{\n\
                 \x20   log10_delta_coefficient: {a},\n\
                 \x20   layer_critical_velocity: {b},\n\
                 \x20   adhesion_critical_velocity: {c},\n}};\n\n\
                 /// The exported scene's eps_N at impact speed |g| [m/s]; NaN in gives NaN out.\n\
                 pub fn rime_eps_n(g: f64) -> f64 {{\n\
                 \x20   rime_eps_n_at(g, &RIME_SCENE_CONTACT)\n}}\n\n\
                 /// The exported scene's eps_T(|g_n|, |g_t|) and stick class.\n\
                 pub fn rime_eps_t(g_n: f64, g_t: f64) -> (f64, RimeStickClass) {{\n\
                 \x20   rime_eps_t_at(g_n, g_t, &RIME_SCENE_CONTACT)\n}}\n"
            )
        };
        self.fill(include_str!("codegen/rime_eps.rs.in"), "// ")
            .replace("@WRAPPERS@", &wrappers)
            .replace("@RUST_TABLE@", &table)
    }

    /// `rime_rebound.c`: a REBOUND `collision_resolve` applying rime's laws.
    pub fn rebound_c(&self) -> String {
        let d = self.runtime_defaults();
        self.fill(include_str!("codegen/rime_rebound.c.in"), " * ")
            .replace(
                "@SOLID_SPHERE@",
                &format!("{:?}", rime_core::kinematics::SOLID_SPHERE),
            )
            .replace("@DEFAULT_A@", &format!("{:?}", d[0]))
            .replace("@DEFAULT_D@", &format!("{:?}", d[3]))
            .replace("@DEFAULT_ETA@", &format!("{:?}", d[4]))
            .replace("@DEFAULT_GAMMA@", &format!("{:?}", d[5]))
    }

    /// `rime_rebound.h`: the handler's prototypes, for C users (after REBOUND's `rebound.h`).
    pub fn rebound_h(&self) -> String {
        self.fill(include_str!("codegen/rime_rebound.h.in"), " * ")
    }

    /// `rime_rebound.py`: the recipe that builds and attaches the handler.
    pub fn rebound_py(&self) -> String {
        let d = self.runtime_defaults();
        self.fill(include_str!("codegen/rime_rebound.py.in"), "# ")
            .replace("@DEFAULT_A@", &format!("{:?}", d[0]))
            .replace("@DEFAULT_D@", &format!("{:?}", d[3]))
            .replace("@DEFAULT_ETA@", &format!("{:?}", d[4]))
            .replace("@DEFAULT_GAMMA@", &format!("{:?}", d[5]))
    }
}
