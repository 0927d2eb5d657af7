//! Scenario presets shipped in `presets/` (this crate) and compiled into the program.

/// Every preset: its name and its TOML text.
pub const PRESETS: [(&str, &str); 10] = [
    (
        "seed",
        include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/presets/seed.toml")),
    ),
    (
        "paired",
        include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/presets/paired.toml")),
    ),
    (
        "circle",
        include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/presets/circle.toml")),
    ),
    (
        "figure8",
        include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/presets/figure8.toml")),
    ),
    (
        "helix",
        include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/presets/helix.toml")),
    ),
    (
        "sway",
        include_str!(concat!(env!("CARGO_MANIFEST_DIR"), "/presets/sway.toml")),
    ),
    (
        "keyframes",
        include_str!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/presets/keyframes.toml"
        )),
    ),
    (
        "servo-desk",
        include_str!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/presets/servo-desk.toml"
        )),
    ),
    (
        "crank-rig",
        include_str!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/presets/crank-rig.toml"
        )),
    ),
    (
        "dietmaier",
        include_str!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/presets/dietmaier.toml"
        )),
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
