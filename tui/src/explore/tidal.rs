//! The tidal-appendix calculator (`t`): Eq. (A.1)–(A.7) of the paper for this scene's grains,
//! beside the numbers the paper prints for its example (Saturn, Encke division, 2 cm ice grains).

//!
//! The model only; [`super::view::tidal`] draws it.

use rime_core::Scene;
use rime_core::tidal::{Tidal, TidalInput, tidal};

/// Saturn's equatorial radius \[m\] (60 268 km at 1 bar): a planet distance below it is inside
/// the planet.
pub const SATURN_RADIUS: f64 = 6.0268e7;

/// The paper's γ, used when the scene has no adhesion \[J/m²\].
pub const PAPER_GAMMA: f64 = 0.1;

/// What the calculator shows: its inputs and the result (or the error, naming the field).
#[derive(Debug, Clone)]
pub struct TidalView {
    /// Inputs: the paper's planet and distance (× the user's factor), the scene's grains.
    pub input: TidalInput,
    /// Whether γ is the paper's 0.1 J/m² because the scene's adhesion is off.
    pub gamma_from_paper: bool,
    /// Whether the inputs are exactly the paper's example (then the printed numbers compare).
    pub paper_inputs: bool,
    /// Whether the planet distance is inside Saturn (below [`SATURN_RADIUS`]).
    pub inside_planet: bool,
    /// Eq. (A.1)–(A.7), or why they cannot be evaluated.
    pub result: Result<Tidal, String>,
}

/// Evaluates the appendix for `scene`'s grains at `factor` × the paper's planet distance.
pub fn view(scene: &Scene, factor: f64) -> TidalView {
    let paper = TidalInput::default();
    let (surface_energy, gamma_from_paper) = match scene.adhesion {
        Some(a) => (a.surface_energy, false),
        None => (PAPER_GAMMA, true),
    };
    let input = TidalInput {
        distance: paper.distance * factor,
        radius: scene.grains.radius_1,
        density: scene.grains.density,
        surface_energy,
        ..paper
    };
    TidalView {
        input,
        gamma_from_paper,
        paper_inputs: input == paper,
        inside_planet: input.distance < SATURN_RADIUS,
        result: tidal(&input).map_err(|e| e.to_string()),
    }
}
