use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use stewart_kinematics::analysis::architecture;

use stewart_kinematics::model::actuator::ActuatorKind;
use stewart_kinematics::{
    Geometry, Scenario, analysis::checks::Finding, analysis::checks::FindingKind, io::settings,
    model::layout::Layout,
};

use super::words::{architecture, finding, setting_label, time_text};
use super::{Lang, catalogue, fill, keys};

/// The `{name}` placeholders of a text.
fn placeholders(text: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut rest = text;
    while let Some(open) = rest.find('{') {
        let after = &rest[open + 1..];
        let Some(close) = after.find('}') else { break };
        out.insert(after[..close].to_owned());
        rest = &after[close + 1..];
    }
    out
}

#[test]
fn both_catalogues_have_the_same_keys_and_placeholders() {
    let en: BTreeSet<&str> = keys(Lang::En).collect();
    let zh: BTreeSet<&str> = keys(Lang::Zh).collect();
    let only_en: Vec<_> = en.difference(&zh).collect();
    let only_zh: Vec<_> = zh.difference(&en).collect();
    assert!(only_en.is_empty(), "missing from zh.toml: {only_en:?}");
    assert!(only_zh.is_empty(), "missing from en.toml: {only_zh:?}");
    assert!(en.len() > 250, "{} keys", en.len());
    for key in en {
        assert_eq!(
            placeholders(Lang::En.tr(key)),
            placeholders(Lang::Zh.tr(key)),
            "`{key}` has other placeholders in zh.toml"
        );
    }
}

#[test]
fn the_chinese_catalogue_is_chinese() {
    // Every entry with words in it carries Chinese characters (symbols, units and
    // letters such as `x` stand alone).
    for key in keys(Lang::Zh) {
        let text = Lang::Zh.tr(key);
        let stripped: String = fill_blank(text);
        let has_word = stripped
            .split(|c: char| !c.is_ascii_alphabetic())
            .any(|w| w.len() >= 3 && !ALLOWED_LATIN.contains(&w));
        let has_han = text.chars().any(is_han);
        assert!(!has_word || has_han, "`{key}` = {text:?} reads as English");
    }
}

/// Latin words that are the same in Chinese technical text: file types, units, keys,
/// protocol names.
const ALLOWED_LATIN: [&str; 12] = [
    "GIF", "MP4", "PNG", "SVG", "PDF", "CSV", "dpi", "UDP", "GPU", "Home", "Esc", "Shift",
];

/// `text` without its placeholders.
fn fill_blank(text: &str) -> String {
    let names = placeholders(text);
    let values: Vec<(&str, &dyn std::fmt::Display)> =
        names.iter().map(|n| (n.as_str(), &"" as _)).collect();
    fill(text, &values)
}

fn is_han(c: char) -> bool {
    ('\u{4e00}'..='\u{9fff}').contains(&c)
}

#[test]
fn placeholders_are_filled_and_unknown_ones_left() {
    assert_eq!(
        fill("{a} and {b}, {a}", &[("a", &1), ("b", &"two")]),
        "1 and two, 1"
    );
    assert_eq!(fill("{gone} {", &[]), "{gone} {");
    assert_eq!(fill("no braces", &[("a", &1)]), "no braces");
    assert_eq!(fill("数 {n} 个", &[("n", &6)]), "数 6 个");
}

#[test]
fn a_missing_key_shows_as_itself() {
    assert_eq!(Lang::Zh.tr("no.such.key"), "no.such.key");
    assert!(catalogue::lookup(Lang::Zh, "no.such.key").is_none());
}

#[test]
fn the_locale_names_the_language() {
    assert_eq!(Lang::from_locale("zh_CN.UTF-8"), Lang::Zh);
    assert_eq!(Lang::from_locale("zh_TW"), Lang::Zh);
    assert_eq!(Lang::from_locale("ZH"), Lang::Zh);
    assert_eq!(Lang::from_locale("en_GB.UTF-8"), Lang::En);
    assert_eq!(Lang::from_locale("C"), Lang::En);
    assert_eq!(Lang::from_locale(""), Lang::En);
}

#[test]
fn chinese_without_a_font_falls_back_to_english_with_a_note() {
    assert_eq!(super::fonts::usable(Lang::Zh, true), (Lang::Zh, None));
    assert_eq!(super::fonts::usable(Lang::En, false), (Lang::En, None));
    let (lang, note) = super::fonts::usable(Lang::Zh, false);
    assert_eq!(lang, Lang::En);
    assert!(note.is_some_and(|n| n.contains("fonts-wqy-microhei")));
}

#[test]
fn english_setting_labels_are_the_cores_and_chinese_ones_exist() {
    for setting in settings::all() {
        assert_eq!(
            setting_label(Lang::En, setting),
            setting.label,
            "{}",
            setting.key
        );
        let zh = setting_label(Lang::Zh, setting);
        assert!(
            !zh.starts_with("setting."),
            "no Chinese label for {}",
            setting.key
        );
        assert!(zh.chars().any(is_han), "{}: {zh}", setting.key);
        assert!(!zh.contains('{'), "{}: {zh}", setting.key);
    }
}

/// One finding of every kind, with one leg, two legs and no leg, over one and many samples.
fn findings() -> Vec<Finding> {
    use FindingKind::*;
    let kinds = [
        StrokeMax,
        StrokeMin,
        LegSpeed,
        LegAccel,
        LegJerk,
        BaseCone,
        PlatformCone,
        LegCollision,
        NearSingular,
        ArchitectureSingular,
        Jump,
        RigidBody,
        Unreachable,
        ServoMax,
        ServoMin,
        ServoSpeed,
        ServoAccel,
        ServoJerk,
        HornCone,
        RodPlatformCone,
        RodCollision,
        RodHornCollision,
        ServoJump,
    ];
    let mut out = Vec::new();
    for (k, kind) in kinds.into_iter().enumerate() {
        for (legs, count) in [(vec![3], 1), (vec![2, 5], 17), (vec![], 4)] {
            for worst in [1.234_567 + k as f64, f64::INFINITY] {
                out.push(Finding {
                    kind,
                    legs: legs.clone(),
                    first_time: 0.125 * k as f64,
                    last_time: 2.5,
                    count,
                    worst_time: 1.0625,
                    worst_value: worst,
                    limit: 0.987_654_3,
                    margin: -0.012_345_6,
                    unit: String::new(),
                });
            }
        }
    }
    out
}

/// The English sentences of [`findings`], one per line, exactly as the core wrote them
/// before the words moved into the catalogues (issue #43).
const FINDINGS_EN: &str = include_str!("findings_en.txt");

#[test]
fn english_findings_read_exactly_as_the_core_wrote_them() {
    let expected: Vec<&str> = FINDINGS_EN.lines().collect();
    let found = findings();
    assert_eq!(found.len(), expected.len());
    for (f, line) in found.iter().zip(expected) {
        assert_eq!(finding(Lang::En, f), line, "{:?}", f.kind);
    }
}

#[test]
fn a_findings_time_names_its_own_row() {
    // Three decimals as before; a row 0.5 ms after another (a table's own rows are
    // judged) gets the digits that tell them apart.
    assert_eq!(time_text(5.0), "5.000");
    assert_eq!(time_text(5.01 + 1e-12), "5.010");
    assert_eq!(time_text(5.0005), "5.0005");
    assert_eq!(time_text(1.062), "1.062");
    assert_eq!(time_text(0.0000012), "0.0000012");
    assert_eq!(time_text(1.4000045), "1.4000045");
    assert_eq!(time_text(54.600234), "54.600234");
    // A row a hair before zero is named as it is, never "-0.000".
    assert_eq!(time_text(-4e-7), "-0.0000004");
    assert_eq!(time_text(-0.0), "0.000");
    assert_eq!(time_text(-0.25), "-0.250");
    // A limit over a microsecond's interval is small, never shown as zero.
    let tiny = Finding {
        kind: FindingKind::Jump,
        legs: vec![2],
        first_time: 5.000001,
        last_time: 5.000001,
        count: 1,
        worst_time: 5.000001,
        worst_value: 7.9e-4,
        limit: 1e-8,
        margin: 1e-8 - 7.9e-4,
        unit: "m".into(),
    };
    let words = finding(Lang::En, &tiny);
    assert!(
        words.ends_with("t = 5.000001 s, where the steps around it allow at most 0.0000100 mm"),
        "{words}"
    );
}

#[test]
fn every_finding_has_a_chinese_sentence() {
    for f in findings() {
        let zh = finding(Lang::Zh, &f);
        assert!(!zh.starts_with("finding."), "{:?}", f.kind);
        assert!(!zh.contains('{'), "{:?}: {zh}", f.kind);
        assert!(zh.chars().filter(|c| is_han(*c)).count() >= 6, "{zh}");
    }
}

/// The seed's English verdict exactly as the core wrote it before the words moved into
/// the catalogues (issue #43): its weakest twist included.
const SEED_VERDICT_EN: &str = "This geometry is architecturally singular: the legs cannot determine the platform's pose at any pose, because its platform joints are a projective image (here a rotated, scaled copy) of its base joints, which lie on a circle, so the six leg lines always belong to one linear complex. The legs cannot resist or control the twist rotation along (-0.09, -0.86, -0.50) combined with translation along (0.36, -0.90, 0.25) (38% rotation). Change the layout: joints in three pairs on each plate (the paired layout, e.g. 20° between the joints of a pair) removes the singularity.";

#[test]
fn the_architecture_verdict_reads_as_the_core_wrote_it() {
    let seed = architecture::architecture(&Geometry::seed());
    assert!(seed.singular);
    let paired = {
        let params =
            stewart_kinematics::GeometryParams::from_layout(1.0, 0.6, 0.8, Layout::paired(20.0));
        architecture::architecture(&Geometry::new(params).unwrap_or_else(|e| panic!("{e}")))
    };
    assert!(!paired.singular);
    assert_eq!(architecture(Lang::En, &seed), SEED_VERDICT_EN);
    assert_eq!(
        architecture(Lang::En, &paired),
        format!(
            "The geometry is not architecturally singular: the legs determine the pose (worst inverse condition number near home {:.3}).",
            paired.worst_inverse_condition
        )
    );
    for report in [seed, paired] {
        let zh = architecture(Lang::Zh, &report);
        assert!(zh.contains("结构奇异"), "{zh}");
        assert!(!zh.contains('{') && !zh.contains("architecture."), "{zh}");
    }
}

/// The program's sources (not its tests).
fn sources() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            let name = path
                .file_name()
                .and_then(|n| n.to_str())
                .unwrap_or_default();
            if path.is_dir() {
                // Test modules with files of their own are tests, not the program.
                if !matches!(name, "tests" | "ui_tests") {
                    walk(&path, out);
                }
            } else if path.extension().is_some_and(|e| e == "rs") && name != "tests.rs" {
                out.push(path);
            }
        }
    }
    let mut out = Vec::new();
    walk(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"), &mut out);
    out.sort();
    out
}

/// A file's text without what `#[cfg(test)]` guards: an item on one line (`mod tests;`,
/// a `use`), or one with a body (an inline `mod tests { … }`, a test-only method) to its
/// matching brace.
fn program_text(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap_or_default();
    let mut out = String::new();
    let mut lines = text.lines();
    while let Some(line) = lines.next() {
        if line.trim() != "#[cfg(test)]" {
            out.push_str(line);
            out.push('\n');
            continue;
        }
        let mut depth = 0i32;
        let mut opened = false;
        for guarded in lines.by_ref() {
            depth += guarded.matches('{').count() as i32 - guarded.matches('}').count() as i32;
            opened |= guarded.contains('{');
            if (opened && depth <= 0) || (!opened && guarded.trim_end().ends_with(';')) {
                break;
            }
        }
    }
    out
}

/// The string literals of `text` (plain `"…"` ones; raw strings hold SVG, not words).
fn literals(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let bytes: Vec<char> = text.chars().collect();
    let mut k = 0;
    while k < bytes.len() {
        let c = bytes[k];
        if c == '/' && bytes.get(k + 1) == Some(&'/') {
            while k < bytes.len() && bytes[k] != '\n' {
                k += 1;
            }
        } else if c == '\'' && bytes.get(k + 2) == Some(&'\'') {
            k += 3; // a char literal such as '"'
        } else if c == 'r' && matches!(bytes.get(k + 1), Some('#' | '"')) {
            let hashes = bytes[k + 1..].iter().take_while(|c| **c == '#').count();
            let close: String = std::iter::once('"')
                .chain(std::iter::repeat_n('#', hashes))
                .collect();
            let rest: String = bytes[k + 2 + hashes..].iter().collect();
            k += 2 + hashes + rest.find(&close).map_or(rest.len(), |e| e + close.len());
        } else if c == '"' {
            let mut s = String::new();
            k += 1;
            while k < bytes.len() && bytes[k] != '"' {
                if bytes[k] == '\\' {
                    k += 1;
                }
                if let Some(&c) = bytes.get(k) {
                    s.push(c);
                }
                k += 1;
            }
            out.push(s);
            k += 1;
        } else {
            k += 1;
        }
    }
    out
}

#[test]
fn every_key_the_code_names_is_in_the_catalogues() {
    let sections: BTreeSet<&str> = keys(Lang::En).filter_map(|k| k.split('.').next()).collect();
    let mut named = 0;
    for path in sources() {
        for lit in literals(&program_text(&path)) {
            let Some((section, rest)) = lit.split_once('.') else {
                continue;
            };
            // Keys are lower-case words joined by dots; file names and templates are not.
            let key_like = sections.contains(section)
                && !rest.is_empty()
                && rest
                    .chars()
                    .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_' || c == '.');
            if !key_like || ["toml", "csv", "json", "png"].contains(&rest) {
                continue;
            }
            named += 1;
            // A key the code looks up per actuator kind (`Lang::tr_kind`) has each kind's.
            let per_kind = |lang| {
                ActuatorKind::ALL
                    .iter()
                    .all(|k| catalogue::lookup(lang, &format!("{lit}.{}", k.name())).is_some())
            };
            for lang in Lang::ALL {
                assert!(
                    catalogue::lookup(lang, &lit).is_some() || per_kind(lang),
                    "{}: `{lit}` is not in {}.toml",
                    path.display(),
                    lang.code()
                );
            }
        }
    }
    assert!(named > 200, "only {named} keys found in the sources");
}

#[test]
fn no_widget_takes_its_words_from_the_code() {
    // Calls that put text on screen, taking a literal (or a format! of one) directly.
    const CALLS: [&str; 22] = [
        ".label(",
        ".button(",
        ".heading(",
        ".small_button(",
        ".on_hover_text(",
        ".on_disabled_hover_text(",
        ".hint_text(",
        ".suffix(",
        ".prefix(",
        ".text(",
        ".selected_text(",
        ".x_axis_label(",
        ".y_axis_label(",
        ".menu_button(",
        "from_label(",
        "CollapsingHeader::new(",
        "RichText::new(",
        "Button::new(",
        "Button::selectable(",
        "ProgressBar::new(",
        ".checkbox(",
        "_value(",
    ];
    let ui_dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/viewer");
    let mut offences = Vec::new();
    for path in sources().into_iter().filter(|p| p.starts_with(&ui_dir)) {
        let text = program_text(&path);
        for call in CALLS {
            for (at, _) in text.match_indices(call) {
                // The call's first line of arguments, up to the end of the statement.
                let args: String = text[at + call.len()..]
                    .chars()
                    .take_while(|c| *c != ';' && *c != '{')
                    .take(160)
                    .collect();
                for lit in literals(&args).into_iter().take(1) {
                    let words = fill_blank(&lit)
                        .split(|c: char| !c.is_ascii_alphabetic())
                        .any(|w| w.len() >= 2);
                    let key = lit.contains('.')
                        && lit
                            .chars()
                            .all(|c| c.is_ascii_lowercase() || c == '_' || c == '.');
                    // Function names read the same in Chinese mathematics.
                    let maths = ["sin", "cos"].contains(&lit.as_str());
                    if words && !key && !maths {
                        offences.push(format!("{}: {call}\"{lit}\"", path.display()));
                    }
                }
            }
        }
    }
    assert!(
        offences.is_empty(),
        "widgets with words from the code, not the catalogues:\n{}",
        offences.join("\n")
    );
}

#[test]
fn the_readout_speaks_chinese() {
    let s = Scenario::seed();
    let text = crate::readout::lines(
        Lang::Zh,
        "",
        &s.geometry,
        None,
        &s.geometry.home_pose(),
        None,
    );
    assert!(text.contains("手动位姿") && text.contains("横滚") && text.contains("偏航"));
}

#[test]
fn every_chinese_text_has_its_glyphs() {
    // The fonts the renderer draws with (a Latin sans, then the system's Chinese font,
    // which egui takes too): no character of the catalogue may fall back to a box.
    assert!(
        super::fonts::cjk().is_some(),
        "no Chinese font: scripts/setup.sh installs fonts-wqy-microhei"
    );
    let fonts = stewart_render::Fonts::system();
    for key in keys(Lang::Zh) {
        let text = Lang::Zh.tr(key);
        let missing: String = text
            .chars()
            .filter(|c| !fonts.covers(&c.to_string()))
            .collect();
        assert!(missing.is_empty(), "`{key}`: no glyph for {missing:?}");
    }
}

#[test]
fn chinese_has_no_space_between_two_chinese_words_and_presets_describe_themselves() {
    let channel = Lang::Zh.fmt("motion.channel", &[("axis", &"横滚")]);
    assert_eq!(channel, "横滚通道");
    // A Latin letter keeps its space.
    assert_eq!(Lang::Zh.fmt("motion.channel", &[("axis", &"x")]), "x 通道");
    for name in stewart_kinematics::io::scenario::presets::names() {
        let s = Scenario::preset(name).unwrap_or_else(|e| panic!("{e}"));
        let zh = super::words::description(Lang::Zh, name, &s.description);
        assert!(zh.chars().any(is_han), "{name}: {zh}");
        assert_eq!(
            super::words::description(Lang::En, name, &s.description),
            s.description
        );
        // An edited description is shown as written.
        assert_eq!(super::words::description(Lang::Zh, name, "mine"), "mine");
    }
}
