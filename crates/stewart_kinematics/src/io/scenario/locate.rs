//! Where a setting's key stands in a scenario file's text, for errors found after
//! parsing (a value outside its accepted range).

use std::ops::Range;

use toml::Spanned;
use toml::de::{DeTable, DeValue};

/// Byte range of the value at `key` (a settings key such as `trajectory.pitch.phase_deg`
/// or `geometry.platform_angles_deg[2]`) in the TOML `text`, if it is written there.
pub(crate) fn span_of(text: &str, key: &str) -> Option<Range<usize>> {
    let root = DeTable::parse(text).ok()?;
    let mut table: &DeTable = root.get_ref();
    let mut parts = key.split('.').peekable();
    while let Some(part) = parts.next() {
        let (name, index) = match part.split_once('[') {
            Some((name, rest)) => (name, rest.trim_end_matches(']').parse::<usize>().ok()),
            None => (part, None),
        };
        let value = lookup(table, name)?;
        let value = match index {
            Some(i) => match value.get_ref() {
                DeValue::Array(items) => items.get(i)?,
                _ => return None,
            },
            None => value,
        };
        if parts.peek().is_none() {
            return Some(value.span());
        }
        match value.get_ref() {
            DeValue::Table(t) => table = t,
            _ => return None,
        }
    }
    None
}

fn lookup<'a, 'i>(table: &'a DeTable<'i>, name: &str) -> Option<&'a Spanned<DeValue<'i>>> {
    table
        .iter()
        .find(|(k, _)| k.get_ref().as_ref() == name)
        .map(|(_, v)| v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_nested_keys_and_array_items() {
        let text = "[geometry]\nbase_radius = 1.0\nplatform_angles_deg = [10, 20, 30]\n\n[trajectory.pitch]\nphase_deg = 45\n";
        let at = |key| span_of(text, key).map(|r| &text[r]);
        assert_eq!(at("geometry.base_radius"), Some("1.0"));
        assert_eq!(at("geometry.platform_angles_deg[2]"), Some("30"));
        assert_eq!(at("trajectory.pitch.phase_deg"), Some("45"));
        assert_eq!(at("trajectory.yaw.phase_deg"), None);
        assert_eq!(at("geometry.platform_angles_deg[7]"), None);
    }
}
