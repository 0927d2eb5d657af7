//! `stewart view`: the interactive viewer, started where the last session left off unless
//! told otherwise.

use std::process::ExitCode;

use anyhow::Result;
use stewart_kinematics::Scenario;

use std::io::Write as _;

use crate::cli::ViewArgs;
use crate::i18n::{Lang, fonts};
use crate::source;
use crate::viewer::state::session::{self, Session};
use crate::viewer::window::window_size::{self, WindowSize};
use crate::viewer::{ViewOptions, ViewerState, run as run_viewer};

/// Run the command.
pub(crate) fn run(args: &ViewArgs) -> Result<ExitCode> {
    // Screenshot runs are reproducible: no session is read (unless --from-session asks for
    // it) and none is written.
    let folder = if args.screenshot.is_some() && !args.from_session {
        None
    } else {
        session::folder()
    };
    let wanted = args.lang.unwrap_or_else(Lang::from_env);
    let (saved, mut note) = match (&folder, args.fresh) {
        (Some(f), false) => match session::load(f) {
            Ok(s) => (s, None),
            Err(e) => (None, Some(e.words(wanted))),
        },
        _ => (None, None),
    };
    let (scenario, origin, restored) = starting_scenario(args, saved.as_ref(), wanted, &mut note)?;
    let parts_folder = parts_folder(args, &origin, restored);
    let mut state = ViewerState::new_in(scenario, parts_folder);
    if let Some(s) = &saved {
        restore(&mut state, s, restored);
    }
    if args.light {
        state.look.light_theme = true;
    }
    // --lang, else the session's, else the environment's; Chinese only with a font for it.
    let asked = args
        .lang
        .or_else(|| saved.as_ref().and_then(|s| s.lang))
        .unwrap_or(wanted);
    let (lang, font_note) = fonts::usable_here(asked);
    if let Some(n) = &font_note {
        let _ = writeln!(std::io::stderr(), "view: {n}");
    }
    state.look.lang = lang;
    note = note.or(font_note);
    state.look.presentation = args.presentation;
    state.look.expand_panels = args.expand_panels;
    state.tools.workspace.show |= args.workspace;
    // Never written by a screenshot run, even one that started from it.
    state.session.folder = folder.filter(|_| args.screenshot.is_none());
    state.remember_file(&origin);
    state.session.origin = origin;
    state.session.note = note;
    // Every section open, whatever the saved panels say.
    if args.expand_panels {
        state.session.panels = None;
    }
    let size = window_size_of(args, saved.as_ref());
    run_viewer(
        state,
        ViewOptions {
            screenshot: args.screenshot.clone(),
            frames: args.frames,
            screenshot_scale: args.screenshot_scale,
            stats: args.frame_stats,
            size,
        },
    )?;
    Ok(ExitCode::SUCCESS)
}

/// The scenario the viewer starts on, where it came from in words, and whether it is the
/// saved session's: the session's when no scenario is given and its scenario reads (else
/// why not goes to `note`), else the one given.
fn starting_scenario(
    args: &ViewArgs,
    saved: Option<&Session>,
    wanted: Lang,
    note: &mut Option<String>,
) -> Result<(Scenario, String, bool)> {
    let given = args.scenario.preset.is_some()
        || args.scenario.scenario.is_some()
        || !args.scenario.set.is_empty();
    let from_session: Option<(Scenario, String)> = match (saved, given) {
        (Some(s), false) => match s.scenario() {
            Ok(scenario) => Some((scenario, s.origin.clone())),
            Err(e) => {
                let why = e.words(wanted);
                *note = Some(wanted.fmt("session.scenario_broken", &[("why", &why)]));
                None
            }
        },
        _ => None,
    };
    let restored = from_session.is_some();
    let (scenario, origin) = match from_session {
        Some(pair) => pair,
        None => {
            let scenario = source::load(&args.scenario)?;
            let origin = origin_of(args, &scenario);
            (scenario, origin)
        }
    };
    Ok((scenario, origin, restored))
}

/// The folder the scenario's part files are named from: its file's (for a session's
/// scenario, the file it came from, when it came from one).
fn parts_folder(args: &ViewArgs, origin: &str, restored: bool) -> std::path::PathBuf {
    if restored {
        Some(std::path::Path::new(origin))
            .filter(|p| !origin.starts_with("preset ") && p.is_file())
            .and_then(std::path::Path::parent)
            .map_or_else(
                || std::path::PathBuf::from("."),
                std::path::Path::to_path_buf,
            )
    } else {
        crate::appearance::folder_of(&args.scenario)
    }
}

/// The window's size: `--size`, else the session's (exactly, for a screenshot, which does
/// not depend on the screen it was made on), else a share of the screen.
fn window_size_of(args: &ViewArgs, saved: Option<&Session>) -> WindowSize {
    let shot = args.screenshot.is_some();
    match (args.size, saved.and_then(Session::window_size)) {
        (Some((w, h)), _) => WindowSize::Exact(w, h),
        (None, Some((w, h))) if shot => WindowSize::Exact(w, h),
        (None, Some((w, h))) => WindowSize::Remembered(w, h),
        (None, None) if shot => WindowSize::Exact(window_size::FALLBACK.0, window_size::FALLBACK.1),
        (None, None) => WindowSize::FitScreen,
    }
}

/// The saved look and panels; the camera too when the scenario is the saved one (another
/// platform wants its own framing).
fn restore(state: &mut ViewerState, saved: &Session, same_scenario: bool) {
    let camera = state.look.camera;
    saved.restore_look(&mut state.look);
    if !same_scenario {
        state.look.camera = camera;
    }
    state.session.panels = saved.panels.clone();
    state.files.recent = saved.recent.iter().map(std::path::PathBuf::from).collect();
    if let Some(form) = &saved.export {
        state.exports.form = form.clone();
    }
}

/// Where the scenario of `args` came from, in words.
fn origin_of(args: &ViewArgs, scenario: &Scenario) -> String {
    match (&args.scenario.scenario, &args.scenario.preset) {
        (Some(path), _) => path.display().to_string(),
        (None, Some(name)) => format!("preset {name}"),
        (None, None) => format!("preset {}", scenario.name),
    }
}
