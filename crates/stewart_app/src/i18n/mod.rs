//! The words people read, in Simplified Chinese and English: one catalogue per language
//! (`locales/en.toml`, `locales/zh.toml`), compiled into the program, looked up by key.
//!
//! A plain table, not an i18n framework: two languages without plural forms or gender
//! need lookup and named placeholders (`{name}`), nothing more, and a table costs no
//! dependency and no build step. Tests check that both catalogues have the same keys and
//! placeholders, that every key the code uses exists, and that the viewer's widgets take
//! their words from here.

mod catalogue;
pub(crate) mod fonts;
pub(crate) mod words;

use std::fmt::Display;

use serde::{Deserialize, Serialize};
use stewart_kinematics::model::actuator::ActuatorKind;

#[cfg(test)]
pub(crate) use catalogue::keys;

/// A language of the interface.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Lang {
    /// English.
    #[default]
    En,
    /// Simplified Chinese.
    Zh,
}

impl Lang {
    /// Both languages, English first.
    pub(crate) const ALL: [Lang; 2] = [Lang::En, Lang::Zh];

    /// `en` or `zh`, as `--lang` takes it.
    #[cfg(test)]
    pub(crate) fn code(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Zh => "zh",
        }
    }

    /// The language's own name (`English`, `中文`).
    pub(crate) fn own_name(self) -> &'static str {
        match self {
            Lang::En => "English",
            Lang::Zh => "中文",
        }
    }

    /// The language `LC_ALL`, `LC_MESSAGES` or `LANG` asks for (the first one set, as the
    /// C library reads them): Chinese for `zh…`, else English.
    pub(crate) fn from_env() -> Lang {
        let value = ["LC_ALL", "LC_MESSAGES", "LANG"]
            .into_iter()
            .filter_map(|name| std::env::var(name).ok())
            .find(|v| !v.is_empty());
        Lang::from_locale(value.as_deref().unwrap_or(""))
    }

    /// The language of a POSIX locale name such as `zh_CN.UTF-8` or `en_GB`.
    pub(crate) fn from_locale(locale: &str) -> Lang {
        if locale.to_ascii_lowercase().starts_with("zh") {
            Lang::Zh
        } else {
            Lang::En
        }
    }

    /// The text of `key` (the key itself when the catalogue lacks it, which a test rules
    /// out for every key the code names).
    pub(crate) fn tr(self, key: &str) -> &'static str {
        catalogue::lookup(self, key).unwrap_or_else(|| leak_missing(key))
    }

    /// The text of `key` for an actuator kind: the catalogue's `key.linear`, `key.rotary`
    /// (a test checks that every such key has each kind's words).
    pub(crate) fn tr_kind(self, key: &str, kind: ActuatorKind) -> &'static str {
        self.tr(&format!("{key}.{}", kind.name()))
    }

    /// [`Lang::fmt`] of `key` for an actuator kind, as [`Lang::tr_kind`] finds it.
    pub(crate) fn fmt_kind(
        self,
        key: &str,
        kind: ActuatorKind,
        args: &[(&str, &dyn Display)],
    ) -> String {
        self.fmt(&format!("{key}.{}", kind.name()), args)
    }

    /// The text of `key` with each `{name}` replaced by its value in `args`.
    pub(crate) fn fmt(self, key: &str, args: &[(&str, &dyn Display)]) -> String {
        let text = fill(self.tr(key), args);
        match self {
            Lang::Zh => close_han_gaps(&text),
            Lang::En => text,
        }
    }
}

/// `text` without the spaces between two Chinese characters (a template such as
/// `{axis} 通道` spaced for a Latin `x` reads `横滚 通道` with a Chinese word in it).
pub(crate) fn close_han_gaps(text: &str) -> String {
    let han = |c: char| matches!(c, '\u{3400}'..='\u{9fff}' | '\u{f900}'..='\u{faff}');
    let mut out = String::with_capacity(text.len());
    let mut chars = text.chars().peekable();
    let mut previous = None;
    while let Some(c) = chars.next() {
        let gap = c == ' ' && previous.is_some_and(han) && chars.peek().is_some_and(|&n| han(n));
        if !gap {
            out.push(c);
        }
        previous = Some(c);
    }
    out
}

/// The language of a command's drawn words: `asked` (`--lang`), else the environment's.
/// Chinese without a font for it falls back to English, said once on standard error.
pub(crate) fn for_command(asked: Option<Lang>, command: &str) -> Lang {
    let (lang, note) = fonts::usable_here(asked.unwrap_or_else(Lang::from_env));
    if let Some(note) = note {
        use std::io::Write as _;
        let _ = writeln!(std::io::stderr(), "{command}: {note}");
    }
    lang
}

/// The text of `key` in `lang`, `None` when the catalogue lacks it.
pub(crate) fn catalogue_text(lang: Lang, key: &str) -> Option<&'static str> {
    catalogue::lookup(lang, key)
}

/// `template` with `{name}` replaced by the matching value of `args`; unknown names stay.
pub(crate) fn fill(template: &str, args: &[(&str, &dyn Display)]) -> String {
    let mut out = String::with_capacity(template.len() + 16);
    let mut rest = template;
    while let Some(open) = rest.find('{') {
        out.push_str(&rest[..open]);
        let after = &rest[open + 1..];
        match after.find('}') {
            Some(close) => {
                let name = &after[..close];
                match args.iter().find(|(n, _)| *n == name) {
                    Some((_, value)) => out.push_str(&value.to_string()),
                    None => {
                        out.push('{');
                        out.push_str(name);
                        out.push('}');
                    }
                }
                rest = &after[close + 1..];
            }
            None => {
                out.push_str(&rest[open..]);
                rest = "";
            }
        }
    }
    out.push_str(rest);
    out
}

/// A missing key shows as itself (never a crash); each distinct one is kept once.
fn leak_missing(key: &str) -> &'static str {
    use std::collections::HashSet;
    use std::sync::Mutex;
    static MISSING: Mutex<Option<HashSet<&'static str>>> = Mutex::new(None);
    let mut guard = MISSING.lock().unwrap_or_else(|p| p.into_inner());
    let set = guard.get_or_insert_with(HashSet::new);
    if let Some(k) = set.get(key) {
        return k;
    }
    let k: &'static str = Box::leak(key.to_owned().into_boxed_str());
    set.insert(k);
    k
}

#[cfg(test)]
mod tests;
