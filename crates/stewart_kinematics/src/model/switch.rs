//! A switch written in words or as a number: the one rule every switch of a scenario takes
//! (`--set`, scenario files' link table, Python), so that `1.0` is on everywhere or nowhere.

/// What a switch takes, in words for refusals.
pub const ACCEPTS: &str = "true or false (on or off, 1 or 0)";

/// The switch `text` says: `true` or `on`, or a number equal to 1, is on; `false` or `off`,
/// or a number equal to 0, is off (any case, spaces around); anything else says neither.
pub fn read(text: &str) -> Option<bool> {
    let word = text.trim().to_ascii_lowercase();
    match word.as_str() {
        "true" | "on" => Some(true),
        "false" | "off" => Some(false),
        _ => match word.parse::<f64>() {
            Ok(1.0) => Some(true),
            Ok(0.0) => Some(false),
            _ => None,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::read;

    #[test]
    fn words_and_the_numbers_one_and_zero_are_switches_and_nothing_else() {
        for on in ["true", "ON", " on ", "1", "1.0", "01"] {
            assert_eq!(read(on), Some(true), "{on}");
        }
        for off in ["false", "Off", "0", "00", "-0", "0.0"] {
            assert_eq!(read(off), Some(false), "{off}");
        }
        for neither in ["3.0", "yes", "", "nan", "0.5", "inf"] {
            assert_eq!(read(neither), None, "{neither}");
        }
    }
}
