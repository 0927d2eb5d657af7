//! Widgets shared by the panels: a slider for a declared setting, coloured messages.

use egui::{Color32, RichText};
use stewart_kinematics::Scenario;
use stewart_kinematics::io::settings::{self, Group, Setting, SettingTarget, Unit};

use crate::i18n::Lang;
use crate::i18n::words::{setting_label, setting_label_with_unit};
use crate::viewer::error::ActionStatus;
use crate::viewer::error::ViewerError;
use crate::viewer::state::document::Document;
use crate::viewer::state::editor::Editor;

/// Red for refusals and errors.
pub(crate) const ERROR: Color32 = Color32::from_rgb(220, 40, 40);
/// Amber for notes that limit but do not refuse.
pub(crate) const WARNING: Color32 = Color32::from_rgb(230, 150, 20);
/// Green for success.
pub(crate) const OK: Color32 = Color32::from_rgb(60, 160, 80);
/// A range proven free of singularity.
pub(crate) const CERTIFIED: Color32 = Color32::from_rgb(90, 160, 235);
/// What lies out of reach (reach bars, the roll–pitch map).
pub(crate) const UNREACHABLE: Color32 = Color32::from_rgb(70, 40, 45);

/// A slider for the setting of `target`, labelled with its unit (a switch is a
/// checkbox); optional settings get a checkbox that switches them on (at their slider's
/// start) and off. Right-click resets to the default. Edits go through the setting's
/// validation.
pub(crate) fn setting_slider(ui: &mut egui::Ui, ed: &mut Editor, target: SettingTarget) {
    let setting = settings::of(target);
    let scenario = ed.scenario();
    if !setting.applies(scenario) {
        return;
    }
    let current = setting.get(scenario);
    if setting.unit == Unit::Switch {
        let mut on = current.is_some_and(|v| v != 0.0);
        let t = ed.lang;
        if ui
            .checkbox(&mut on, setting_label(t, setting))
            .on_hover_text(slider_tip(t, setting, scenario))
            .changed()
        {
            ed.apply(setting, Some(f64::from(u8::from(on))));
        }
        return;
    }
    let t = ed.lang;
    let kind = scenario.geometry.actuator().kind();
    let mut edit: Option<Option<f64>> = None;
    ui.horizontal(|ui| {
        if setting.optional() {
            edit = switch_on(ui, t, setting, scenario, current.is_some());
        }
        match current {
            Some(value) => {
                if let Some(slid) = value_slider(ui, t, setting, scenario, value) {
                    edit = Some(slid);
                }
            }
            None => {
                ui.label(t.fmt(
                    "widgets.off",
                    &[("name", &setting_label_with_unit(t, setting, kind))],
                ));
            }
        }
    });
    if let Some(value) = edit {
        ed.apply(setting, value);
    }
}

/// An optional setting's switch, `on` when it has a value: `Some` with the value to write
/// (`None`: off) when it was switched.
fn switch_on(
    ui: &mut egui::Ui,
    t: Lang,
    setting: &Setting,
    scenario: &Scenario,
    on: bool,
) -> Option<Option<f64>> {
    let mut on = on;
    let name = setting_label(t, setting);
    // A limit is switched on; a quantity (a stiffness) is given, from a typical value.
    let tip = if setting.unit == Unit::Stiffness {
        let start = setting.value_when_switched_on(scenario);
        t.fmt(
            "widgets.use_value",
            &[
                ("name", &name),
                ("value", &format!("{start:e}")),
                ("unit", &unit_of(setting, scenario)),
            ],
        )
    } else {
        t.fmt("widgets.use_limit", &[("name", &name)])
    };
    ui.checkbox(&mut on, "")
        .on_hover_text(tip)
        .changed()
        .then(|| on.then(|| setting.value_when_switched_on(scenario)))
}

/// The slider of a setting at `value`: `Some` with what to write when it was dragged,
/// stepped finely with Shift, or reset from its menu.
fn value_slider(
    ui: &mut egui::Ui,
    t: Lang,
    setting: &Setting,
    scenario: &Scenario,
    value: f64,
) -> Option<Option<f64>> {
    let kind = scenario.geometry.actuator().kind();
    let mut edit = None;
    let range = setting.range_for(scenario);
    let mut v = value;
    // The right and middle buttons open the menu or pan: they never move the knob.
    let other_button = ui.input(|i| {
        [egui::PointerButton::Secondary, egui::PointerButton::Middle]
            .into_iter()
            .any(|b| i.pointer.button_down(b) || i.pointer.button_released(b))
    });
    let fine = ui.input(|i| i.modifiers.shift);
    // A drag that went fine stays fine until its button is up, even when Shift is
    // let go first (the plain slider would then jump to the pointer, as a
    // second undo step). Keyed by the setting: one slider is dragged at a time.
    let fine_id = ui.scope_id().with(("fine drag", &setting.key));
    let was_fine = ui.data(|d| d.get_temp::<bool>(fine_id)).unwrap_or(false);
    // While a fine drag may go on, the slider shows the value applied, not where
    // the pointer would put a plain drag.
    let frozen = (fine || was_fine) && ui.input(|i| i.pointer.primary_down());
    let label = setting_label_with_unit(t, setting, kind);
    let fits = make_room_for_the_label(ui, &label, value);
    let text = fits.then(|| label.clone());
    let slid = ui.add(slider(setting, text, range.clone(), &mut v, frozen));
    // Too long even beside the shortest track: its own label, wrapped, names it.
    let slid = if fits {
        slid
    } else {
        let words = ui.add(egui::Label::new(label).wrap());
        slid.labelled_by(words.id)
    };
    // A slider senses drags only: clicks too, so that the right button's click
    // opens the reset menu.
    let response = slid
        .union(slid.interact(egui::Sense::click()))
        .on_hover_text(slider_tip(t, setting, scenario));
    let held = slid.is_pointer_button_down_on() || slid.drag_stopped();
    let fine = fine || (held && was_fine);
    let still_fine = fine && slid.is_pointer_button_down_on();
    if still_fine != was_fine {
        ui.data_mut(|d| d.insert_temp(fine_id, still_fine));
    }
    if fine && held {
        // Fine steps from where the value is, by the pointer's motion alone
        // (the plain slider would jump to the pointer).
        let dx = ui.input(|i| i.pointer.delta().x);
        if dx != 0.0 && slid.is_pointer_button_down_on() {
            edit = Some(Some(fine_drag(ui, setting, &range, value, dx)));
        }
    } else if slid.changed() && !other_button {
        edit = Some(Some(v));
    }
    if let Some(reset) = reset_menu(&response, t, setting, scenario) {
        edit = Some(reset);
    }
    edit
}

/// The slider's right-click menu: back to the default (or off, for an optional setting
/// without one). The value to write when chosen.
fn reset_menu(
    response: &egui::Response,
    t: Lang,
    setting: &Setting,
    scenario: &Scenario,
) -> Option<Option<f64>> {
    let mut chosen = None;
    response.context_menu(|ui| {
        let default = setting.default_for(scenario);
        let text = default.map_or_else(
            || t.tr("widgets.switch_off").to_owned(),
            |d| {
                t.fmt(
                    "widgets.reset_to",
                    &[("value", &d), ("unit", &unit_of(setting, scenario))],
                )
            },
        );
        if ui
            .button(text)
            .on_hover_text(t.tr("widgets.reset_tip"))
            .clicked()
        {
            chosen = Some(default);
            ui.close();
        }
    });
    chosen
}

/// The shortest a slider's track gets to leave its label room, points.
const SHORTEST_TRACK: f32 = 48.0;

/// Shorten this row's slider track (down to [`SHORTEST_TRACK`]) so that its number box and
/// `label` fit in the width left: a long label ("cylinder centre of mass (m)") is read
/// whole in a narrow panel instead of cut at its edge. Whether it fits on one line.
fn make_room_for_the_label(ui: &mut egui::Ui, label: &str, value: f64) -> bool {
    let font = egui::TextStyle::Body.resolve(ui.style());
    let width = |text: String| {
        ui.painter()
            .layout_no_wrap(text, font.clone(), Color32::WHITE)
            .size()
            .x
    };
    let number = width(format!("{value:.4}")).max(ui.spacing().interact_size.x)
        + 2.0 * ui.spacing().button_padding.x;
    let gaps = 3.0 * ui.spacing().item_spacing.x;
    // The width left in sight (a wider row above may have widened the layout past the
    // panel's edge, where the panel cuts).
    let left = ui
        .available_width()
        .min(ui.clip_rect().right() - ui.cursor().min.x);
    let room = left - width(label.to_owned()) - number - gaps;
    let track = &mut ui.spacing_mut().slider_width;
    *track = room.clamp(SHORTEST_TRACK, *track);
    room >= SHORTEST_TRACK
}

/// `slider` (given no text) in a row of its own with `text` beside it, its track shortened
/// to leave the text room, or the text wrapped beside the shortest track; `value` is the
/// value it shows (for the width of its number box).
pub(super) fn fitted_slider(
    ui: &mut egui::Ui,
    text: &str,
    value: f64,
    slider: egui::Slider<'_>,
) -> egui::Response {
    ui.horizontal(|ui| {
        if make_room_for_the_label(ui, text, value) {
            ui.add(slider.text(text))
        } else {
            let slid = ui.add(slider);
            let words = ui.add(egui::Label::new(text).wrap());
            slid.labelled_by(words.id)
        }
    })
    .inner
}

/// How far a drag with Shift held moves the value, against a plain drag.
const FINE: f64 = 0.1;

/// Whether a slider over `range` is logarithmic (positive ranges over three decades).
fn is_logarithmic(range: &std::ops::RangeInclusive<f64>) -> bool {
    *range.start() > 0.0 && range.end() / range.start() > 1000.0
}

/// The value after a Shift drag of `dx` points from `value`: a tenth of what the plain
/// drag would move (in the logarithm's scale on a logarithmic slider).
fn fine_drag(
    ui: &egui::Ui,
    setting: &Setting,
    range: &std::ops::RangeInclusive<f64>,
    value: f64,
    dx: f32,
) -> f64 {
    let share = FINE * f64::from(dx) / f64::from(ui.spacing().slider_width.max(1.0));
    let (lo, hi) = (*range.start(), *range.end());
    let v = if is_logarithmic(range) && value > 0.0 {
        value * ((hi / lo).ln() * share).exp()
    } else {
        value + (hi - lo) * share
    };
    if setting.unit == Unit::Count {
        v.round()
    } else {
        v
    }
}

/// A setting's tooltip: its file key, accepted values, default, and the gestures.
fn slider_tip(t: Lang, setting: &Setting, scenario: &Scenario) -> String {
    let default = setting.default_for(scenario).map_or_else(
        || t.tr("widgets.default_off").to_owned(),
        stewart_kinematics::ground::bounds::short,
    );
    t.fmt(
        "widgets.slider_tip",
        &[
            ("key", &setting.key),
            ("accepted", &setting.accepted_words()),
            ("default", &default),
            ("unit", &unit_of(setting, scenario)),
        ],
    )
}

/// The symbol of a setting's unit for the scenario's actuators (a stiffness is N/m for
/// legs, N·m/rad for servos).
fn unit_of(setting: &Setting, scenario: &Scenario) -> &'static str {
    setting.unit.symbol_for(scenario.geometry.actuator().kind())
}

/// A setting's slider over `range` showing `value`, with `text` beside it (none: its label
/// is laid out apart); `frozen`, it keeps the value (a fine drag moves it instead, from the
/// pointer's motion).
fn slider<'a>(
    setting: &Setting,
    text: Option<String>,
    range: std::ops::RangeInclusive<f64>,
    value: &'a mut f64,
    frozen: bool,
) -> egui::Slider<'a> {
    let logarithmic = is_logarithmic(&range);
    let s = egui::Slider::from_get_set(range, move |set| {
        if let Some(new) = set
            && !frozen
        {
            *value = new;
        }
        *value
    })
    .text(text.unwrap_or_default())
    .clamping(egui::SliderClamping::Never)
    .logarithmic(logarithmic);
    if setting.unit == Unit::Count {
        s.integer()
    } else if *setting.range.start() > 0.0 && *setting.range.start() < 1e-3 {
        // Tolerances span decades: scientific notation reads (and types) better.
        s.custom_formatter(|v, _| format!("{v:.2e}"))
            .custom_parser(|text| text.trim().parse().ok())
    } else {
        s
    }
}

/// The outcome of the last action, green or red (an error in `t`'s words).
pub(crate) fn status(ui: &mut egui::Ui, status: &ActionStatus, t: Lang) {
    match status {
        Some(Ok(message)) => {
            ui.label(RichText::new(message).color(OK));
        }
        Some(Err(e)) => {
            ui.label(RichText::new(e.words(t)).color(ERROR));
        }
        None => {}
    }
}

/// Why the last edit in one of `groups` was refused, if it was.
pub(crate) fn edit_error(ui: &mut egui::Ui, doc: &Document, t: Lang, groups: &[Group]) {
    if let Some((group, e)) = &doc.edit_error
        && groups.contains(group)
    {
        not_applied(ui, e, t);
    }
}

/// "Not drawn", and why, in red (a CAD part whose file cannot be used now).
pub(crate) fn not_shown(ui: &mut egui::Ui, e: &ViewerError, t: Lang) {
    let why = e.words(t);
    ui.label(RichText::new(t.fmt("widgets.not_shown", &[("why", &why)])).color(ERROR));
}

/// "Not applied", and why, in red.
pub(crate) fn not_applied(ui: &mut egui::Ui, e: &ViewerError, t: Lang) {
    let why = e.words(t);
    ui.label(RichText::new(t.fmt("widgets.not_applied", &[("why", &why)])).color(ERROR));
}

/// A bar over `full` (slider units) with the `reachable` part in green, the range proven
/// free of singularity (`certified`) as a blue line along its foot, and the `value`
/// marked: drawn under a slider of that `width`, or alone.
pub(crate) fn range_bar(
    ui: &mut egui::Ui,
    full: [f64; 2],
    reachable: Option<[f64; 2]>,
    certified: Option<[f64; 2]>,
    value: f64,
    width: f32,
) {
    let (rect, _) = ui.allocate_exact_size(egui::vec2(width, 5.0), egui::Sense::hover());
    let painter = ui.painter_at(rect);
    let x = |v: f64| {
        let f = ((v - full[0]) / (full[1] - full[0])).clamp(0.0, 1.0) as f32;
        rect.left() + f * rect.width()
    };
    painter.rect_filled(rect, 1.0, UNREACHABLE);
    if let Some([lo, hi]) = reachable {
        painter.rect_filled(
            egui::Rect::from_x_y_ranges(x(lo)..=x(hi), rect.y_range()),
            1.0,
            OK,
        );
    }
    if let Some([lo, hi]) = certified {
        let foot = rect.bottom() - 1.0;
        painter.line_segment(
            [egui::pos2(x(lo), foot), egui::pos2(x(hi), foot)],
            egui::Stroke::new(2.0, CERTIFIED),
        );
    }
    let vx = x(value);
    painter.line_segment(
        [
            egui::pos2(vx, rect.top() - 1.0),
            egui::pos2(vx, rect.bottom() + 1.0),
        ],
        egui::Stroke::new(2.0, ui.visuals().strong_text_color()),
    );
}

/// The width of a button that fits the widest of `words` (so that it keeps one width when
/// its words change), points.
pub(crate) fn button_width_for<S: AsRef<str>>(ui: &egui::Ui, words: &[S]) -> f32 {
    let widest = (words.iter())
        .map(|w| {
            egui::WidgetText::from(w.as_ref())
                .into_galley(
                    ui,
                    Some(egui::TextWrapMode::Extend),
                    f32::INFINITY,
                    egui::TextStyle::Button,
                )
                .size()
                .x
        })
        .fold(0.0, f32::max);
    widest + 2.0 * ui.spacing().button_padding.x
}
