//! Workspace: the reachable volume at an orientation drawn in the 3D view, its volume and
//! extent, whether the platform centre lies inside, and a horizontal slice coloured by
//! the condition number with its colour bar.

use egui::{Color32, RichText};
use stewart_kinematics::analysis::workspace;
use stewart_kinematics::{Pose, Scenario};
use stewart_render::colormap;

use super::context::PanelContext;
use super::widgets::{self, ERROR, OK, WARNING};
use crate::i18n::Lang;
use crate::viewer::tools::certified::CertifiedKey;
use crate::viewer::tools::workspace::WorkspaceTool;
use crate::volume_text::{format_bound, format_volume, format_volume_error};
use stewart_kinematics::analysis::certified::workspace::{
    BoxClass, CertifiedWorkspace, ClassedBox,
};

/// The panel: the workspace tool, for `scenario` with `pose` shown; `open`: whether it
/// starts open.
pub(crate) fn show(
    ui: &mut egui::Ui,
    w: &mut WorkspaceTool,
    scenario: &Scenario,
    cx: &PanelContext,
) {
    let (t, open) = (cx.lang, cx.expand);
    let pose = &cx.pose;
    egui::CollapsingHeader::new(t.tr("workspace_panel.heading"))
        .default_open(open || w.show)
        .show(ui, |ui| {
            ui.checkbox(&mut w.show, t.tr("workspace_panel.show"))
                .on_hover_text(t.tr("workspace_panel.show_tip"));
            if !w.show {
                return;
            }
            orientation(ui, w, t);
            numbers(ui, w, scenario, pose, t);
            certified(ui, w, scenario, pose, t);
            ui.separator();
            let centre_z = scenario.geometry.platform_centre(pose).z;
            let condition_max = scenario.checks.condition_max;
            let per_unit = scenario.dynamics.actuator_stiffness.is_none();
            slice(ui, w, centre_z, condition_max, t);
            if w.show_slice {
                stiffness_note(ui, w, per_unit, t);
            }
        });
}

/// The certified bracket: a button that asks for it, the bracket for the scenario and
/// orientation shown, and a horizontal slice of its boxes at the platform's height.
fn certified(ui: &mut egui::Ui, w: &mut WorkspaceTool, scenario: &Scenario, pose: &Pose, t: Lang) {
    let key = CertifiedKey {
        geometry: scenario.geometry.clone(),
        limits: scenario.limits,
        orientation: w.orientation_at(pose),
    };
    ui.horizontal(|ui| {
        let busy = w.certified.busy();
        if ui
            .add_enabled(!busy, egui::Button::new(t.tr("workspace_panel.certify")))
            .on_hover_text(t.tr("workspace_panel.certify_tip"))
            .clicked()
        {
            w.certified.start(key.clone());
        }
        if busy {
            ui.spinner();
        }
    });
    let Some(outcome) = &w.certified.latest else {
        return;
    };
    if outcome.key != key {
        ui.label(RichText::new(t.tr("workspace_panel.certified_stale")).color(WARNING));
        return;
    }
    let Some(c) = &outcome.workspace else {
        ui.label(t.tr("workspace_panel.certified_none"));
        return;
    };
    let share = if c.inner_m3 > 0.0 {
        format!("{:.1}", 100.0 * c.boundary_m3 / c.inner_m3)
    } else {
        "∞".to_owned()
    };
    ui.label(
        RichText::new(t.fmt(
            "workspace_panel.certified",
            &[
                ("lo", &format_bound(c.inner_m3, false)),
                ("hi", &format_bound(c.inner_m3 + c.boundary_m3, true)),
                ("share", &share),
                ("boxes", &c.tested),
                ("width", &format!("{:.1}", 1000.0 * outcome.width)),
            ],
        ))
        .color(OK),
    );
    if c.cut_short {
        ui.label(RichText::new(t.tr("workspace_panel.certified_cut")).color(WARNING));
    }
    ui.label(t.tr("workspace_panel.certified_slice"));
    certified_slice(ui, c, pose.position.z);
}

/// The certified boxes the plane `z` crosses, seen from above: inner green, boundary
/// amber over them, on the smallest square holding them. (A flat stretch of the edge with
/// no amber is a limit that happens to fall on a box face: decided exactly there.)
fn certified_slice(ui: &mut egui::Ui, c: &CertifiedWorkspace, z: f64) {
    let crossed: Vec<_> = c
        .boxes
        .iter()
        .filter(|b| b.position[2].contains(z))
        .collect();
    let side = ui.available_width().clamp(120.0, 240.0);
    let (rect, _) = ui.allocate_exact_size(egui::vec2(side, side), egui::Sense::hover());
    let painter = ui.painter_at(rect);
    painter.rect_filled(rect, 2.0, ui.visuals().extreme_bg_color);
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for b in &crossed {
        for k in 0..2 {
            lo[k] = lo[k].min(b.position[k].lo());
            hi[k] = hi[k].max(b.position[k].hi());
        }
    }
    let span = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    if !(span.is_finite() && span > 0.0) {
        return;
    }
    let centre = [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0];
    let at = |x: f64, y: f64| {
        egui::pos2(
            rect.center().x + ((x - centre[0]) / span) as f32 * rect.width(),
            rect.center().y - ((y - centre[1]) / span) as f32 * rect.height(),
        )
    };
    // The proven boxes first, the undecided over them.
    let (inner, undecided): (Vec<&ClassedBox>, Vec<&ClassedBox>) = crossed
        .into_iter()
        .partition(|b| b.class == BoxClass::Inner);
    for b in inner.into_iter().chain(undecided) {
        let colour = match b.class {
            BoxClass::Inner => OK,
            _ => WARNING,
        };
        // Half a pixel more each way: boxes finer than a pixel still join up.
        let r = egui::Rect::from_two_pos(
            at(b.position[0].lo(), b.position[1].lo()),
            at(b.position[0].hi(), b.position[1].hi()),
        )
        .expand(0.5);
        painter.rect_filled(r, 0.0, colour);
    }
}

/// At the pose's orientation, or at one chosen with three drag values.
fn orientation(ui: &mut egui::Ui, w: &mut WorkspaceTool, t: Lang) {
    ui.radio_value(&mut w.follow_pose, true, t.tr("workspace_panel.follow"));
    ui.horizontal(|ui| {
        ui.radio_value(&mut w.follow_pose, false, t.tr("workspace_panel.chosen"));
        for (k, key) in ["pose.roll", "pose.pitch", "pose.yaw"].iter().enumerate() {
            ui.add_enabled(
                !w.follow_pose,
                egui::DragValue::new(&mut w.orientation_deg[k])
                    .range(-90.0..=90.0)
                    .speed(0.25)
                    .suffix("°"),
            )
            .on_hover_text(t.tr(key));
        }
    });
}

/// Progress, volume, extent, and where the platform centre lies.
fn numbers(ui: &mut egui::Ui, w: &WorkspaceTool, scenario: &Scenario, pose: &Pose, t: Lang) {
    if let Some(e) = &w.error {
        widgets::not_applied(ui, e, t);
        return;
    }
    let Some(o) = &w.latest else {
        ui.label(t.tr("workspace_panel.computing"));
        return;
    };
    let ms = format!("{:.0}", o.elapsed.as_secs_f64() * 1e3);
    let columns = o.resolution.to_string();
    let key = if w.busy() {
        "workspace_panel.refining"
    } else {
        "workspace_panel.columns"
    };
    ui.label(RichText::new(t.fmt(key, &[("n", &columns), ("ms", &ms)])).small());
    if w.stale() {
        // The pose moved on while this was computed (playback on a slow machine): say for
        // which orientation the surface shown stands.
        let [roll, pitch, yaw] = o.request.orientation.map(|a| format!("{:.1}", a.degrees()));
        ui.label(
            RichText::new(t.fmt(
                "workspace_panel.stale",
                &[("roll", &roll), ("pitch", &pitch), ("yaw", &yaw)],
            ))
            .small()
            .color(ui.visuals().warn_fg_color),
        );
    }
    let Some(extent) = o.extent else {
        ui.label(RichText::new(t.tr("workspace_panel.empty")).color(ERROR));
        return;
    };
    ui.label(t.fmt(
        "workspace_panel.volume",
        &[
            ("volume", &format_volume(o.volume)),
            ("error", &format_volume_error(o.volume_error)),
        ],
    ));
    for (axis, [lo, hi]) in ["x", "y", "z"].iter().zip(extent) {
        ui.label(
            RichText::new(t.fmt(
                "workspace_panel.extent",
                &[
                    ("axis", axis),
                    ("min", &format!("{lo:.4}")),
                    ("max", &format!("{hi:.4}")),
                ],
            ))
            .monospace(),
        );
    }
    let (key, colour) = if centre_inside(w, scenario, pose) {
        ("workspace_panel.inside", OK)
    } else {
        ("workspace_panel.outside", ERROR)
    };
    ui.label(RichText::new(t.tr(key)).color(colour));
    if o.split_columns > 0 {
        ui.label(
            RichText::new(t.fmt("workspace_panel.split", &[("count", &o.split_columns)])).small(),
        );
    }
}

/// Whether the platform centre of `pose` is reachable at the workspace's orientation (the
/// pose itself when the orientation follows it).
pub(crate) fn centre_inside(w: &WorkspaceTool, scenario: &Scenario, pose: &Pose) -> bool {
    let [roll, pitch, yaw] = w.orientation_at(pose);
    let g = &scenario.geometry;
    // The same centre at the workspace's orientation.
    let probe = Pose::new(pose.position, roll, pitch, yaw);
    let shift = g.platform_centre(pose) - g.platform_centre(&probe);
    let probe = probe.with_position(pose.position + shift);
    workspace::pose_within_limits(g, &scenario.limits, &probe)
}

/// The slice's switches, its colour bar and the cells past the threshold: the tool alone,
/// with the platform centre's height and the near-singular threshold.
fn slice(ui: &mut egui::Ui, w: &mut WorkspaceTool, centre_z: f64, condition_max: f64, t: Lang) {
    let top = w
        .latest
        .as_ref()
        .and_then(|o| o.extent)
        .map_or(2.0 * centre_z.max(0.1), |e| e[2][1]);
    ui.checkbox(&mut w.show_slice, t.tr("workspace_panel.slice"))
        .on_hover_text(t.tr("workspace_panel.slice_tip"));
    if !w.show_slice {
        return;
    }
    ui.checkbox(&mut w.slice_follows, t.tr("workspace_panel.slice_follows"));
    if w.slice_follows {
        w.slice_height = centre_z;
    }
    ui.add_enabled(
        !w.slice_follows,
        egui::Slider::new(&mut w.slice_height, 0.0..=top.max(0.01))
            .suffix(" m")
            .text(t.tr("workspace_panel.slice_height")),
    );
    ui.horizontal(|ui| {
        ui.radio_value(
            &mut w.slice_by_stiffness,
            false,
            t.tr("workspace_panel.by_conditioning"),
        );
        ui.radio_value(
            &mut w.slice_by_stiffness,
            true,
            t.tr("workspace_panel.by_stiffness"),
        )
        .on_hover_text(t.tr("workspace_panel.by_stiffness_tip"));
    });
    if w.slice_by_stiffness {
        return;
    }
    colour_bar(ui, condition_max);
    if let Some(s) = w.latest.as_ref().and_then(|o| o.slice.as_ref()) {
        let colour = if s.past > 0 { WARNING } else { OK };
        ui.label(
            RichText::new(t.fmt(
                "workspace_panel.past",
                &[
                    ("max", &format!("{condition_max}")),
                    ("past", &s.past),
                    ("cells", &s.reachable),
                ],
            ))
            .color(colour),
        );
    }
}

/// A stiffness slice's colours: viridis from its lowest stiffness to its highest, and
/// the two values (per unit actuator stiffness when none is given).
fn stiffness_note(ui: &mut egui::Ui, w: &WorkspaceTool, per_unit: bool, t: Lang) {
    let Some([low, high]) = w
        .latest
        .as_ref()
        .and_then(|o| o.slice.as_ref())
        .and_then(|s| s.stiffness)
    else {
        return;
    };
    let width = ui.available_width().clamp(120.0, 280.0);
    let (rect, _) = ui.allocate_exact_size(egui::vec2(width, 12.0), egui::Sense::hover());
    let steps = 64;
    for k in 0..steps {
        let [r, g, b] = colormap::viridis((k as f64 + 0.5) / steps as f64);
        let x0 = rect.left() + rect.width() * k as f32 / steps as f32;
        let x1 = rect.left() + rect.width() * (k + 1) as f32 / steps as f32;
        ui.painter().rect_filled(
            egui::Rect::from_x_y_ranges(x0..=x1 + 0.5, rect.y_range()),
            0.0,
            Color32::from_rgb(r, g, b),
        );
    }
    let unit = if per_unit {
        t.tr("workspace_panel.per_unit")
    } else {
        ""
    };
    ui.label(t.fmt(
        "workspace_panel.stiffness_range",
        &[
            ("low", &format!("{low:.4e}")),
            ("high", &format!("{high:.4e}")),
            ("unit", &unit),
        ],
    ));
}

/// Viridis from 1 to `condition_max` (log scale) with ticks, then the colour past it.
fn colour_bar(ui: &mut egui::Ui, condition_max: f64) {
    let width = ui.available_width().clamp(120.0, 280.0);
    let (rect, _) = ui.allocate_exact_size(egui::vec2(width, 30.0), egui::Sense::hover());
    let painter = ui.painter_at(rect);
    let bar = egui::Rect::from_min_size(rect.min, egui::vec2(width - 22.0, 12.0));
    let steps = 64;
    for k in 0..steps {
        let s = (k as f64 + 0.5) / steps as f64;
        let [r, g, b] = colormap::viridis(s);
        let x0 = bar.left() + bar.width() * k as f32 / steps as f32;
        let x1 = bar.left() + bar.width() * (k + 1) as f32 / steps as f32;
        painter.rect_filled(
            egui::Rect::from_x_y_ranges(x0..=x1 + 0.5, bar.y_range()),
            0.0,
            Color32::from_rgb(r, g, b),
        );
    }
    let [r, g, b] = colormap::PAST;
    painter.rect_filled(
        egui::Rect::from_min_size(
            egui::pos2(bar.right() + 6.0, bar.top()),
            egui::vec2(16.0, 12.0),
        ),
        0.0,
        Color32::from_rgb(r, g, b),
    );
    let text = ui.visuals().text_color();
    let max = condition_max.max(1.5);
    let mut marks: Vec<f64> = [1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0, 1000.0]
        .into_iter()
        .filter(|m| *m < max * 0.8)
        .collect();
    marks.push(max);
    for m in marks {
        let x = bar.left() + bar.width() * (m.ln() / max.ln()) as f32;
        painter.line_segment(
            [
                egui::pos2(x, bar.bottom()),
                egui::pos2(x, bar.bottom() + 3.0),
            ],
            egui::Stroke::new(1.0, text),
        );
        painter.text(
            egui::pos2(x, bar.bottom() + 3.0),
            egui::Align2::CENTER_TOP,
            format!("{m}"),
            egui::FontId::proportional(super::SMALLEST_TEXT),
            text,
        );
    }
}
