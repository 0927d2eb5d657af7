//! Scenario presets shipped in the repository's top-level `assets/presets/` and compiled
//! into the program.

/// A preset's name and its text, from `assets/presets/NAME.toml`.
macro_rules! preset {
    ($name:literal) => {
        (
            $name,
            include_str!(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/../../assets/presets/",
                $name,
                ".toml"
            )),
        )
    };
}

/// Every preset: its name and its TOML text.
pub const PRESETS: [(&str, &str); 10] = [
    preset!("seed"),
    preset!("paired"),
    preset!("circle"),
    preset!("figure8"),
    preset!("helix"),
    preset!("sway"),
    preset!("keyframes"),
    preset!("servo-desk"),
    preset!("crank-rig"),
    preset!("dietmaier"),
];

/// The names of the presets, in order.
pub fn names() -> impl Iterator<Item = &'static str> {
    PRESETS.iter().map(|(name, _)| *name)
}

/// The TOML text of preset `name`.
pub fn text(name: &str) -> Option<&'static str> {
    PRESETS
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, text)| *text)
}

#[cfg(test)]
mod folder_tests {
    #[test]
    fn every_file_in_assets_presets_is_compiled_in_and_only_those() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/presets");
        let mut files: Vec<String> = std::fs::read_dir(&dir)
            .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
            .filter_map(|e| e.ok())
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .collect();
        files.sort();
        let mut compiled: Vec<String> = super::names().map(|n| format!("{n}.toml")).collect();
        compiled.sort();
        assert_eq!(files, compiled);
    }
}
