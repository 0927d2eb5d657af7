//! The Appearance panel: a scenario's CAD parts listed and edited (a unit that makes a
//! part absurd is refused, the picture kept), a part removed and brought back by undo,
//! and a mesh file dropped on the window attached to the part the user picks.

use std::path::{Path, PathBuf};

use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use stewart_kinematics::model::appearance::{MeshScale, Part};

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/cad")
}

/// The viewer on the seed with its CAD parts, the Appearance panel open.
fn seed_with_parts() -> egui_kittest::Harness<'static, crate::viewer::state::ViewerState> {
    let mut h = super::tall_harness("seed", 2600.0);
    h.state_mut().open_file(&examples().join("seed-cad.toml"));
    h.run();
    h.get_by_label("Appearance: CAD parts").click();
    super::settle(&mut h);
    h
}

#[test]
fn the_parts_of_a_scenario_are_listed_and_a_unit_that_makes_one_absurd_is_refused() {
    let mut h = seed_with_parts();
    for file in ["base.stl", "platform.obj", "cylinder.glb", "rod.stl"] {
        assert!(h.query_by_label(file).is_some(), "{file} not listed");
    }
    let parts = h.state().doc.parts().clone();
    assert!(Part::ALL[..4].iter().all(|&p| parts.get(p).is_some()));
    assert_eq!(parts.triangles(), 1608 + 280 + 512 + 512);
    super::look(&mut h, "appearance-panel.png");
    // The base in metres: 2.9 km across. Refused, saying which unit fits; still in mm.
    h.get_all_by_role_and_label(Role::ComboBox, "file unit")
        .find(|n| n.value().as_deref() == Some("mm"))
        .unwrap_or_else(|| panic!("no unit box"))
        .click();
    h.run();
    h.get_by_label("m").click();
    h.run();
    let base = h.state().scenario().appearance.part(Part::Base).cloned();
    assert_eq!(base.map(|b| b.scale), Some(MeshScale::Millimetre));
    assert!(
        h.query_by_label_contains("is the file in millimetres?")
            .is_some(),
        "the refusal is shown"
    );
    assert!(
        h.state().doc.parts().get(Part::Base).is_some(),
        "the picture is kept"
    );
}

#[test]
fn a_part_removed_comes_back_with_undo() {
    let mut h = seed_with_parts();
    h.get_all_by_label("Remove")
        .next()
        .unwrap_or_else(|| panic!("no Remove"))
        .click();
    h.run();
    assert!(h.state().scenario().appearance.part(Part::Base).is_none());
    assert!(h.state().doc.parts().get(Part::Base).is_none());
    h.state_mut().undo_edit();
    h.run();
    assert!(h.state().doc.parts().get(Part::Base).is_some());
    assert!(h.query_by_label("base.stl").is_some());
}

#[test]
fn a_mesh_dropped_on_the_window_is_attached_to_the_part_chosen() {
    let mut h = super::tall_harness("seed", 1400.0);
    let rod = examples().join("rod.stl");
    h.input_mut()
        .dropped_files
        .push(std::sync::Arc::new(Dropped(rod.clone())));
    h.run();
    assert!(h.query_by_label("Which part is rod.stl?").is_some());
    // A linear platform: no horn to offer.
    assert!(h.query_by_label("Servo horn").is_none());
    h.get_by_label("Rod").click();
    h.run();
    let look = h
        .state()
        .scenario()
        .appearance
        .part(Part::Rod)
        .cloned()
        .unwrap_or_else(|| panic!("no rod"));
    // STL: millimetres guessed, which makes the rod 0.76 m long against the 1 m platform.
    assert_eq!(look.scale, MeshScale::Millimetre);
    assert_eq!(
        std::fs::canonicalize(&look.file).ok(),
        std::fs::canonicalize(&rod).ok()
    );
    assert!(h.state().doc.parts().get(Part::Rod).is_some());
    assert!(h.query_by_label("Which part is rod.stl?").is_none());
}

/// A file dropped on the window, as the windowing layer hands it to egui.
#[derive(Debug)]
struct Dropped(PathBuf);

impl egui::DroppedFile for Dropped {
    fn path(&self) -> &Path {
        &self.0
    }

    fn bytes(&self) -> Result<Vec<u8>, String> {
        std::fs::read(&self.0).map_err(|e| e.to_string())
    }
}

#[test]
fn a_scenario_saved_elsewhere_keeps_its_parts() {
    let mut h = seed_with_parts();
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let copy = dir.path().join("copy.toml");
    h.state_mut().save_file(&copy);
    h.run();
    // The saved file names the same meshes from its own folder, and reads back with them.
    let saved = stewart_kinematics::Scenario::load(&copy).unwrap_or_else(|e| panic!("{e}"));
    let base = saved
        .appearance
        .part(Part::Base)
        .cloned()
        .unwrap_or_else(|| panic!("base"));
    assert_eq!(
        std::fs::canonicalize(dir.path().join(&base.file)).ok(),
        std::fs::canonicalize(examples().join("base.stl")).ok()
    );
    h.state_mut().open_file(&copy);
    h.run();
    assert_eq!(h.state().doc.parts().triangles(), 1608 + 280 + 512 + 512);
    assert!(h.state().doc.edit_error.is_none());
}

#[test]
fn parts_are_read_from_the_scenario_folder_and_undo_brings_back_the_same_files() {
    // The scenario's folder given at start, whatever the working folder.
    let file = examples().join("seed-cad.toml");
    let scenario = stewart_kinematics::Scenario::load(&file).unwrap_or_else(|e| panic!("{e}"));
    let state = crate::viewer::state::ViewerState::new_in(scenario, examples());
    assert!(state.doc.parts_error().is_none());
    assert_eq!(state.doc.parts().triangles(), 1608 + 280 + 512 + 512);
    let mut h = super::harness_with(state, 1400.0);
    // Another scenario from another folder, then undo: the parts are the same files.
    let other =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenarios/heavy-legs.toml");
    h.state_mut().open_file(&other);
    h.run();
    assert!(h.state().doc.parts().is_empty());
    h.state_mut().undo_edit();
    h.run();
    assert_eq!(h.state().doc.parts().triangles(), 1608 + 280 + 512 + 512);
    assert!(h.state().doc.parts_error().is_none());
}

#[test]
fn a_part_whose_file_is_gone_is_not_drawn_and_blocks_no_other_edit() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let text = std::fs::read_to_string(examples().join("seed-cad.toml"))
        .unwrap_or_else(|e| panic!("{e}"))
        .replace(
            "\"base.stl\"",
            &format!("{:?}", examples().join("base.stl")),
        )
        .replace(
            "\"platform.obj\"",
            &format!("{:?}", examples().join("platform.obj")),
        )
        .replace(
            "\"cylinder.glb\"",
            &format!("{:?}", examples().join("cylinder.glb")),
        )
        .replace("\"rod.stl\"", "\"gone.stl\"");
    let file = dir.path().join("s.toml");
    std::fs::write(&file, text).unwrap_or_else(|e| panic!("{e}"));
    let mut h = super::tall_harness("seed", 2600.0);
    h.state_mut().open_file(&file);
    h.run();
    h.get_by_label("Appearance: CAD parts").click();
    super::settle(&mut h);
    assert!(h.state().doc.parts().get(Part::Base).is_some());
    assert!(h.state().doc.parts().get(Part::Rod).is_none());
    let said = "Not drawn: a CAD part cannot be drawn: `appearance.rod.file`";
    assert!(h.query_by_label_contains(said).is_some());
    assert!(
        h.query_by_label_contains("gone.stl: No such file")
            .is_some()
    );
    // The base moved: accepted although the rod still fails.
    let applied =
        h.state_mut()
            .doc
            .edit(stewart_kinematics::io::settings::Group::Appearance, |s| {
                if let Some(b) = s.appearance.slot_mut(Part::Base) {
                    b.offset_m = [0.0, 0.0, -0.01];
                }
                Ok(())
            });
    assert!(applied);
    // A new file for the rod that is missing too: refused, naming it.
    h.state_mut()
        .attach_mesh(Part::Rod, &dir.path().join("also-gone.stl"));
    h.run();
    assert!(
        h.state()
            .scenario()
            .appearance
            .part(Part::Rod)
            .is_some_and(|r| r.file.ends_with("gone.stl"))
    );
    assert!(h.query_by_label_contains("also-gone.stl").is_some());
}

#[test]
fn a_platform_made_much_smaller_judges_its_parts_again_and_keeps_the_edit() {
    let mut h = seed_with_parts();
    // A desk-sized platform: the 2.2 m base plate is now far too big for it.
    let applied = h
        .state_mut()
        .doc
        .edit(stewart_kinematics::io::settings::Group::Geometry, |s| {
            Ok(stewart_kinematics::io::settings::apply_all(
                s,
                [
                    "geometry.base_radius=0.01",
                    "geometry.platform_radius=0.006",
                    "geometry.home_height=0.008",
                ],
            )?)
        });
    assert!(
        applied,
        "{:?}",
        h.state().doc.edit_error.as_ref().map(|e| e.1.to_string())
    );
    h.run();
    assert!(h.state().doc.parts().get(Part::Base).is_none());
    let said = h
        .state()
        .doc
        .parts_error()
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert!(said.contains("`appearance.base.scale`"), "{said}");
}
