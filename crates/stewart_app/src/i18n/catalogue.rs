//! The two catalogues, read from the TOML compiled into the program: each `[section]`
//! and `key = "text"` becomes the key `section.key`.

use std::collections::BTreeMap;
use std::sync::LazyLock;

use super::Lang;

/// English (the source language).
const EN: &str = include_str!("../../locales/en.toml");
/// Simplified Chinese.
const ZH: &str = include_str!("../../locales/zh.toml");

static TABLES: LazyLock<[BTreeMap<String, String>; 2]> =
    LazyLock::new(|| [parse(EN, "en.toml"), parse(ZH, "zh.toml")]);

/// The text of `key` in `lang`.
pub(crate) fn lookup(lang: Lang, key: &str) -> Option<&'static str> {
    let table = &TABLES[lang as usize];
    table.get(key).map(String::as_str)
}

/// Every key of `lang`'s catalogue, sorted.
#[cfg(test)]
pub(crate) fn keys(lang: Lang) -> impl Iterator<Item = &'static str> {
    TABLES[lang as usize].keys().map(String::as_str)
}

/// A catalogue as flat keys. The catalogues are part of the program (tests parse both),
/// so a broken one is a build defect, not bad input.
fn parse(text: &str, name: &str) -> BTreeMap<String, String> {
    let table: toml::Table = match text.parse() {
        Ok(t) => t,
        Err(e) => panic!("the catalogue {name} is not valid TOML: {e}"),
    };
    let mut out = BTreeMap::new();
    flatten("", &table, &mut out, name);
    out
}

fn flatten(prefix: &str, table: &toml::Table, out: &mut BTreeMap<String, String>, name: &str) {
    for (key, value) in table {
        let full = if prefix.is_empty() {
            key.clone()
        } else {
            format!("{prefix}.{key}")
        };
        match value {
            toml::Value::String(s) => {
                out.insert(full, s.clone());
            }
            toml::Value::Table(t) => flatten(&full, t, out, name),
            other => panic!("the catalogue {name}: `{full}` is {other:?}, not text"),
        }
    }
}
