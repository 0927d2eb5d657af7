//! Scenario presets shipped in `assets/presets/` and compiled into the program.

/// Every preset: its name and its TOML text.
pub const PRESETS: [(&str, &str); 10] = [
    (
        "seed",
        include_str!("../../../../../assets/presets/seed.toml"),
    ),
    (
        "paired",
        include_str!("../../../../../assets/presets/paired.toml"),
    ),
    (
        "circle",
        include_str!("../../../../../assets/presets/circle.toml"),
    ),
    (
        "figure8",
        include_str!("../../../../../assets/presets/figure8.toml"),
    ),
    (
        "helix",
        include_str!("../../../../../assets/presets/helix.toml"),
    ),
    (
        "sway",
        include_str!("../../../../../assets/presets/sway.toml"),
    ),
    (
        "keyframes",
        include_str!("../../../../../assets/presets/keyframes.toml"),
    ),
    (
        "servo-desk",
        include_str!("../../../../../assets/presets/servo-desk.toml"),
    ),
    (
        "crank-rig",
        include_str!("../../../../../assets/presets/crank-rig.toml"),
    ),
    (
        "dietmaier",
        include_str!("../../../../../assets/presets/dietmaier.toml"),
    ),
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
