//! The interactive terminal explorer.

use rime_core::{Accuracy, Scene};

/// Runs the explorer until the user quits.
pub fn run(scene: Scene, accuracy: Accuracy) -> Result<(), Box<dyn std::error::Error>> {
    let _ = (scene, accuracy);
    Ok(())
}
