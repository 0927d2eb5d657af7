//! A C header of a scenario's geometry for controller firmware (Arduino, STM32): named
//! constants with their units in the names, so a sketch can run the same inverse
//! kinematics the studio runs and apply the same servo mounting (reversal and trim).

use std::fmt::Write as _;

use stewart_kinematics::model::actuator::Actuator;
use stewart_kinematics::model::rotary::RotaryActuators;
use stewart_kinematics::{Geometry, Scenario, model::geometry::Plate};

/// A number as a C double literal that reads back to the same `f64` (shortest
/// round-trip digits, always with a decimal point or exponent).
fn c_double(v: f64) -> String {
    let text = format!("{v:?}");
    if text.contains(['.', 'e', 'E']) {
        text
    } else {
        format!("{text}.0")
    }
}

/// A number for a `#define`: negative values in parentheses, so `x-STEWART_A` stays right.
fn c_define(v: f64) -> String {
    if v < 0.0 {
        format!("({})", c_double(v))
    } else {
        c_double(v)
    }
}

fn c_list(values: impl IntoIterator<Item = f64>) -> String {
    let items: Vec<String> = values.into_iter().map(c_double).collect();
    format!("{{ {} }}", items.join(", "))
}

/// `name` made into the tail of a C identifier: letters and digits in upper case, the rest `_`.
fn identifier(name: &str) -> String {
    let id: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_uppercase()
            } else {
                '_'
            }
        })
        .collect();
    if id.is_empty() {
        "SCENARIO".to_owned()
    } else {
        id
    }
}

/// The header text for `scenario`. Everything is in the base frame (z up, metres) and
/// degrees, as in the scenario file; the joints are listed as points so that firmware
/// needs no trigonometry to place them.
pub(crate) fn header(scenario: &Scenario) -> String {
    let g = &scenario.geometry;
    // What differs by actuator kind: its flag, what the base points are, and its section.
    let (rotary, base_points, section) = match g.actuator() {
        Actuator::Linear => (0, "Base joints B_i (base frame)", stroke_section(g)),
        Actuator::Rotary(servos) => (
            1,
            "Servo shaft centres B_i (base frame)",
            servo_section(servos),
        ),
    };
    let p = g.params();
    let guard = format!("STEWART_GEOMETRY_{}_H", identifier(&scenario.name));
    let mut s = String::new();
    // Writing to a String cannot fail.
    let _ = writeln!(
        s,
        "/* Geometry of the Stewart platform `{}`, written by `stewart firmware`.\n \
         * Base frame: z up, origin at the base centre; lengths in metres, angles in degrees.\n \
         * Platform joints are in the platform frame; the pose (x, y, z, roll, pitch, yaw) puts\n \
         * them at p + R_z(yaw) R_y(pitch) R_x(roll) (a - pivot) + pivot. */",
        scenario.name.replace("*/", "* /")
    );
    let _ = writeln!(s, "#ifndef {guard}\n#define {guard}\n");
    // Arrays a translation unit does not use must not warn (C's -Wunused-const-variable).
    let _ = writeln!(
        s,
        "#if defined(__GNUC__)\n#define STEWART_UNUSED __attribute__((unused))\n#else\n#define STEWART_UNUSED\n#endif\n"
    );
    let _ = writeln!(s, "#define STEWART_ACTUATOR_ROTARY {rotary}");
    let _ = writeln!(
        s,
        "#define STEWART_BASE_RADIUS_M {}",
        c_define(g.plate_radius(Plate::Base))
    );
    let _ = writeln!(
        s,
        "#define STEWART_PLATFORM_RADIUS_M {}",
        c_define(g.plate_radius(Plate::Platform))
    );
    let _ = writeln!(
        s,
        "#define STEWART_HOME_HEIGHT_M {}\n",
        c_define(p.home_height)
    );
    let points = |joints: &[nalgebra::Vector3<f64>; 6]| {
        let rows: Vec<String> = joints
            .iter()
            .map(|j| format!("    {}", c_list([j.x, j.y, j.z])))
            .collect();
        rows.join(",\n")
    };
    let _ = writeln!(
        s,
        "/* {base_points}. */\nSTEWART_UNUSED static const double STEWART_BASE_JOINTS_M[6][3] = {{\n{}\n}};",
        points(g.base_joints())
    );
    let _ = writeln!(
        s,
        "/* Platform joints a_i (platform frame). */\nSTEWART_UNUSED static const double STEWART_PLATFORM_JOINTS_M[6][3] = {{\n{}\n}};",
        points(g.platform_joints())
    );
    let _ = writeln!(
        s,
        "/* Rotation centre (platform frame). */\nSTEWART_UNUSED static const double STEWART_PIVOT_M[3] = {};\n",
        c_list([p.pivot.x, p.pivot.y, p.pivot.z])
    );
    s.push_str(&section);
    let _ = writeln!(s, "\n#endif /* {guard} */");
    s
}

/// The stroke of linear legs, where the scenario sets it.
fn stroke_section(g: &Geometry) -> String {
    let mut s = String::new();
    let stroke = g.stroke();
    for (name, v) in [("LEG_MIN_M", stroke.min), ("LEG_MAX_M", stroke.max)] {
        if let Some(v) = v {
            let _ = writeln!(s, "#define STEWART_{name} {}", c_define(v));
        }
    }
    s
}

/// Horns, rods, range and mounting of the servos.
fn servo_section(servos: &RotaryActuators) -> String {
    let mut text = String::new();
    let s = &mut text;
    let _ = writeln!(
        s,
        "/* Servo i: horn tip H_i = B_i + a (cos t cos b_i, cos t sin b_i, sin t) at model angle t;\n \
         * the rod closes |q_i - H_i| = s. Closed form, with l = q_i - B_i:\n \
         * L = |l|^2 - (s^2 - a^2), M = 2 a l_z, N = 2 a (cos b_i l_x + sin b_i l_y),\n \
         * t = asin(L / sqrt(M^2 + N^2)) - atan2(N, M); unreachable when |L| > sqrt(M^2 + N^2).\n \
         * Commanded angle = (reversed ? -t : t) + trim, wrapped to (-180, 180]. */"
    );
    let _ = writeln!(
        s,
        "#define STEWART_HORN_LENGTH_M {}",
        c_define(servos.horn_length())
    );
    let _ = writeln!(
        s,
        "#define STEWART_ROD_LENGTH_M {}",
        c_define(servos.rod_length())
    );
    if let Some((min, max)) = servos.range() {
        let _ = writeln!(
            s,
            "#define STEWART_SERVO_MIN_DEG {}",
            c_define(min.degrees())
        );
        let _ = writeln!(
            s,
            "#define STEWART_SERVO_MAX_DEG {}",
            c_define(max.degrees())
        );
    }
    let _ = writeln!(
        s,
        "/* Horn directions b_i: where horn i points at model angle 0, from +x in the base plane. */\nSTEWART_UNUSED static const double STEWART_HORN_ANGLES_DEG[6] = {};",
        c_list(servos.horn_angles().iter().map(|a| a.degrees()))
    );
    let _ = writeln!(
        s,
        "/* Servos mounted mirrored (1: the commanded angle runs the other way). */\nSTEWART_UNUSED static const int STEWART_SERVO_REVERSED[6] = {{ {} }};",
        servos
            .reversed()
            .iter()
            .map(|&r| if r { "1" } else { "0" })
            .collect::<Vec<_>>()
            .join(", ")
    );
    let _ = writeln!(
        s,
        "/* Mounting offsets added to the commanded angles. */\nSTEWART_UNUSED static const double STEWART_SERVO_TRIM_DEG[6] = {};",
        c_list(servos.trims().iter().map(|a| a.degrees()))
    );
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_read_back_exactly_and_names_are_identifiers() {
        for v in [0.025, 1.0, -70.0, 1e-7, 0.1 + 0.2, 123456789.0] {
            let text = c_double(v);
            assert!(text.contains(['.', 'e']), "{text}");
            assert_eq!(text.parse::<f64>().ok(), Some(v));
        }
        assert_eq!(identifier("servo-desk"), "SERVO_DESK");
        assert_eq!(identifier("台架"), "__");
    }
}
