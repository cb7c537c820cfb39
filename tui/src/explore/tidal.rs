//! The tidal-appendix calculator (`t`): the core's card (`rime_core::explorer::tidal`) for this
//! scene's grains at a factor of the paper's planet distance. The model only;
//! [`super::view::tidal`] lays the card out.

use rime_core::Scene;
use rime_core::explorer::tidal::{TidalCard, card, input_for};
use rime_core::tidal::TidalInput;

/// What the calculator shows: its inputs and the core's card (or the error, naming the field).
#[derive(Debug, Clone)]
pub struct TidalView {
    /// Inputs: the paper's planet and distance (× the user's factor), the scene's grains.
    pub input: TidalInput,
    /// Whether γ is the paper's 0.1 J/m² because the scene's adhesion is off.
    pub gamma_from_paper: bool,
    /// The card, or why the appendix cannot be evaluated.
    pub card: Result<TidalCard, String>,
}

/// The card for `scene`'s grains at `factor` × the paper's planet distance.
pub fn view(scene: &Scene, factor: f64) -> TidalView {
    let (input, gamma_from_paper) = input_for(scene, factor);
    TidalView {
        input,
        gamma_from_paper,
        card: card(input, gamma_from_paper).map_err(|e| e.to_string()),
    }
}
