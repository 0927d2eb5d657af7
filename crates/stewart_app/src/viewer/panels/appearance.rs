//! Appearance: a CAD part (STL, OBJ, glTF) for each body the platform has — base,
//! platform, and its actuators' moving parts — with the file's unit, a turn and an offset
//! in the part's frame, and an own colour. Every change is one edit of `[appearance]`
//! (undoable, the meshes read again only when the file changes), seen at once in the 3D
//! view; a mesh that cannot be used is refused with its reason and the picture stays.

use egui::RichText;
use stewart_kinematics::io::settings::Group;
use stewart_kinematics::model::appearance::{Colour, MAX_OFFSET_M, MeshScale, Part, PartLook};

use super::widgets::edit_error;
use crate::i18n::Lang;
use crate::viewer::state::editor::Editor;

/// What the panel asks of the viewer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum AppearanceAction {
    /// Choose a mesh file for this part (the file dialog).
    Browse(Part),
}

/// The part's name in `t`.
pub(crate) fn part_name(part: Part, t: Lang) -> &'static str {
    t.tr(match part {
        Part::Base => "appearance.base",
        Part::Platform => "appearance.platform",
        Part::Cylinder => "appearance.cylinder",
        Part::Rod => "appearance.rod",
        Part::Horn => "appearance.horn",
    })
}

/// The section; what it asks of the viewer.
pub(crate) fn show(ui: &mut egui::Ui, ed: &mut Editor) -> Option<AppearanceAction> {
    let t = ed.lang;
    let mut asked = None;
    egui::CollapsingHeader::new(t.tr("appearance.heading"))
        .default_open(ed.expand)
        .show(ui, |ui| {
            ui.label(RichText::new(t.tr("appearance.intro")).small());
            let kind = ed.scenario().geometry.actuator().kind();
            for part in Part::ALL.into_iter().filter(|p| p.applies_to(kind)) {
                if let Some(a) = part_row(ui, ed, part) {
                    asked = Some(a);
                }
            }
            if let Some(e) = ed.doc.parts_error() {
                super::widgets::not_shown(ui, e, t);
            }
            edit_error(ui, ed.doc, t, &[Group::Appearance]);
        });
    asked
}

/// One part: its file (or the usual drawing), and when it has one, its unit, turn,
/// offset and colour.
fn part_row(ui: &mut egui::Ui, ed: &mut Editor, part: Part) -> Option<AppearanceAction> {
    let t = ed.lang;
    let look = ed.scenario().appearance.part(part).cloned();
    let mut asked = None;
    ui.horizontal(|ui| {
        ui.label(RichText::new(part_name(part, t)).strong());
        match &look {
            None => {
                ui.label(t.tr("appearance.usual"));
            }
            // The file's name; its whole path on hover.
            Some(l) => {
                let name = std::path::Path::new(&l.file)
                    .file_name()
                    .map_or_else(|| l.file.clone(), |n| n.to_string_lossy().into_owned());
                ui.label(name).on_hover_text(&l.file);
            }
        }
        if ui
            .button(t.tr("appearance.choose"))
            .on_hover_text(t.tr("appearance.choose_tip"))
            .clicked()
        {
            asked = Some(AppearanceAction::Browse(part));
        }
        if look.is_some()
            && ui
                .button(t.tr("appearance.remove"))
                .on_hover_text(t.tr("appearance.remove_tip"))
                .clicked()
        {
            ed.edit(Group::Appearance, |s| {
                *s.appearance.slot_mut(part) = None;
                Ok(())
            });
        }
    });
    let Some(look) = look else {
        return asked;
    };
    let mut edited = look.clone();
    ui.indent(("appearance", part.word()), |ui| {
        unit(ui, &mut edited, part, t);
        ui.horizontal(|ui| {
            ui.label(t.tr("appearance.rotation"));
            for (k, axis) in ["x", "y", "z"].into_iter().enumerate() {
                ui.add(
                    egui::DragValue::new(&mut edited.rotation_deg[k])
                        .range(-360.0..=360.0)
                        .speed(1.0)
                        .prefix(format!("{axis} "))
                        .suffix("°"),
                )
                .on_hover_text(t.tr("appearance.rotation_tip"));
            }
        });
        ui.horizontal(|ui| {
            ui.label(t.tr("appearance.offset"));
            for (k, axis) in ["x", "y", "z"].into_iter().enumerate() {
                ui.add(
                    egui::DragValue::new(&mut edited.offset_m[k])
                        .range(-MAX_OFFSET_M..=MAX_OFFSET_M)
                        .speed(0.001)
                        .max_decimals(4)
                        .prefix(format!("{axis} "))
                        .suffix(" m"),
                )
                .on_hover_text(t.tr("appearance.offset_tip"));
            }
        });
        colour(ui, &mut edited, t);
    });
    if edited != look {
        ed.edit(Group::Appearance, |s| {
            *s.appearance.slot_mut(part) = Some(edited);
            Ok(())
        });
    }
    asked
}

/// The file's unit: mm, cm, m, in, or metres per unit typed.
fn unit(ui: &mut egui::Ui, look: &mut PartLook, part: Part, t: Lang) {
    ui.horizontal(|ui| {
        let words = |s: MeshScale| match s {
            MeshScale::Factor(_) => t.tr("appearance.unit_other").to_owned(),
            other => other.word(),
        };
        egui::ComboBox::new(("unit", part.word()), t.tr("appearance.unit"))
            .selected_text(words(look.scale))
            .show_ui(ui, |ui| {
                for s in [
                    MeshScale::Millimetre,
                    MeshScale::Centimetre,
                    MeshScale::Metre,
                    MeshScale::Inch,
                ] {
                    ui.selectable_value(&mut look.scale, s, s.word());
                }
                if !matches!(look.scale, MeshScale::Factor(_)) {
                    let now = look.scale.metres();
                    ui.selectable_value(
                        &mut look.scale,
                        MeshScale::Factor(now),
                        words(MeshScale::Factor(now)),
                    );
                }
            })
            .response
            .on_hover_text(t.tr("appearance.unit_tip"));
        if let MeshScale::Factor(f) = &mut look.scale {
            let (lo, hi) = stewart_kinematics::model::appearance::SCALE_RANGE;
            ui.add(
                egui::DragValue::new(f)
                    .range(lo..=hi)
                    .speed(0.0001)
                    .max_decimals(6)
                    .suffix(" m"),
            );
        }
    });
}

/// The part's own colour, or none (the file's, else the studio's).
fn colour(ui: &mut egui::Ui, look: &mut PartLook, t: Lang) {
    ui.horizontal(|ui| {
        let mut own = look.colour.is_some();
        if ui
            .checkbox(&mut own, t.tr("appearance.own_colour"))
            .on_hover_text(t.tr("appearance.own_colour_tip"))
            .changed()
        {
            look.colour = own.then_some(Colour([200, 200, 205]));
        }
        if let Some(c) = &mut look.colour {
            let mut rgb = c.0;
            if ui.color_edit_button_srgb(&mut rgb).changed() {
                *c = Colour(rgb);
            }
        }
    });
}
