//! The controls' panel on the left: as wide as the user made it by dragging its edge, and
//! never wider because of what it shows. A row wider than the panel is cut at its edge
//! (sliders make room for their labels first, see `widgets`); the width egui remembers,
//! in the session too, is the user's.

use egui::containers::panel::PanelState;

/// The panel's id salt.
const ID: &str = "controls";

/// The panel's width before anyone drags it, points.
pub(crate) const DEFAULT_WIDTH: f32 = 320.0;

/// The panel, its width within `range`, with `add` inside (its own scrolling); returns the
/// width drawn, points.
pub(super) fn show(
    ui: &mut egui::Ui,
    frame: egui::Frame,
    range: std::ops::RangeInclusive<f32>,
    add: impl FnOnce(&mut egui::Ui),
) -> f32 {
    let id = panel_id(ui);
    let before = PanelState::load(ui.ctx(), id);
    let drawn = egui::Panel::left(ID)
        .frame(frame)
        .resizable(true)
        .default_size(DEFAULT_WIDTH)
        .size_range(range)
        .show(ui, |ui| {
            // The content in a child of exactly the panel's area, clipped there; the panel
            // claims that area alone, so a wide row cannot widen it.
            let area = ui.available_rect_before_wrap();
            let mut inside = ui.new_child(egui::UiBuilder::new().max_rect(area));
            inside.shrink_clip_rect(area);
            add(&mut inside);
            ui.allocate_rect(area, egui::Sense::hover());
        })
        .response
        .rect
        .width();
    // Only a drag of the edge changes the width remembered.
    let resize = ui.ctx().read_response(id.with("__resize"));
    let dragged = resize
        .as_ref()
        .is_some_and(|r| r.dragged() || r.drag_stopped());
    if let Some(after) = PanelState::load(ui.ctx(), id)
        && !dragged
    {
        let kept = before.map_or(DEFAULT_WIDTH, |b| b.size().x);
        if (after.size().x - kept).abs() > 0.5 {
            let mut outer_rect = after.outer_rect;
            outer_rect.set_width(kept);
            ui.ctx()
                .data_mut(|d| d.insert_persisted(id, PanelState { outer_rect }));
        }
    }
    drawn
}

/// The panel's id as egui keys its state (from the window's root).
fn panel_id(ui: &egui::Ui) -> egui::Id {
    ui.scope_id().with_salt(egui::IdSalt::new(ID))
}
