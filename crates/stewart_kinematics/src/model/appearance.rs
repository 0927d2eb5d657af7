//! The `[appearance]` table: a mesh file (a CAD part) drawn in place of a body's usual
//! drawing — the base, the platform, and per actuator kind its moving parts (a linear
//! leg's `cylinder` and `rod`, a servo's `horn` and `rod`).
//!
//! ```toml
//! [appearance.base]
//! file = "parts/base.stl"   # relative to the scenario file
//! scale = "mm"              # mm, cm, m, in, or metres per file unit
//! rotation_deg = [0, 0, 0]  # about the part's x, then y, then z axis
//! offset_m = [0, 0, 0]      # in the part's frame
//! colour = "#8a9099"        # optional
//! ```
//!
//! Each part has a frame of its own (see [`Part`]); the file's vertices `v` are placed at
//! `frame · (offset + R · scale · v)` with `R = Rz · Ry · Rx`. This module holds the table
//! as data and checks its values; reading the files is the renderer's.

use serde::{Deserialize, Serialize};

use crate::model::actuator::ActuatorKind;

/// A body that may be drawn from a mesh file, with its frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Part {
    /// The base plate. Frame: the base frame (origin at the base centre, z up; the
    /// base joints lie in its z = 0 plane).
    Base,
    /// The moving plate. Frame: the platform frame (its origin where `stewart solve`
    /// puts the platform, its axes the platform's; the platform joints lie in its
    /// z = 0 plane).
    Platform,
    /// A linear leg's body. Frame: origin at the leg's base joint, +y along the leg
    /// towards its platform joint (x and z: the base frame's, turned by the shortest
    /// rotation that takes its y axis onto the leg).
    Cylinder,
    /// The rod: of a linear leg, origin at the platform joint, +y along the leg away
    /// from the base (the rod reaches down along −y), turned as the cylinder; of a
    /// servo, origin at the horn tip, +y along the rod towards the platform joint.
    Rod,
    /// A servo's horn. Frame: origin at the shaft's centre, +x along the horn towards
    /// its tip, +z along the shaft so that a positive servo angle turns +x towards +y
    /// (at angle 0, +y is the base frame's up).
    Horn,
}

impl Part {
    /// Every part, in file order.
    pub const ALL: [Part; 5] = [
        Part::Base,
        Part::Platform,
        Part::Cylinder,
        Part::Rod,
        Part::Horn,
    ];

    /// Its key in the table: `base`, `platform`, `cylinder`, `rod`, `horn`.
    pub fn word(self) -> &'static str {
        match self {
            Part::Base => "base",
            Part::Platform => "platform",
            Part::Cylinder => "cylinder",
            Part::Rod => "rod",
            Part::Horn => "horn",
        }
    }

    /// The part with this key.
    pub fn from_word(word: &str) -> Option<Part> {
        Part::ALL.into_iter().find(|p| p.word() == word)
    }

    /// Whether a platform whose actuators are of `kind` has this part.
    pub fn applies_to(self, kind: ActuatorKind) -> bool {
        match self {
            Part::Cylinder => kind == ActuatorKind::Linear,
            Part::Horn => kind == ActuatorKind::Rotary,
            _ => true,
        }
    }
}

impl std::fmt::Display for Part {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.word())
    }
}

/// The length of one unit of a mesh file.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "ScaleText", into = "ScaleText")]
pub enum MeshScale {
    /// Millimetres (most CAD exports).
    Millimetre,
    /// Centimetres.
    Centimetre,
    /// Metres (glTF's unit).
    #[default]
    Metre,
    /// Inches.
    Inch,
    /// Metres per file unit.
    Factor(f64),
}

/// The smallest and largest factor accepted: a micrometre to a kilometre a unit.
pub const SCALE_RANGE: (f64, f64) = (1e-6, 1e3);
/// The largest offset, metres.
pub const MAX_OFFSET_M: f64 = 100.0;

impl MeshScale {
    /// Metres per file unit.
    pub fn metres(self) -> f64 {
        match self {
            MeshScale::Millimetre => 1e-3,
            MeshScale::Centimetre => 1e-2,
            MeshScale::Metre => 1.0,
            MeshScale::Inch => 0.0254,
            MeshScale::Factor(f) => f,
        }
    }

    /// Read `mm`, `cm`, `m`, `in` or a number of metres per unit.
    pub fn parse(text: &str) -> Result<MeshScale, String> {
        let text = text.trim();
        let scale = match text {
            "mm" => MeshScale::Millimetre,
            "cm" => MeshScale::Centimetre,
            "m" => MeshScale::Metre,
            "in" | "inch" => MeshScale::Inch,
            _ => MeshScale::Factor(text.parse::<f64>().map_err(|_| {
                format!("`{text}` is not mm, cm, m, in or a number of metres per unit")
            })?),
        };
        scale.check()?;
        Ok(scale)
    }

    /// Refuse a factor that is not finite or outside [`SCALE_RANGE`].
    fn check(self) -> Result<(), String> {
        let (lo, hi) = SCALE_RANGE;
        let f = self.metres();
        if f.is_finite() && (lo..=hi).contains(&f) {
            Ok(())
        } else {
            Err(format!(
                "must be mm, cm, m, in or {lo:e} … {hi:e} metres per unit, got {f}"
            ))
        }
    }

    /// As written in the file and by `stewart settings`.
    pub fn word(self) -> String {
        match self {
            MeshScale::Millimetre => "mm".into(),
            MeshScale::Centimetre => "cm".into(),
            MeshScale::Metre => "m".into(),
            MeshScale::Inch => "in".into(),
            MeshScale::Factor(f) => f.to_string(),
        }
    }
}

/// A scale as the file holds it: a word or a number.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(untagged)]
enum ScaleText {
    Number(f64),
    Word(String),
}

impl TryFrom<ScaleText> for MeshScale {
    type Error = String;
    fn try_from(t: ScaleText) -> Result<Self, String> {
        match t {
            ScaleText::Word(w) => MeshScale::parse(&w),
            ScaleText::Number(f) => {
                let s = MeshScale::Factor(f);
                s.check()?;
                Ok(s)
            }
        }
    }
}

impl From<MeshScale> for ScaleText {
    fn from(s: MeshScale) -> Self {
        match s {
            MeshScale::Factor(f) => ScaleText::Number(f),
            other => ScaleText::Word(other.word()),
        }
    }
}

/// An sRGB colour written `#rrggbb`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(try_from = "String", into = "String")]
pub struct Colour(pub [u8; 3]);

impl Colour {
    /// Read `#rrggbb` (the `#` optional).
    pub fn parse(text: &str) -> Result<Colour, String> {
        let hex = text.trim();
        let hex = hex.strip_prefix('#').unwrap_or(hex);
        let bad = || format!("`{text}` is not a colour written #rrggbb");
        if hex.len() != 6 || !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
            return Err(bad());
        }
        let byte = |k: usize| u8::from_str_radix(&hex[k..k + 2], 16).map_err(|_| bad());
        Ok(Colour([byte(0)?, byte(2)?, byte(4)?]))
    }

    /// Red, green and blue from 0 to 1 (sRGB) and alpha 1.
    pub fn rgba(self) -> [f32; 4] {
        let [r, g, b] = self.0.map(|c| f32::from(c) / 255.0);
        [r, g, b, 1.0]
    }
}

impl TryFrom<String> for Colour {
    type Error = String;
    fn try_from(s: String) -> Result<Self, String> {
        Colour::parse(&s)
    }
}

impl From<Colour> for String {
    fn from(c: Colour) -> String {
        let [r, g, b] = c.0;
        format!("#{r:02x}{g:02x}{b:02x}")
    }
}

/// One part's mesh file and how it sits in the part's frame.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PartLook {
    /// The mesh file (STL, OBJ, glTF or GLB), relative to the scenario file.
    pub file: String,
    /// The length of one of the file's units.
    #[serde(default)]
    pub scale: MeshScale,
    /// Turned about the part's x, then y, then z axis, degrees.
    #[serde(default, deserialize_with = "crate::ground::text::exactly")]
    pub rotation_deg: [f64; 3],
    /// Moved in the part's frame, metres.
    #[serde(default, deserialize_with = "crate::ground::text::exactly")]
    pub offset_m: [f64; 3],
    /// Drawn in this colour (else the file's own colours, else the studio's).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub colour: Option<Colour>,
}

impl PartLook {
    /// A file at the default scale (metres), unturned, in its colours.
    pub fn new(file: impl Into<String>) -> Self {
        Self {
            file: file.into(),
            scale: MeshScale::Metre,
            rotation_deg: [0.0; 3],
            offset_m: [0.0; 3],
            colour: None,
        }
    }
}

/// The `[appearance]` table: a mesh file per part, or none (the usual drawing).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct AppearanceSettings {
    /// `[appearance.base]`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub base: Option<PartLook>,
    /// `[appearance.platform]`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub platform: Option<PartLook>,
    /// `[appearance.cylinder]`: every linear leg's body.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cylinder: Option<PartLook>,
    /// `[appearance.rod]`: every rod.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rod: Option<PartLook>,
    /// `[appearance.horn]`: every servo horn.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub horn: Option<PartLook>,
}

/// An `[appearance]` value refused: its key (`appearance.rod.scale`) and why.
#[derive(Clone, Debug, PartialEq)]
pub struct AppearanceProblem {
    /// The key, as `--set` and the file name it.
    pub key: String,
    /// Why.
    pub reason: String,
}

impl AppearanceSettings {
    /// The look of `part`, if it has a file.
    pub fn part(&self, part: Part) -> Option<&PartLook> {
        self.slot(part).as_ref()
    }

    /// The slot of `part`, to set or clear.
    pub fn slot_mut(&mut self, part: Part) -> &mut Option<PartLook> {
        match part {
            Part::Base => &mut self.base,
            Part::Platform => &mut self.platform,
            Part::Cylinder => &mut self.cylinder,
            Part::Rod => &mut self.rod,
            Part::Horn => &mut self.horn,
        }
    }

    fn slot(&self, part: Part) -> &Option<PartLook> {
        match part {
            Part::Base => &self.base,
            Part::Platform => &self.platform,
            Part::Cylinder => &self.cylinder,
            Part::Rod => &self.rod,
            Part::Horn => &self.horn,
        }
    }

    /// The parts that have a file, with their looks.
    pub fn parts(&self) -> impl Iterator<Item = (Part, &PartLook)> {
        Part::ALL
            .into_iter()
            .filter_map(|p| self.part(p).map(|look| (p, look)))
    }

    /// The first value that cannot work: an empty file name, a scale that is not finite
    /// or outside [`SCALE_RANGE`], a rotation or offset that is not finite or beyond
    /// ±360° or [`MAX_OFFSET_M`].
    pub fn problem(&self) -> Option<AppearanceProblem> {
        for (part, look) in self.parts() {
            let bad = |key: &str, reason: String| {
                Some(AppearanceProblem {
                    key: format!("appearance.{part}.{key}"),
                    reason,
                })
            };
            if look.file.trim().is_empty() {
                return bad(
                    "file",
                    "must name a mesh file (STL, OBJ, glTF or GLB)".into(),
                );
            }
            if let Err(reason) = look.scale.check() {
                return bad("scale", reason);
            }
            if let Some(v) = look
                .rotation_deg
                .iter()
                .find(|v| !(v.is_finite() && v.abs() <= 360.0))
            {
                return bad(
                    "rotation_deg",
                    format!("each angle must be a finite number within ±360°, got {v}"),
                );
            }
            if let Some(v) = look
                .offset_m
                .iter()
                .find(|v| !(v.is_finite() && v.abs() <= MAX_OFFSET_M))
            {
                return bad(
                    "offset_m",
                    format!(
                        "each coordinate must be a finite number within ±{MAX_OFFSET_M} m, got {v}"
                    ),
                );
            }
        }
        None
    }

    /// Change one key from its text (what `--set appearance.PART.KEY=VALUE` does): `file`
    /// (`off` removes the part's mesh), `scale`, `rotation_deg` and `offset_m` (three
    /// numbers, `x,y,z`), `colour` (`#rrggbb`, `off` for the file's or the studio's).
    /// A refused value leaves the table unchanged.
    pub fn set_text(&mut self, key: &str, value: &str) -> Result<(), AppearanceProblem> {
        let full = format!("appearance.{key}");
        let refuse = |reason: String| AppearanceProblem {
            key: full.clone(),
            reason,
        };
        let value = value.trim();
        let (part, name) = key
            .split_once('.')
            .and_then(|(p, n)| Some((Part::from_word(p)?, n)))
            .ok_or_else(|| {
                refuse(
                    "unknown appearance setting: appearance.PART.KEY with PART one of base, \
                     platform, cylinder, rod, horn"
                        .to_owned(),
                )
            })?;
        let mut edited = self.clone();
        let off = value.eq_ignore_ascii_case("off");
        let slot = edited.slot_mut(part);
        if name == "file" {
            *slot = match (off, slot.take()) {
                (true, _) => None,
                (false, Some(look)) => Some(PartLook {
                    file: value.to_owned(),
                    ..look
                }),
                (false, None) => Some(PartLook::new(value)),
            };
        } else {
            let look = slot.as_mut().ok_or_else(|| {
                refuse(format!(
                    "`appearance.{part}` has no file yet: set `appearance.{part}.file` first"
                ))
            })?;
            match name {
                "scale" => look.scale = MeshScale::parse(value).map_err(&refuse)?,
                "rotation_deg" => look.rotation_deg = three(value).map_err(&refuse)?,
                "offset_m" => look.offset_m = three(value).map_err(&refuse)?,
                "colour" | "color" => {
                    look.colour = if off {
                        None
                    } else {
                        Some(Colour::parse(value).map_err(&refuse)?)
                    };
                }
                _ => {
                    return Err(refuse(
                        "unknown appearance key: file, scale, rotation_deg, offset_m or colour"
                            .to_owned(),
                    ));
                }
            }
        }
        if let Some(p) = edited.problem() {
            return Err(refuse(p.reason));
        }
        *self = edited;
        Ok(())
    }

    /// Every key `set_text` takes with its current value, for `stewart settings`
    /// (`PART.file = off` for a part drawn as usual).
    pub fn entries(&self) -> Vec<(String, String)> {
        let mut rows = Vec::new();
        for part in Part::ALL {
            match self.part(part) {
                None => rows.push((format!("{part}.file"), "off".to_owned())),
                Some(look) => {
                    let triple = |v: &[f64; 3]| format!("{},{},{}", v[0], v[1], v[2]);
                    rows.push((format!("{part}.file"), look.file.clone()));
                    rows.push((format!("{part}.scale"), look.scale.word()));
                    rows.push((format!("{part}.rotation_deg"), triple(&look.rotation_deg)));
                    rows.push((format!("{part}.offset_m"), triple(&look.offset_m)));
                    rows.push((
                        format!("{part}.colour"),
                        look.colour.map_or_else(|| "off".to_owned(), String::from),
                    ));
                }
            }
        }
        rows
    }
}

/// Three numbers written `x,y,z` (brackets and spaces allowed).
fn three(text: &str) -> Result<[f64; 3], String> {
    let inner = text.trim().trim_start_matches('[').trim_end_matches(']');
    let numbers: Vec<f64> = inner
        .split(',')
        .map(|s| s.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| format!("`{text}` is not three numbers x,y,z"))?;
    numbers
        .try_into()
        .map_err(|_| format!("`{text}` is not three numbers x,y,z"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scales_read_as_words_or_numbers_and_absurd_ones_are_refused() {
        assert_eq!(MeshScale::parse("mm").map(MeshScale::metres), Ok(1e-3));
        assert_eq!(MeshScale::parse("in").map(MeshScale::metres), Ok(0.0254));
        assert_eq!(MeshScale::parse("0.5").map(MeshScale::metres), Ok(0.5));
        for bad in ["0", "-1", "NaN", "inf", "1e9", "feet", ""] {
            assert!(MeshScale::parse(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn colours_are_hex_triples() {
        assert_eq!(Colour::parse("#ff8000"), Ok(Colour([255, 128, 0])));
        assert_eq!(Colour::parse("FF8000"), Ok(Colour([255, 128, 0])));
        assert_eq!(String::from(Colour([255, 128, 0])), "#ff8000");
        for bad in ["#ff80", "#gg0000", "red", "#ff80000"] {
            assert!(Colour::parse(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn set_text_edits_one_key_and_refuses_without_a_change() {
        let mut a = AppearanceSettings::default();
        assert!(a.set_text("rod.scale", "mm").is_err(), "no file yet");
        a.set_text("rod.file", "rod.stl")
            .unwrap_or_else(|p| panic!("{p:?}"));
        a.set_text("rod.scale", "mm")
            .unwrap_or_else(|p| panic!("{p:?}"));
        a.set_text("rod.rotation_deg", "[90, 0, -45]")
            .unwrap_or_else(|p| panic!("{p:?}"));
        a.set_text("rod.colour", "#102030")
            .unwrap_or_else(|p| panic!("{p:?}"));
        let rod = a.part(Part::Rod).cloned().unwrap_or_else(|| panic!("rod"));
        assert_eq!(rod.scale, MeshScale::Millimetre);
        assert_eq!(rod.rotation_deg, [90.0, 0.0, -45.0]);
        assert_eq!(rod.colour, Some(Colour([0x10, 0x20, 0x30])));
        let before = a.clone();
        let p = a.set_text("rod.offset_m", "1,2").err();
        assert_eq!(p.map(|p| p.key), Some("appearance.rod.offset_m".to_owned()));
        assert!(a.set_text("rod.offset_m", "0,0,1000").is_err());
        assert!(a.set_text("rod.rotation_deg", "0,NaN,0").is_err());
        assert!(a.set_text("wheel.file", "x.stl").is_err());
        assert_eq!(a, before);
        a.set_text("rod.file", "off")
            .unwrap_or_else(|p| panic!("{p:?}"));
        assert_eq!(a, AppearanceSettings::default());
    }

    #[test]
    fn entries_name_every_part() {
        let a = AppearanceSettings {
            base: Some(PartLook::new("base.stl")),
            ..AppearanceSettings::default()
        };
        let e = a.entries();
        assert_eq!(e[0], ("base.file".to_owned(), "base.stl".to_owned()));
        assert!(e.contains(&("horn.file".to_owned(), "off".to_owned())));
        // What `entries` prints, `set_text` takes back.
        let mut b = AppearanceSettings::default();
        for (k, v) in &e {
            b.set_text(k, v)
                .unwrap_or_else(|p| panic!("{k}={v}: {p:?}"));
        }
        assert_eq!(a, b);
    }
}
