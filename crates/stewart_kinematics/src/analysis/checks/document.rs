//! The report as one document for programs: the scenario's name, whether it is clean, the
//! actuator kind and its limits, then the report's own fields. `stewart check --format
//! json` writes it; the Python package's `Platform.check()` returns it as a dict.

use serde::Serialize;

use super::CheckReport;
use crate::model::geometry::Geometry;

/// The JSON document of a check.
#[derive(Serialize)]
pub struct CheckDocument<'a> {
    scenario: &'a str,
    clean: bool,
    actuator: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    leg_min_m: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    leg_max_m: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    servo_min_deg: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    servo_max_deg: Option<f64>,
    #[serde(flatten)]
    report: &'a CheckReport,
}

impl<'a> CheckDocument<'a> {
    /// The document of `report`, for the scenario called `name` on `geometry`.
    pub fn new(name: &'a str, geometry: &Geometry, report: &'a CheckReport) -> Self {
        let stroke = geometry.stroke();
        let range = geometry.actuator().servo_range();
        Self {
            scenario: name,
            clean: report.is_clean(),
            actuator: geometry.actuator().kind_name(),
            leg_min_m: stroke.min,
            leg_max_m: stroke.max,
            servo_min_deg: range.map(|(min, _)| min.degrees()),
            servo_max_deg: range.map(|(_, max)| max.degrees()),
            report,
        }
    }
}
