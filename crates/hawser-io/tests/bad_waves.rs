//! `[environment.waves]`: a valid sea reads into the same waves the core builds from the same
//! numbers, and every bad value gets a diagnostic naming the file, line and column, the key,
//! the value, the expected unit or range and a hint, never a panic (as in `bad_input.rs`).

use hawser::physics::waves::{
    IrregularSea, RegularWave, SeaState, Spectrum, Stretching, WaveSpec, Waves,
};
mod common;
use common::*;
use hawser_io::scenario;
use std::f64::consts::PI;
use std::path::Path;

/// A riser in an irregular sea with every wave key given.
const BASE: &str = r#"# Base scenario for the wave input tests.

[simulation]
duration = 10.0

[environment]
depth = 60.0

[environment.waves]
type = "jonswap"
significant_height = 3.0
peak_period = 9.0
gamma = 2.5
direction = 30.0
spreading = 6.0
seed = 42
components = 150
frequency_range = [0.06, 0.5]
ramp_time = 20.0
stretching = "vertical"

[[line_types]]
name = "riser"
diameter = 0.2
mass_per_length = 60.0
axial_stiffness = 5.0e8
normal_drag = 1.2
tangential_drag = 0.0

[[points]]
name = "anchor"
type = "fixed"
position = [0.0, 0.0, -60.0]

[[points]]
name = "top"
type = "fixed"
position = [0.0, 0.0, -5.0]

[[lines]]
name = "riser"
end_a = "anchor"
end_b = "top"
type = "riser"
length = 54.9
elements = 10
"#;

/// The regular-wave table that replaces the irregular one.
const REGULAR: &str = r#"[environment.waves]
type = "regular"
height = 4.0
period = 8.0
direction = -45.0
"#;

/// The irregular waves table of `BASE`.
fn irregular_table() -> &'static str {
    let start = BASE.find("[environment.waves]").unwrap();
    let end = BASE.find("[[line_types]]").unwrap();
    &BASE[start..end]
}

/// `BASE` with the regular waves table.
fn regular_base() -> String {
    BASE.replacen(irregular_table(), &format!("{REGULAR}\n"), 1)
}

/// `text` with the first occurrence of `from` replaced by `to` (which must exist).
fn mutate(from: &str, to: &str) -> String {
    replaced(BASE, from, to)
}

#[test]
fn irregular_sea_reads_as_the_core_builds_it() {
    let s = scenario::parse(Path::new(FILE), BASE).expect("the base scenario is valid");
    let expect = Waves::new(
        &WaveSpec {
            sea: SeaState::Irregular(IrregularSea {
                spectrum: Spectrum::Jonswap {
                    significant_height: 3.0,
                    peak_period: 9.0,
                    peak_enhancement: 2.5,
                },
                direction: 30f64.to_radians(),
                spreading: Some(6.0),
                seed: 42,
                components: 150,
                frequency_range: (2.0 * PI * 0.06, 2.0 * PI * 0.5),
            }),
            ramp_time: 20.0,
            stretching: Stretching::Vertical,
        },
        60.0,
        9.80665,
    )
    .unwrap();
    assert_eq!(s.model.environment.waves, expect);
}

/// Defaults: γ 3.3, direction 0, seed 1, 200 components from 0.5 to 5 times 1/Tp, a ramp of
/// two peak periods, Wheeler stretching; a Pierson–Moskowitz sea likewise.
#[test]
fn irregular_defaults() {
    let minimal =
        "[environment.waves]\ntype = \"jonswap\"\nsignificant_height = 3.0\npeak_period = 9.0\n\n";
    let text = BASE.replacen(irregular_table(), minimal, 1);
    let s = scenario::parse(Path::new(FILE), &text).unwrap();
    let wp = 2.0 * PI / 9.0;
    let sea = |spectrum| WaveSpec {
        sea: SeaState::Irregular(IrregularSea {
            spectrum,
            direction: 0.0,
            spreading: None,
            seed: 1,
            components: 200,
            frequency_range: (0.5 * wp, 5.0 * wp),
        }),
        ramp_time: 18.0,
        stretching: Stretching::Wheeler,
    };
    let field = s.model.environment.waves.field().unwrap();
    let want = sea(Spectrum::Jonswap {
        significant_height: 3.0,
        peak_period: 9.0,
        peak_enhancement: 3.3,
    });
    // The default range is computed through Hz: equal to rounding.
    let SeaState::Irregular(got) = &field.spec().sea else {
        panic!()
    };
    let SeaState::Irregular(w) = &want.sea else {
        panic!()
    };
    assert!((got.frequency_range.0 - w.frequency_range.0).abs() < 1e-15);
    assert!((got.frequency_range.1 - w.frequency_range.1).abs() < 1e-14);
    assert_eq!(got.spectrum, w.spectrum);
    assert_eq!(
        (got.direction, got.spreading, got.seed, got.components),
        (0.0, None, 1, 200)
    );
    assert_eq!(field.spec().ramp_time, 18.0);
    assert_eq!(field.spec().stretching, Stretching::Wheeler);
    let pm = text.replacen("\"jonswap\"", "\"pierson-moskowitz\"", 1);
    let s = scenario::parse(Path::new(FILE), &pm).unwrap();
    let SeaState::Irregular(got) = &s.model.environment.waves.field().unwrap().spec().sea else {
        panic!()
    };
    assert_eq!(
        got.spectrum,
        Spectrum::PiersonMoskowitz {
            significant_height: 3.0,
            peak_period: 9.0
        }
    );
}

#[test]
fn regular_wave_reads_with_its_defaults() {
    let s = scenario::parse(Path::new(FILE), &regular_base()).expect("valid");
    let expect = Waves::new(
        &WaveSpec {
            sea: SeaState::Regular(RegularWave {
                height: 4.0,
                period: 8.0,
                direction: (-45f64).to_radians(),
            }),
            ramp_time: 16.0,
            stretching: Stretching::Wheeler,
        },
        60.0,
        9.80665,
    )
    .unwrap();
    assert_eq!(s.model.environment.waves, expect);
    // No table: a calm sea.
    let calm = BASE.replacen(irregular_table(), "", 1);
    let s = scenario::parse(Path::new(FILE), &calm).unwrap();
    assert!(s.model.environment.waves.is_none());
}

#[test]
fn negative_significant_height() {
    let text = mutate("significant_height = 3.0", "significant_height = -3.0");
    let msg = bad(
        &text,
        "significant_height",
        "environment.waves.significant_height",
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn zero_peak_period() {
    let text = mutate("peak_period = 9.0", "peak_period = 0.0");
    let msg = bad(&text, "peak_period", "environment.waves.peak_period");
    insta::assert_snapshot!(msg);
}

#[test]
fn gamma_below_one() {
    let text = mutate("gamma = 2.5", "gamma = 0.5");
    let msg = bad(&text, "gamma", "environment.waves.gamma");
    insta::assert_snapshot!(msg);
}

#[test]
fn non_finite_direction() {
    let text = mutate("direction = 30.0", "direction = nan");
    let msg = bad(&text, "direction", "environment.waves.direction");
    insta::assert_snapshot!(msg);
}

#[test]
fn negative_spreading() {
    let text = mutate("spreading = 6.0", "spreading = -2.0");
    let msg = bad(&text, "spreading", "environment.waves.spreading");
    insta::assert_snapshot!(msg);
}

#[test]
fn zero_components() {
    let text = mutate("components = 150", "components = 0");
    let msg = bad(&text, "components", "environment.waves.components");
    insta::assert_snapshot!(msg);
}

#[test]
fn too_many_components() {
    let text = mutate("components = 150", "components = 10000000");
    let msg = bad(&text, "components", "environment.waves.components");
    insta::assert_snapshot!(msg);
}

#[test]
fn fractional_components() {
    let text = mutate("components = 150", "components = 150.5");
    let msg = bad(&text, "components", "environment.waves.components");
    insta::assert_snapshot!(msg);
}

#[test]
fn fractional_seed() {
    let text = mutate("seed = 42", "seed = 4.2");
    let msg = bad(&text, "seed", "environment.waves.seed");
    insta::assert_snapshot!(msg);
}

#[test]
fn decreasing_frequency_range() {
    let text = mutate(
        "frequency_range = [0.06, 0.5]",
        "frequency_range = [0.5, 0.06]",
    );
    let msg = bad(
        &text,
        "frequency_range",
        "environment.waves.frequency_range",
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn zero_frequency() {
    let text = mutate(
        "frequency_range = [0.06, 0.5]",
        "frequency_range = [0.0, 0.5]",
    );
    let msg = bad(
        &text,
        "frequency_range",
        "environment.waves.frequency_range",
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn negative_ramp_time() {
    let text = mutate("ramp_time = 20.0", "ramp_time = -1.0");
    let msg = bad(&text, "ramp_time", "environment.waves.ramp_time");
    insta::assert_snapshot!(msg);
}

#[test]
fn unknown_wave_type() {
    let text = mutate("type = \"jonswap\"", "type = \"jonswop\"");
    let msg = bad(&text, "jonswop", "environment.waves.type");
    insta::assert_snapshot!(msg);
}

#[test]
fn unknown_stretching() {
    let text = mutate("stretching = \"vertical\"", "stretching = \"linear\"");
    let msg = bad(&text, "stretching", "environment.waves.stretching");
    insta::assert_snapshot!(msg);
}

#[test]
fn misspelt_wave_key() {
    let text = mutate("peak_period = 9.0", "peak_perod = 9.0");
    let msg = bad(&text, "peak_perod", "environment.waves.peak_perod");
    assert!(msg.contains("did you mean `peak_period`"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn irregular_sea_without_significant_height() {
    let text = mutate("significant_height = 3.0\n", "");
    let msg = bad(
        &text,
        "type = \"jonswap\"",
        "environment.waves.significant_height",
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn height_on_an_irregular_sea() {
    let text = mutate("gamma = 2.5", "gamma = 2.5\nheight = 3.0");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "\nheight = 3.0") + 1,
        "environment.waves.height",
        true,
        false,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn gamma_on_a_pierson_moskowitz_sea() {
    let text = mutate("type = \"jonswap\"", "type = \"pierson-moskowitz\"");
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "gamma"),
        "environment.waves.gamma",
        true,
        false,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn regular_wave_without_period() {
    let text = replaced(&regular_base(), "period = 8.0\n", "");
    let msg = bad(&text, "type = \"regular\"", "environment.waves.period");
    insta::assert_snapshot!(msg);
}

#[test]
fn negative_wave_height() {
    let text = replaced(&regular_base(), "height = 4.0", "height = -4.0");
    let msg = bad(&text, "height", "environment.waves.height");
    insta::assert_snapshot!(msg);
}

/// A 16 m, 8 s wave in 60 m of water is steeper than Miche's limit H ≤ 0.142 L tanh kh
/// (L = 99.7 m, kh = 3.8: 14.1 m).
#[test]
fn breaking_wave() {
    let text = replaced(&regular_base(), "height = 4.0", "height = 16.0");
    let msg = bad(&text, "height", "environment.waves.height");
    assert!(msg.contains("breaks"), "{msg}");
    insta::assert_snapshot!(msg);
}

#[test]
fn seed_on_a_regular_wave() {
    let text = replaced(
        &regular_base(),
        "direction = -45.0",
        "direction = -45.0\nseed = 3",
    );
    let msg = error(&text);
    assert_located(
        &msg,
        line_of(&text, "seed"),
        "environment.waves.seed",
        true,
        false,
    );
    insta::assert_snapshot!(msg);
}

#[test]
fn waves_without_gravity() {
    let text = mutate("depth = 60.0", "depth = 60.0\ngravity = 0.0");
    let msg = bad(&text, "type = \"jonswap\"", "environment.gravity");
    insta::assert_snapshot!(msg);
}

/// Every line of the wave tables replaced by extreme and ill-typed values: no panic.
#[test]
fn never_panics_on_bad_wave_values() {
    let values = [
        "nan",
        "inf",
        "-inf",
        "0",
        "-0.0",
        "-1",
        "1e308",
        "-1e308",
        "9223372036854775807",
        "-9223372036854775808",
        "\"\"",
        "\"regular\"",
        "[]",
        "[0.0]",
        "[1e308, inf]",
        "[1e-300, 1e-299]",
        "{}",
        "true",
    ];
    let mut bad = Vec::new();
    for base in [BASE.to_string(), regular_base()] {
        let lines: Vec<&str> = base.lines().collect();
        let start = line_of(&base, "[environment.waves]");
        let end = line_of(&base, "[[line_types]]");
        for i in start..end - 1 {
            let Some((key, _)) = lines[i].split_once(" = ") else {
                continue;
            };
            for v in values {
                let mut l = lines.clone();
                let g = format!("{key} = {v}");
                l[i] = &g;
                if panics(&l.join("\n")) {
                    bad.push(format!("line {}: {g}", i + 1));
                }
            }
        }
    }
    assert!(bad.is_empty(), "panics: {bad:?}");
}

/// `kinematics = "static-position"` and its `sample_interval` read into the environment; a bad
/// interval, an interval without the method, and bad keys of an elevation record or a current
/// table are located, with the key, the expected range and a hint.
#[test]
fn static_position_record_and_current_table_keys() {
    use hawser::physics::static_kinematics::WaveKinematicsMethod;
    let text = replaced(
        BASE,
        "stretching = \"vertical\"",
        "stretching = \"vertical\"\nkinematics = \"static-position\"\nsample_interval = 0.05",
    );
    let s = scenario::parse(Path::new(FILE), &text).unwrap();
    assert_eq!(
        s.model.environment.wave_kinematics,
        WaveKinematicsMethod::StaticPosition {
            sample_interval: 0.05
        }
    );
    bad(
        &replaced(&text, "sample_interval = 0.05", "sample_interval = -1.0"),
        "sample_interval",
        "environment.waves.sample_interval",
    );
    let msg = error(&replaced(
        BASE,
        "stretching = \"vertical\"",
        "stretching = \"vertical\"\nsample_interval = 0.05",
    ));
    assert!(
        msg.contains("environment.waves.sample_interval") && msg.contains("hint"),
        "{msg}"
    );
    // An elevation record: record keys misplaced on a spectral sea; spectral keys on a record;
    // a record that does not increase.
    let msg = error(&replaced(
        BASE,
        "ramp_time = 20.0",
        "ramp_time = 20.0\ncutoff_frequency = 0.5",
    ));
    assert!(msg.contains("environment.waves.cutoff_frequency"), "{msg}");
    let record = replaced(
        BASE,
        "type = \"jonswap\"\nsignificant_height = 3.0\npeak_period = 9.0\ngamma = 2.5\n",
        "type = \"elevation-record\"\nelevation = [[0.0, 0.0], [1.0, 0.5], [0.5, 0.2], [2.0, 0.0], [3.0, -0.4]]\n",
    );
    let msg = error(&record);
    assert!(msg.contains("environment.waves.spreading"), "{msg}");
    let record = replaced(
        &replaced(
            &record,
            "spreading = 6.0\nseed = 42\ncomponents = 150\nfrequency_range = [0.06, 0.5]\n",
            "",
        ),
        "elevation = [[0.0",
        "elevation = [[0.0",
    );
    bad(&record, "elevation =", "environment.waves.elevation");
    // A current table whose rows do not match its heights.
    let table = replaced(
        BASE,
        "[environment.waves]",
        "[environment.current]\ntype = \"profile-table\"\nz = [-60.0, 0.0]\ntimes = [0.0, 10.0]\nux = [[0.0, 0.1], [0.2]]\n\n[environment.waves]",
    );
    let msg = error(&table);
    assert_located(
        &msg,
        line_of(&table, "ux = "),
        "environment.current.ux",
        false,
        true,
    );
    let table = replaced(&table, "times = [0.0, 10.0]", "times = [10.0, 0.0]");
    bad(&table, "times = ", "environment.current.times");
    assert!(!panics(&table) && !panics(&record));
}
