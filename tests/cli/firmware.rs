//! `stewart firmware`: the C header compiles with the system C compiler (strict warnings,
//! as C99 and as C++), and a C program using only its constants computes the same
//! commanded servo angles as `stewart solve --commanded`.

use crate::{parse_csv, stderr, stdout, stewart, tempdir, write};

/// A C program: the closed-form servo angle of the header's comment, for the poses given
/// on its command line (x y z roll pitch yaw, metres and degrees), commanded with the
/// header's reversal and trim; prints six angles per pose.
const PROGRAM: &str = r#"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "servo_geometry.h"

static double rad(double d) { return d * 3.14159265358979323846 / 180.0; }

int main(int argc, char **argv) {
    for (int k = 1; k + 5 < argc; k += 6) {
        double p[3], a[3];
        for (int j = 0; j < 3; j++) { p[j] = atof(argv[k + j]); a[j] = rad(atof(argv[k + 3 + j])); }
        double cr = cos(a[0]), sr = sin(a[0]), cp = cos(a[1]), sp = sin(a[1]), cy = cos(a[2]), sy = sin(a[2]);
        /* R = Rz(yaw) Ry(pitch) Rx(roll) */
        double r[3][3] = {
            { cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr },
            { sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr },
            { -sp, cp * sr, cp * cr } };
        for (int i = 0; i < 6; i++) {
            double l[3];
            for (int j = 0; j < 3; j++) {
                double q = p[j] + STEWART_PIVOT_M[j];
                for (int m = 0; m < 3; m++) q += r[j][m] * (STEWART_PLATFORM_JOINTS_M[i][m] - STEWART_PIVOT_M[m]);
                l[j] = q - STEWART_BASE_JOINTS_M[i][j];
            }
            double s = STEWART_ROD_LENGTH_M, h = STEWART_HORN_LENGTH_M, b = rad(STEWART_HORN_ANGLES_DEG[i]);
            double L = l[0] * l[0] + l[1] * l[1] + l[2] * l[2] - (s * s - h * h);
            double M = 2 * h * l[2], N = 2 * h * (cos(b) * l[0] + sin(b) * l[1]);
            double t = (asin(L / sqrt(M * M + N * N)) - atan2(N, M)) * 180.0 / 3.14159265358979323846;
            double c = (STEWART_SERVO_REVERSED[i] ? -t : t) + STEWART_SERVO_TRIM_DEG[i];
            while (c > 180.0) c -= 360.0;
            while (c <= -180.0) c += 360.0;
            printf("%.17g%c", c, i == 5 ? '\n' : ',');
        }
    }
    return 0;
}
"#;

/// Build `source` into `program` with `compiler` and `flags` plus strict warnings; a failed
/// build fails the test with the compiler's words.
fn build(compiler: &str, flags: &[&str], source: &str, program: &std::path::Path) {
    let built = std::process::Command::new(compiler)
        .args(flags)
        .args(["-Wall", "-Wextra", "-Werror", "-o"])
        .arg(program)
        .arg(source)
        .arg("-lm")
        .output()
        .unwrap_or_else(|e| panic!("{compiler}: {e}"));
    assert!(
        built.status.success(),
        "{compiler}: {}",
        String::from_utf8_lossy(&built.stderr)
    );
}

#[test]
fn the_header_compiles_and_gives_the_commanded_angles_of_solve() {
    let dir = tempdir();
    let header = dir.path().join("servo_geometry.h");
    let mounting = [
        "--set",
        "actuator.servo_trim_deg[0]=4.5",
        "--set",
        "actuator.servo_trim_deg[3]=-2",
    ];
    let mut args = vec!["firmware", "--preset", "servo-desk"];
    args.extend(mounting);
    args.extend(["--out", header.to_str().unwrap_or_default()]);
    let o = stewart(&args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = std::fs::read_to_string(&header).unwrap_or_else(|e| panic!("{e}"));
    assert!(
        text.contains("#define STEWART_SERVO_MIN_DEG (-70.0)"),
        "{text}"
    );
    assert!(text.contains("STEWART_SERVO_TRIM_DEG[6] = { 4.5, 0.0, 0.0, -2.0, 0.0, 0.0 }"));
    // Strict C99 and C++ builds of a file that includes the header and uses nothing.
    let empty = write(
        dir.path(),
        "empty.c",
        "#include \"servo_geometry.h\"\nint main(void) { return 0; }\n",
    );
    for (compiler, flags) in [("cc", vec!["-std=c99"]), ("c++", vec!["-x", "c++"])] {
        let out = dir.path().join(format!("empty-{compiler}"));
        build(compiler, &flags, &empty, &out);
    }
    // The program's angles equal solve's commanded angles.
    let source = write(dir.path(), "angles.c", PROGRAM);
    let program = dir.path().join("angles");
    build("cc", &["-std=c99", "-O2"], &source, &program);
    let poses = [
        [0.0, 0.0, 0.112, 0.0, 0.0, 0.0],
        [0.01, -0.008, 0.118, 5.0, -4.0, 8.0],
        [-0.006, 0.012, 0.105, -3.0, 6.0, -12.0],
    ];
    let table: String = std::iter::once("x,y,z,roll_deg,pitch_deg,yaw_deg\n".to_owned())
        .chain(poses.iter().map(|p| {
            let cells: Vec<String> = p.iter().map(|v| v.to_string()).collect();
            cells.join(",") + "\n"
        }))
        .collect();
    let table = write(dir.path(), "poses.csv", &table);
    let mut args = vec![
        "solve",
        "--preset",
        "servo-desk",
        "--commanded",
        "--poses",
        &table,
    ];
    args.extend(mounting);
    let o = stewart(&args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let (header_row, rows) = parse_csv(&stdout(&o));
    let first = header_row
        .iter()
        .position(|c| c == "cmd1")
        .unwrap_or_else(|| panic!("{header_row:?}"));
    let numbers: Vec<String> = poses.iter().flatten().map(|v| v.to_string()).collect();
    let run = std::process::Command::new(&program)
        .args(&numbers)
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    let printed = String::from_utf8_lossy(&run.stdout).into_owned();
    let c_rows: Vec<Vec<f64>> = printed
        .lines()
        .map(|l| l.split(',').filter_map(|v| v.parse().ok()).collect())
        .collect();
    assert_eq!(c_rows.len(), poses.len(), "{printed}");
    for (c_row, row) in c_rows.iter().zip(&rows) {
        for i in 0..6 {
            assert!(
                (c_row[i] - row[first + i]).abs() < 1e-9,
                "servo {}: C {} vs stewart {}",
                i + 1,
                c_row[i],
                row[first + i]
            );
        }
    }
}

#[test]
fn a_linear_platform_gets_its_joints_and_stroke() {
    let dir = tempdir();
    let o = stewart(&["firmware", "--preset", "paired"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = stdout(&o);
    assert!(text.contains("#define STEWART_ACTUATOR_ROTARY 0"));
    assert!(text.contains("#define STEWART_LEG_MAX_M 1.3") && !text.contains("HORN"));
    write(dir.path(), "servo_geometry.h", &text);
    let source = write(
        dir.path(),
        "use.c",
        "#include \"servo_geometry.h\"\nint main(void) { return STEWART_BASE_JOINTS_M[0][0] > 0.0 ? 0 : 1; }\n",
    );
    let program = dir.path().join("use");
    build("cc", &["-std=c99"], &source, &program);
    let ran = std::process::Command::new(&program).status();
    assert!(ran.is_ok_and(|s| s.success()));
}
