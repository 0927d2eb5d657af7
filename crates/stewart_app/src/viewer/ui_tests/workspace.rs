//! The Workspace panel: the surface follows the scenario and the pose, its numbers agree
//! with `stewart workspace`, the platform centre is placed inside or outside, and the
//! conditioning slice counts the cells past the threshold — in English and in Chinese.

use crate::i18n::Lang;
use crate::viewer::state::ViewerState;
use crate::viewer::state::playback::MotionMode;
use crate::viewer::tools::workspace::WorkspaceTool;
use crate::volume_text::{format_volume, format_volume_error};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use stewart_kinematics::analysis::dynamics;
use stewart_kinematics::analysis::workspace;
use stewart_kinematics::{Angle, Pose, Scenario};

/// Columns a side of the refinement in these tests (the viewer's 512 are slow in a debug
/// build).
const FINE: usize = 96;

/// The viewer on `preset` in manual mode at home, every section open, the workspace
/// (computed at 32 then [`FINE`] columns) not yet shown.
fn viewer(preset: &str) -> ViewerState {
    let mut state = ViewerState::new(Scenario::preset(preset).unwrap_or_else(|e| panic!("{e}")));
    state.tools.workspace = WorkspaceTool::with_resolutions(32, FINE);
    state.look.expand_panels = true;
    state.playback.mode = MotionMode::Manual;
    state
}

/// [`viewer`] with the workspace shown and refined, in `lang`.
fn shown(preset: &str, lang: Lang) -> Harness<'static, ViewerState> {
    let mut state = viewer(preset);
    state.look.lang = lang;
    state.tools.workspace.show = true;
    let mut h = super::harness_with(state, 4200.0);
    settle(&mut h);
    h
}

/// Wait for the refinement (a debug build sharing two cores with the other tests can take
/// a while), then draw.
fn settle(h: &mut Harness<'static, ViewerState>) {
    h.state_mut().settle_workspace();
    h.state_mut()
        .tools
        .workspace
        .wait(std::time::Duration::from_secs(120));
    h.run();
}

/// The volume line as the panel writes it, from a workspace computed here.
fn volume_line(s: &Scenario, orientation: [Angle; 3]) -> String {
    let ws = workspace::constant_orientation_workspace(&s.geometry, &s.limits, orientation, FINE)
        .unwrap_or_else(|e| panic!("{e}"));
    format!(
        "Volume {} m³ ± {} m³",
        format_volume(ws.volume),
        format_volume_error(ws.volume_error)
    )
}

#[test]
fn the_checkbox_shows_the_surface_and_its_numbers() {
    let mut h = super::harness_with(viewer("paired"), 4200.0);
    let theme = h.state().theme();
    assert!(h.state().draw_list(&theme).analysis.is_empty());
    h.get_by_label("Show the reachable workspace").click();
    h.run();
    settle(&mut h);
    let s = h.state().scenario().clone();
    assert!(
        h.query_by_label(&volume_line(&s, [Angle::ZERO; 3]))
            .is_some(),
        "the volume of `stewart workspace` at {FINE} columns"
    );
    assert!(h.query_by_label_contains("96 × 96 columns in").is_some());
    assert!(
        h.query_by_label("The platform centre is inside the workspace.")
            .is_some()
    );
    assert!(h.query_by_label("Past κ = 30 or singular: 0 of").is_none());
    assert!(
        h.query_by_label_contains("Past κ = 30 or singular: 0 of")
            .is_some()
    );
    // Surface and slice are drawn.
    assert_eq!(h.state().draw_list(&theme).analysis.len(), 2);
    h.get_by_label("Conditioning slice").click();
    h.run();
    assert_eq!(h.state().draw_list(&theme).analysis.len(), 1);
}

#[test]
fn the_surface_follows_the_geometry_and_the_pose() {
    let mut h = shown("paired", Lang::En);
    let before = h
        .state()
        .tools
        .workspace
        .latest
        .clone()
        .unwrap_or_else(|| panic!("none"));
    // A longer stroke: a larger workspace.
    let mut s = h.state().scenario().clone();
    let mut params = s.geometry.params().clone();
    params.stroke.max = Some(1.4);
    h.state_mut().set_geometry(params.clone());
    h.run();
    settle(&mut h);
    let after = h
        .state()
        .tools
        .workspace
        .latest
        .clone()
        .unwrap_or_else(|| panic!("none"));
    assert!(
        after.volume > before.volume * 1.1,
        "{} → {}",
        before.volume,
        after.volume
    );
    s.geometry = stewart_kinematics::Geometry::new(params).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        h.query_by_label(&volume_line(&s, [Angle::ZERO; 3]))
            .is_some()
    );
    // The pose turns: the surface is recomputed at its orientation.
    let pose = Pose::from_xyz_rpy_deg([0.0, 0.0, 0.8], [0.0, 0.0, 20.0]);
    h.state_mut().playback.manual = pose;
    h.run();
    eprintln!(
        "pose now {:?} mode {:?}",
        h.state().pose().rpy_degrees(),
        h.state().playback.mode
    );
    settle(&mut h);
    let turned = h
        .state()
        .tools
        .workspace
        .latest
        .clone()
        .unwrap_or_else(|| panic!("none"));
    assert_eq!(turned.request.orientation[2], Angle::from_degrees(20.0));
    assert!(
        h.query_by_label(&volume_line(
            &s,
            [Angle::ZERO, Angle::ZERO, Angle::from_degrees(20.0)]
        ))
        .is_some()
    );
}

#[test]
fn a_chosen_orientation_can_leave_the_centre_outside() {
    let mut h = shown("paired", Lang::En);
    let s = h.state().scenario().clone();
    let at = |roll: f64| Pose::from_xyz_rpy_deg([0.0, 0.0, 1.0], [roll, 0.0, 0.0]);
    let level = at(0.0);
    assert!(workspace::pose_within_limits(
        &s.geometry,
        &s.limits,
        &level
    ));
    // The first roll (5° steps) at which this centre is out of reach; the workspace
    // there is not empty.
    let roll = (1..18)
        .map(|k| 5.0 * k as f64)
        .find(|&r| !workspace::pose_within_limits(&s.geometry, &s.limits, &at(r)))
        .unwrap_or_else(|| panic!("always reachable"));
    h.state_mut().playback.manual = level;
    h.run();
    settle(&mut h);
    assert!(
        h.query_by_label("The platform centre is inside the workspace.")
            .is_some()
    );
    // Rolled so far the legs cannot hold the centre there.
    h.state_mut().tools.workspace.follow_pose = false;
    h.state_mut().tools.workspace.orientation_deg = [roll, 0.0, 0.0];
    h.run();
    settle(&mut h);
    assert!(
        h.query_by_label_contains("Volume ").is_some(),
        "empty at roll {roll}°"
    );
    assert!(
        h.query_by_label("The platform centre is outside the workspace.")
            .is_some()
    );
}

#[test]
fn a_singular_platform_marks_every_slice_cell() {
    // The seed's layout is singular everywhere: every reachable cell is past the threshold.
    let h = shown("seed", Lang::En);
    let slice = h
        .state()
        .tools
        .workspace
        .latest
        .as_ref()
        .and_then(|o| o.slice.clone())
        .unwrap_or_else(|| panic!("no slice"));
    assert!(
        slice.reachable > 0 && slice.past == slice.reachable,
        "{slice:?}"
    );
    let line = format!(
        "Past κ = 30 or singular: {} of {} cells",
        slice.reachable, slice.reachable
    );
    assert!(h.query_by_label(&line).is_some(), "{line}");
}

#[test]
fn the_panel_reads_in_chinese() {
    let h = shown("paired", Lang::Zh);
    assert!(h.query_by_label("显示可达工作空间").is_some());
    assert!(h.query_by_label("动平台中心在工作空间内。").is_some());
    assert!(h.query_by_label_contains("体积 ").is_some());
    assert!(
        h.query_by_label_contains("超过 κ = 30 或奇异：0 / ")
            .is_some()
    );
}

#[test]
fn the_slice_can_be_coloured_by_the_platforms_lowest_stiffness() {
    let mut h = shown("paired", Lang::En);
    h.get_by_label("coloured by stiffness").click();
    h.run();
    settle(&mut h);
    super::look(&mut h, "stiffness_slice.png");
    let state = h.state();
    let slice = state
        .tools
        .workspace
        .latest
        .as_ref()
        .and_then(|o| o.slice.as_ref())
        .unwrap_or_else(|| panic!("no slice"));
    let [low, high] = slice
        .stiffness
        .unwrap_or_else(|| panic!("not a stiffness slice"));
    assert!(low > 0.0 && low < high, "{low} … {high}");
    // No actuator stiffness in the preset: per unit stiffness, and it says so.
    assert!(
        h.query_by_label_contains("(per unit actuator stiffness)")
            .is_some()
    );
    // The paired platform is stiffest centred: the slice's stiffest cells, next to the
    // centre, come close to the stiffness at home (by the core) without passing it.
    let s = state.scenario();
    let home =
        dynamics::lowest_stiffness(&s.geometry, &s.geometry.home_pose(), 1.0).unwrap_or(f64::NAN);
    assert!(
        high <= home * (1.0 + 1e-9) && high > 0.95 * home,
        "{low} … {high}, home {home}"
    );
    assert_eq!(slice.past, 0);
    // Back to conditioning: the slice is the conditioning's again.
    h.get_by_label("coloured by conditioning").click();
    h.run();
    settle(&mut h);
    let again = h
        .state()
        .tools
        .workspace
        .latest
        .as_ref()
        .and_then(|o| o.slice.as_ref())
        .map(|s| s.stiffness);
    assert_eq!(again, Some(None));
}

#[test]
fn certify_proves_the_bracket_the_command_line_gives_and_says_when_it_is_stale() {
    let mut h = shown("paired", Lang::En);
    h.get_by_label("Certify the volume").click();
    // One frame takes the click (a spinner then turns while it runs).
    h.step();
    h.state_mut().tools.workspace.certified.wait();
    h.run();
    super::look(&mut h, "certified.png");
    let s = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
    let level = s.geometry.home_pose();
    let never = || false;
    let request = stewart_kinematics::analysis::certified::workspace::WorkspaceRequest {
        orientation: &level,
        boundary_width: 0.01 * s.geometry.characteristic_length(),
        budget: 3_000_000,
        stop: &never,
    };
    let c = stewart_kinematics::analysis::certified::workspace::certified_workspace(
        &s.geometry,
        &s.limits,
        &request,
    )
    .expect("stroke");
    // The bounds rounded outward, as the command line prints them.
    let bounds = format!(
        "Proven: {} m³ ≤ volume ≤ {} m³",
        crate::volume_text::format_bound(c.inner_m3, false),
        crate::volume_text::format_bound(c.inner_m3 + c.boundary_m3, true)
    );
    assert!(
        h.query_by_label_contains(&bounds).is_some(),
        "{bounds} not shown"
    );
    assert!(
        h.query_by_label_contains("proven reachable (green)")
            .is_some()
    );
    // Another orientation: the bracket shown is no longer for it.
    h.state_mut().tools.workspace.follow_pose = false;
    h.state_mut().tools.workspace.orientation_deg = [5.0, 0.0, 0.0];
    h.run();
    assert!(h.query_by_label_contains("certify again").is_some());
}
