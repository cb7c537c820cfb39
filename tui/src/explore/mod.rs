//! The interactive terminal explorer (ARCHITECTURE.md).
//!
//! Elm-like: [`state::App`] is the state, [`update::update`] applies one [`state::Event`] (one method
//! per action; files and the collision integration are in [`effects`]), and
//! [`view::render`] draws the state without side effects. One channel carries every event: keys,
//! mouse and resizes from a reader thread, finished frames from a worker thread. The worker always
//! computes the newest request: it drains older ones, and abandons a computation (between curves and
//! every few points) as soon as a newer generation is requested, so the UI never waits for it.

pub mod colors;
pub mod compute;
pub mod effects;
pub mod format;
pub mod frame_export;
pub mod keymap;
pub mod layout;
pub mod line_input;
pub mod state;
#[cfg(test)]
mod tests;
pub mod tidal;
pub mod update;
pub mod view;

use compute::Job;
use rime_core::{Accuracy, Scene};
use state::{App, Event};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{self, Receiver, Sender};
use std::time::Duration;
use update::update;

/// The generation the worker is told about when the user quits: no request has it, so whatever
/// the worker is computing (a refinement, say) is abandoned at its next check.
const QUIT: u64 = u64::MAX;

/// Computes the newest request, dropping older ones and abandoning stale work: first a `fast`
/// preview, then the requested level ([`compute::progressive`]).
fn worker(requests: Receiver<Job>, events: Sender<Event>, latest: Arc<AtomicU64>) {
    let threads = compute::threads();
    // The session's literal-layer outcomes: an edit that leaves the layer stage's inputs unchanged
    // (adhesion, friction, overlays, ...) is answered without integrating again.
    let memo = rime_core::normal::memo::SharedLayerMemo::new();
    // A preview only for frames whose kind was dear (or is new): the page's rule.
    let mut rule = compute::PreviewRule::default();
    while let Ok(mut req) = requests.recv() {
        while let Ok(newer) = requests.try_recv() {
            req = newer;
        }
        let generation = req.generation;
        let cancelled = || latest.load(Ordering::Relaxed) != generation;
        let mut deliver = |data| events.send(Event::Computed(Box::new(data))).is_ok();
        if !compute::progressive(&req, &cancelled, threads, &memo, &mut rule, &mut deliver) {
            return;
        }
    }
}

/// Forwards terminal events into the channel.
fn reader(events: Sender<Event>) {
    use crossterm::event::{self, Event as CEvent};
    loop {
        let ev = match event::read() {
            Ok(CEvent::Key(k)) => Event::Key(k),
            Ok(CEvent::Mouse(m)) => Event::Mouse(m),
            Ok(CEvent::Resize(w, h)) => Event::Resize(w, h),
            Ok(_) => continue,
            Err(_) => return,
        };
        if events.send(ev).is_err() {
            return;
        }
    }
}

/// Runs the explorer until the user quits.
pub fn run(scene: Scene, accuracy: Accuracy) -> Result<(), Box<dyn std::error::Error>> {
    let mut terminal = ratatui::try_init()?;
    // ratatui's hook restores the terminal on panic; ours also releases the mouse first.
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let _ = crossterm::execute!(std::io::stdout(), crossterm::event::DisableMouseCapture);
        previous(info);
    }));
    let _ = crossterm::execute!(std::io::stdout(), crossterm::event::EnableMouseCapture);
    let result = event_loop(&mut terminal, scene, accuracy);
    let _ = crossterm::execute!(std::io::stdout(), crossterm::event::DisableMouseCapture);
    ratatui::restore();
    result
}

fn event_loop(
    terminal: &mut ratatui::DefaultTerminal,
    scene: Scene,
    accuracy: Accuracy,
) -> Result<(), Box<dyn std::error::Error>> {
    let (event_tx, event_rx) = mpsc::channel::<Event>();
    let (request_tx, request_rx) = mpsc::channel::<Job>();
    let latest = Arc::new(AtomicU64::new(0));
    {
        let tx = event_tx.clone();
        let latest = Arc::clone(&latest);
        std::thread::Builder::new()
            .name("rime-worker".into())
            .spawn(move || worker(request_rx, tx, latest))?;
    }
    {
        let tx = event_tx.clone();
        std::thread::Builder::new()
            .name("rime-input".into())
            .spawn(move || reader(tx))?;
    }
    drop(event_tx);
    let mut app = App::new(scene, accuracy);
    app.colors = view::plot::Colors::from_env();
    let size = terminal.size()?;
    app.size = (size.width, size.height);
    loop {
        if let Some(req) = app.take_request() {
            latest.store(req.generation, Ordering::Relaxed);
            // The worker lives as long as we do; a failed send means it is gone.
            request_tx.send(req)?;
        }
        terminal.draw(|f| view::render(&app, f))?;
        // Wait for one event, then take everything already queued before drawing again, so that
        // a held-down key never builds a backlog of frames.
        let first = match event_rx.recv_timeout(Duration::from_millis(250)) {
            Ok(e) => Some(e),
            Err(mpsc::RecvTimeoutError::Timeout) => None,
            Err(mpsc::RecvTimeoutError::Disconnected) => break,
        };
        for ev in first
            .into_iter()
            .chain(std::iter::from_fn(|| event_rx.try_recv().ok()))
        {
            update(&mut app, ev);
            if app.quit {
                break;
            }
            if let Some(req) = app.pending.as_ref() {
                latest.store(req.generation, Ordering::Relaxed);
            }
        }
        if app.quit {
            break;
        }
    }
    // Quitting cancels the worker's computation at once (it checks between every few points).
    latest.store(QUIT, Ordering::Relaxed);
    Ok(())
}
