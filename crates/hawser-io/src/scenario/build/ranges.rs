//! The physical range of every numeric key. A value beyond it is no physical system (a wrong
//! unit or exponent, or a fuzzer's f64::MAX) and would overflow the computation: a free point
//! of mass 1e308 kg weighs ∞ N and statics "converges" with an infinite residual. Each bound
//! is far beyond the largest real system (10 to 1000 times), so no real input is refused,
//! and low enough that the products the forces are made of stay far from overflow (a mass of
//! 1e10 kg under 100 m/s² weighs 1e12 N).
//!
//! Keys are matched by their path without indices or `mean` (`points[3].motion.mean.speed`
//! reads as `points[].motion.speed`), by the longest dotted suffix in [`RANGES`]. A test
//! checks that every number of the JSON Schema has a range, so a new key cannot go without.

/// The bounds of one number [unit].
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Bounds {
    /// Smallest value [unit].
    pub min: f64,
    /// Largest value [unit].
    pub max: f64,
    /// Unit, as in the expected text of errors.
    pub unit: &'static str,
}

/// The range of a key: the same bounds for every number, or bounds per column of its rows
/// (entry j of a flattened row takes column j mod the number of columns).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Range {
    /// Every number of the key.
    All(Bounds),
    /// One bounds per column.
    Columns(&'static [Bounds]),
}

impl Range {
    /// The bounds of entry `j` of the key's numbers.
    pub fn bounds(&self, j: usize) -> Bounds {
        match self {
            Range::All(b) => *b,
            Range::Columns(c) => c[j % c.len()],
        }
    }
}

const fn b(min: f64, max: f64, unit: &'static str) -> Bounds {
    Bounds { min, max, unit }
}

const fn all(min: f64, max: f64, unit: &'static str) -> Range {
    Range::All(b(min, max, unit))
}

/// 10 full turns either way [deg]: angles beyond lose their precision in sin and cos.
const ANGLE: Range = all(-3600.0, 3600.0, "deg");
/// Positions, anywhere within 10 000 km [m].
const POSITION: Range = all(-1e7, 1e7, "m");
/// Times and durations: up to 3 years [s].
const TIME: Range = all(0.0, 1e8, "s");
/// Dimensionless coefficients (drag, added mass, damping ratios).
const COEFFICIENT: Range = all(0.0, 1e3, "-");

/// Keys (dotted suffixes of index-free paths) and their ranges.
pub(super) const RANGES: &[(&str, Range)] = &[
    // [simulation]
    ("simulation.duration", TIME),
    ("simulation.time_step", all(0.0, 1e3, "s")),
    ("simulation.safety_factor", all(0.0, 1.0, "-")),
    ("simulation.spectral_radius", all(0.0, 1.0, "-")),
    ("simulation.tolerance", all(0.0, 1.0, "-")),
    ("simulation.output_interval", TIME),
    ("simulation.snapshot_interval", TIME),
    // [statistics]
    ("statistics.start", TIME),
    ("statistics.storm_duration", TIME),
    // [environment]
    ("environment.gravity", all(0.0, 100.0, "m/s²")),
    ("environment.water_density", all(0.0, 1e5, "kg/m³")),
    ("environment.air_density", all(0.0, 1e5, "kg/m³")),
    ("environment.depth", all(0.0, 1e5, "m")),
    ("seabed.stiffness", all(0.0, 1e13, "Pa/m")),
    ("seabed.damping_ratio", all(0.0, 1e4, "-")),
    ("seabed.damping", all(0.0, 1e13, "Pa·s/m")),
    ("seabed.friction_coefficient", all(0.0, 100.0, "-")),
    ("seabed.friction_velocity", all(0.0, 1e3, "m/s")),
    ("seabed.friction_damping", all(0.0, 1e13, "N·s/m")),
    ("seabed.static_friction_scale", all(0.0, 1e3, "-")),
    ("seabed.gradient", all(-1e3, 1e3, "-")),
    ("seabed.normal", all(-1e3, 1e3, "-")),
    (
        "seabed.grid",
        Range::Columns(&[b(-1e7, 1e7, "m"), b(-1e7, 1e7, "m"), b(-1e5, 1e5, "m")]),
    ),
    ("current.velocity", all(-100.0, 100.0, "m/s")),
    (
        "current.profile",
        Range::Columns(&[
            b(-1e5, 1e5, "m"),
            b(-100.0, 100.0, "m/s"),
            b(-100.0, 100.0, "m/s"),
            b(-100.0, 100.0, "m/s"),
        ]),
    ),
    ("current.z", all(-1e5, 1e5, "m")),
    ("current.times", all(-1e9, 1e9, "s")),
    ("current.ux", all(-100.0, 100.0, "m/s")),
    ("current.uy", all(-100.0, 100.0, "m/s")),
    ("current.uz", all(-100.0, 100.0, "m/s")),
    (
        "waves.elevation",
        Range::Columns(&[b(-1e9, 1e9, "s"), b(-100.0, 100.0, "m")]),
    ),
    (
        "waves.elevation_file",
        Range::Columns(&[b(-1e9, 1e9, "s"), b(-100.0, 100.0, "m")]),
    ),
    ("waves.resample_interval", all(0.0, 1e4, "s")),
    ("waves.cutoff_frequency", all(0.0, 1e3, "Hz")),
    ("waves.sample_interval", all(0.0, 1e4, "s")),
    ("waves.height", all(0.0, 100.0, "m")),
    ("waves.period", all(0.0, 1e4, "s")),
    ("waves.significant_height", all(0.0, 100.0, "m")),
    ("waves.peak_period", all(0.0, 1e4, "s")),
    ("waves.gamma", all(0.0, 100.0, "-")),
    ("waves.direction", ANGLE),
    ("waves.spreading", all(0.0, 1e3, "-")),
    ("waves.frequency_range", all(0.0, 1e3, "Hz")),
    ("waves.ramp_time", TIME),
    // [[line_types]]
    ("line_types[].diameter", all(0.0, 100.0, "m")),
    ("line_types[].mass_per_length", all(0.0, 1e6, "kg/m")),
    ("line_types[].axial_stiffness", all(0.0, 1e14, "N")),
    (
        "line_types[].tension_strain",
        Range::Columns(&[b(-1.0, 100.0, "-"), b(-1e14, 1e14, "N")]),
    ),
    ("line_types[].axial_damping", all(0.0, 1e14, "N·s")),
    ("line_types[].axial_damping_ratio", all(0.0, 1e4, "-")),
    ("line_types[].normal_drag", COEFFICIENT),
    ("line_types[].tangential_drag", COEFFICIENT),
    ("line_types[].normal_added_mass", COEFFICIENT),
    ("line_types[].tangential_added_mass", COEFFICIENT),
    ("line_types[].bending_stiffness", all(0.0, 1e14, "N·m²")),
    ("line_types[].bending_damping", all(0.0, 1e14, "N·m²·s")),
    ("line_types[].minimum_breaking_load", all(0.0, 1e12, "N")),
    ("line_types[].design_safety_factor", all(1.0, 100.0, "-")),
    ("loading_functions.normal.cos", all(-1e3, 1e3, "-")),
    ("loading_functions.normal.sin", all(-1e3, 1e3, "-")),
    ("loading_functions.tangential.cos", all(-1e3, 1e3, "-")),
    ("loading_functions.tangential.sin", all(-1e3, 1e3, "-")),
    // [[points]], [[bodies]], [[obstacles]]
    ("position", POSITION),
    ("mass", all(0.0, 1e10, "kg")),
    ("volume", all(0.0, 1e8, "m³")),
    ("drag_area", all(0.0, 1e8, "m²")),
    ("added_mass_coefficient", COEFFICIENT),
    ("force", all(-1e13, 1e13, "N")),
    // motions
    ("motion.velocity", all(-1e3, 1e3, "m/s")),
    ("motion.amplitude", all(-1e5, 1e5, "m")),
    ("motion.period", TIME),
    ("motion.frequency", all(0.0, 1e4, "Hz")),
    ("motion.phase", ANGLE),
    ("motion.ramp_time", TIME),
    ("motion.radius", all(0.0, 1e7, "m")),
    (
        "motion.table",
        Range::Columns(&[
            b(-1e9, 1e9, "s"),
            b(-1e7, 1e7, "m"),
            b(-1e7, 1e7, "m"),
            b(-1e7, 1e7, "m"),
        ]),
    ),
    (
        "motion.file",
        Range::Columns(&[
            b(-1e9, 1e9, "s"),
            b(-1e7, 1e7, "m"),
            b(-1e7, 1e7, "m"),
            b(-1e7, 1e7, "m"),
            b(-3600.0, 3600.0, "deg"),
            b(-3600.0, 3600.0, "deg"),
            b(-3600.0, 3600.0, "deg"),
        ]),
    ),
    ("motion.time_offset", all(-1e9, 1e9, "s")),
    ("motion.start", POSITION),
    ("motion.heading", ANGLE),
    ("motion.speed", all(0.0, 100.0, "m/s")),
    ("motion.speed_knots", all(0.0, 200.0, "kn")),
    ("motion.straight_before", all(0.0, 1e8, "m")),
    ("motion.turn_radius", all(0.0, 1e7, "m")),
    ("motion.turn_angle", all(-36000.0, 36000.0, "deg")),
    ("motion.straight_after", all(0.0, 1e8, "m")),
    ("motion.build_up_time", TIME),
    ("motion.transition_length", all(0.0, 1e7, "m")),
    // [[lines]]
    ("lines[].length", all(0.0, 1e6, "m")),
    ("sections[].length", all(0.0, 1e6, "m")),
    ("lines[].modal_filter", all(0.0, 1.0, "-")),
    ("lines[].shock_filter", all(0.0, 1.0, "-")),
    ("lines[].clamp_a", all(-1e6, 1e6, "-")),
    ("lines[].clamp_b", all(-1e6, 1e6, "-")),
    ("winch.ramp_time", TIME),
    ("winch.minimum_length", all(0.0, 1e6, "m")),
    ("stages[].duration", TIME),
    ("stages[].payout_rate", all(-100.0, 100.0, "m/s")),
    ("failure.time", TIME),
    ("failure.tension", all(0.0, 1e12, "N")),
    ("failures[].time", TIME),
    ("failures[].tension", all(0.0, 1e12, "N")),
    // [[bodies]]
    ("bodies[].orientation", ANGLE),
    ("bodies[].centre_of_gravity", all(-1e4, 1e4, "m")),
    ("bodies[].pin_point", all(-1e4, 1e4, "m")),
    ("bodies[].centre_of_buoyancy", all(-1e4, 1e4, "m")),
    ("bodies[].hydrodynamic_centre", all(-1e4, 1e4, "m")),
    ("bodies[].members[].end_a", all(-1e4, 1e4, "m")),
    ("bodies[].members[].end_b", all(-1e4, 1e4, "m")),
    ("bodies[].members[].diameter", all(0.0, 1e3, "m")),
    ("bodies[].members[].normal_drag", COEFFICIENT),
    ("bodies[].members[].normal_added_mass", COEFFICIENT),
    ("bodies[].members[].end_drag", COEFFICIENT),
    ("bodies[].members[].end_added_mass", COEFFICIENT),
    ("bodies[].inertia", all(-1e16, 1e16, "kg·m²")),
    (
        "bodies[].added_mass",
        Range::Columns(&[
            b(0.0, 1e10, "kg"),
            b(0.0, 1e10, "kg"),
            b(0.0, 1e10, "kg"),
            b(0.0, 1e16, "kg·m²"),
            b(0.0, 1e16, "kg·m²"),
            b(0.0, 1e16, "kg·m²"),
        ]),
    ),
    (
        "bodies[].linear_drag",
        Range::Columns(&[
            b(0.0, 1e13, "N·s/m"),
            b(0.0, 1e13, "N·s/m"),
            b(0.0, 1e13, "N·s/m"),
            b(0.0, 1e16, "N·m·s/rad"),
            b(0.0, 1e16, "N·m·s/rad"),
            b(0.0, 1e16, "N·m·s/rad"),
        ]),
    ),
    (
        "bodies[].quadratic_drag",
        Range::Columns(&[
            b(0.0, 1e8, "m²"),
            b(0.0, 1e8, "m²"),
            b(0.0, 1e8, "m²"),
            b(0.0, 1e16, "m⁵"),
            b(0.0, 1e16, "m⁵"),
            b(0.0, 1e16, "m⁵"),
        ]),
    ),
    ("bodies[].drag_coefficients", COEFFICIENT),
    ("bodies[].drag_areas", all(0.0, 1e8, "m²")),
    ("displacement.radius", all(0.0, 1e4, "m")),
    ("displacement.height", all(0.0, 1e4, "m")),
    ("displacement.length", all(0.0, 1e4, "m")),
    ("displacement.breadth", all(0.0, 1e4, "m")),
    ("thrust.moment", all(-1e15, 1e15, "N·m")),
    (
        "thrust.table",
        Range::Columns(&[
            b(-1e9, 1e9, "s"),
            b(-1e13, 1e13, "N"),
            b(-1e13, 1e13, "N"),
            b(-1e13, 1e13, "N"),
            b(-1e15, 1e15, "N·m"),
            b(-1e15, 1e15, "N·m"),
            b(-1e15, 1e15, "N·m"),
        ]),
    ),
    ("wind.velocity", all(-1e3, 1e3, "m/s")),
    ("wind.centre", all(-1e4, 1e4, "m")),
    // [[obstacles]]
    ("obstacles[].radius", all(0.0, 1e5, "m")),
    ("obstacles[].length", all(0.0, 1e6, "m")),
    ("obstacles[].axis", all(-1e6, 1e6, "-")),
    ("obstacles[].stiffness", all(0.0, 1e13, "N/m²")),
    ("obstacles[].damping_ratio", all(0.0, 1e4, "-")),
    ("obstacles[].damping", all(0.0, 1e13, "N·s/m²")),
    ("obstacles[].friction_coefficient", all(0.0, 100.0, "-")),
    ("obstacles[].friction_velocity", all(0.0, 1e3, "m/s")),
];

/// `key` without indices and `mean` segments: `points[3].motion.mean.speed` becomes
/// `points[].motion.speed`.
fn normalised(key: &str) -> String {
    let mut out = String::with_capacity(key.len());
    let mut in_index = false;
    for c in key.chars() {
        match c {
            '[' => {
                in_index = true;
                out.push('[');
            }
            ']' => {
                in_index = false;
                out.push(']');
            }
            _ if in_index => {}
            _ => out.push(c),
        }
    }
    out.replace(".mean.", ".")
}

/// The range of `key` (a key path as diagnostics name it), if it has one.
pub(super) fn range_of(key: &str) -> Option<Range> {
    let key = normalised(key);
    let mut suffix = key.as_str();
    loop {
        if let Some((_, r)) = RANGES.iter().find(|(k, _)| *k == suffix) {
            return Some(*r);
        }
        suffix = &suffix[suffix.find('.')? + 1..];
    }
}

/// A bound as written in messages: `1e10`, `-3600`, `0.5`.
pub(super) fn number(x: f64) -> String {
    if x != 0.0 && !(1e-3..1e5).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Integer keys, bounded by their own checks (counts) or without a physical range (a seed).
    const INTEGER_KEYS: &[&str] = &["elements", "order", "components", "seed", "segments"];

    /// The table of ranges as markdown (docs/scenario.md holds it; a test keeps it up to date).
    fn markdown_table() -> String {
        let mut out = String::from("| key | unit | from | to |\n|---|---|---|---|\n");
        for (key, range) in RANGES {
            let columns = match range {
                Range::All(b) => vec![*b],
                Range::Columns(c) => c.to_vec(),
            };
            let many = columns.len() > 1;
            for (j, b) in columns.iter().enumerate() {
                if many && j > 0 && columns[j - 1] == *b {
                    continue;
                }
                let name = match many {
                    true => format!("`{key}` (column {})", j + 1),
                    false => format!("`{key}`"),
                };
                out += &format!(
                    "| {name} | {} | {} | {} |\n",
                    b.unit,
                    number(b.min),
                    number(b.max)
                );
            }
        }
        out
    }

    /// Every numeric leaf of the JSON Schema as an index-free path (`points[].mass`); arrays
    /// of numbers are their key (`current.profile`), arrays of tables add `[]`.
    fn numeric_leaves() -> Vec<String> {
        let schema =
            serde_json::to_value(schemars::schema_for!(crate::scenario::schema::Scenario)).unwrap();
        let defs = schema["$defs"].clone();
        let mut out = Vec::new();
        fn walk(
            v: &serde_json::Value,
            defs: &serde_json::Value,
            path: &str,
            out: &mut Vec<String>,
        ) {
            if path.matches(".mean").count() > 1 {
                return;
            }
            let v = match v.get("$ref").and_then(|r| r.as_str()) {
                Some(r) => &defs[r.trim_start_matches("#/$defs/")],
                None => v,
            };
            for key in ["anyOf", "oneOf"] {
                for alt in v.get(key).and_then(|a| a.as_array()).into_iter().flatten() {
                    walk(alt, defs, path, out);
                }
            }
            let kinds: Vec<&str> = match v.get("type") {
                Some(serde_json::Value::String(s)) => vec![s.as_str()],
                Some(serde_json::Value::Array(a)) => a.iter().filter_map(|x| x.as_str()).collect(),
                _ => vec![],
            };
            for kind in kinds {
                match kind {
                    "object" => {
                        for (k, p) in v
                            .get("properties")
                            .and_then(|p| p.as_object())
                            .into_iter()
                            .flatten()
                        {
                            let sub = if path.is_empty() {
                                k.clone()
                            } else {
                                format!("{path}.{k}")
                            };
                            walk(p, defs, &sub, out);
                        }
                    }
                    "array" => {
                        let items = v
                            .get("items")
                            .or_else(|| v.get("prefixItems").and_then(|p| p.get(0)));
                        if let Some(items) = items {
                            let resolved = match items.get("$ref").and_then(|r| r.as_str()) {
                                Some(r) => &defs[r.trim_start_matches("#/$defs/")],
                                None => items,
                            };
                            let tables = resolved.get("properties").is_some();
                            walk(
                                items,
                                defs,
                                &(path.to_string() + if tables { "[]" } else { "" }),
                                out,
                            );
                        }
                    }
                    "number" | "integer" if !out.contains(&path.to_string()) => {
                        out.push(path.to_string());
                    }
                    _ => {}
                }
            }
        }
        walk(&schema, &defs, "", &mut out);
        out
    }

    /// Every number a scenario can hold has a physical range (or is an integer with its own
    /// check): a key added without one fails here.
    #[test]
    fn every_numeric_key_has_a_range() {
        let leaves = numeric_leaves();
        assert!(leaves.len() > 100, "{leaves:?}");
        let missing: Vec<&String> = leaves
            .iter()
            .filter(|k| {
                let leaf = k.rsplit('.').next().unwrap_or(k);
                range_of(k).is_none() && !INTEGER_KEYS.contains(&leaf)
            })
            .collect();
        assert!(
            missing.is_empty(),
            "numeric keys without a physical range: {missing:?}"
        );
        // And every range serves a key of the schema (no stale entries).
        for (suffix, _) in RANGES {
            // Files of rows are string keys in the schema.
            let used = ["motion.file", "waves.elevation_file", "seabed.grid"].contains(suffix)
                || leaves
                    .iter()
                    .any(|k| k == suffix || k.ends_with(&format!(".{suffix}")));
            assert!(used, "`{suffix}` names no key of the schema");
        }
    }

    #[test]
    fn keys_resolve_by_their_longest_suffix() {
        assert_eq!(range_of("points[3].mass"), range_of("bodies[0].mass"));
        assert_eq!(
            range_of("points[0].motion.mean.speed"),
            range_of("points[1].motion.speed")
        );
        let seabed = range_of("environment.seabed.damping").unwrap().bounds(0);
        assert_eq!(seabed.unit, "Pa·s/m");
        assert_eq!(
            range_of("obstacles[2].damping").unwrap().bounds(0).unit,
            "N·s/m²"
        );
        assert_eq!(
            range_of("line_types[0].tension_strain")
                .unwrap()
                .bounds(3)
                .unit,
            "N"
        );
        assert_eq!(range_of("lines[0].name"), None);
        assert_eq!(number(1e10), "1e10");
        assert_eq!(number(-3600.0), "-3600");
        assert_eq!(number(0.0), "0");
    }

    /// docs/scenario.md lists the ranges as the code has them.
    #[test]
    fn the_documented_ranges_are_the_code() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/scenario.md");
        let doc = std::fs::read_to_string(path).unwrap();
        assert!(
            doc.contains(&markdown_table()),
            "docs/scenario.md lacks the current table of physical ranges:\n{}",
            markdown_table()
        );
    }
}
