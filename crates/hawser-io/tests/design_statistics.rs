//! The design statistics and range graphs a run writes, end to end: a fairlead moving as a
//! sinusoid of known amplitude and period gives its channel's statistics in closed form in
//! `summary.json`; the statistics of the other channels equal those computed in memory from
//! the time series read back (the writer reads its file twice, `hawser plot` once); the
//! range graph's largest tension at end A is the largest end A tension; the strength check
//! uses it.

use hawser::analysis::statistics::statistics_of;
use hawser_io::run_files::read_timeseries;

/// A 60 m wire hanging from a fairlead that surges 2 m at an 8 s period, ramped in over 8 s;
/// statistics from t = 8 s over 4 whole periods (t = 8 … 40 s, sampled every 0.1 s).
const SCENARIO: &str = r#"
[simulation]
duration = 40.0
output_interval = 0.1
snapshot_interval = 4.0

[statistics]
start = 8.0
storm_duration = 3600.0
linked_channels = ["fairlead.x"]

[[line_types]]
name = "wire"
diameter = 0.02
mass_per_length = 2.0
axial_stiffness = 2.0e7
normal_drag = 1.2
tangential_drag = 0.01
minimum_breaking_load = 4.0e5
design_safety_factor = 2.5

[[points]]
name = "fairlead"
type = "prescribed"
position = [0.0, 0.0, -5.0]
motion = { type = "sinusoid", amplitude = [2.0, 0.0, 0.0], period = 8.0, ramp_time = 8.0 }

[[points]]
name = "weight"
type = "free"
position = [0.0, 0.0, -65.0]
mass = 200.0
volume = 0.02

[[lines]]
name = "wire"
end_a = "fairlead"
end_b = "weight"
type = "wire"
length = 60.0
elements = 6
"#;

#[test]
fn summary_statistics_of_a_sinusoid_and_the_range_graph() {
    let dir = std::env::temp_dir().join(format!("hawser_design_stats_{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("wire.toml");
    let loaded = hawser_io::scenario::parse(&file, SCENARIO).unwrap();
    let mut session = hawser::Session::new(loaded.model.clone()).unwrap();
    let writer = hawser_io::results::RunWriter::create(
        &dir,
        &session,
        &file,
        // CSV and JSON only, whatever the build's features.
        &hawser_io::scenario::OutputFormats {
            parquet: false,
            vtk: false,
        },
        &loaded.statistics,
    )
    .unwrap();
    session.attach(writer);
    let result = session.run();
    session.finish(result.as_ref().err()).unwrap();
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    let x = &summary["channels"]["fairlead.x"];
    // Samples at t = 8.0, 8.1, … 40.0: 321, covering 4 periods plus one sample at phase 0
    // (x = 0), so Σx² = a²/2 · 320 and σ = a √(160/321). The motion is evaluated at the
    // solver's clock, which carries the round-off of k · 0.1 (the time column, from the sample
    // counter, does not), so values at phase 0 are ~1e-15 m, not 0.
    let a: f64 = 2.0;
    assert_eq!(x["samples"].as_u64(), Some(321));
    let std = x["std"].as_f64().unwrap();
    assert!(
        (std - a * (160.0f64 / 321.0).sqrt()).abs() < 1e-12,
        "σ {std}"
    );
    assert!(x["mean"].as_f64().unwrap().abs() < 1e-12);
    // Crossings at 8, 16, 24, 32 s (and maybe 40 s, within round-off of the last sample):
    // T_z = 8 s to the round-off of the interpolated crossing times.
    let tz = x["zero_up_crossing_period"].as_f64().unwrap();
    assert!((tz - 8.0).abs() < 1e-9, "T_z {tz}");
    let mpm = x["most_probable_maximum"].as_f64().unwrap();
    let mean = x["mean"].as_f64().unwrap();
    assert!((mpm - (mean + std * (2.0 * (3600.0f64 / tz).ln()).sqrt())).abs() < 1e-12);
    // The maximum a at t = 10, 18, 26, 34 s: the first one, with itself as linked value.
    assert!((x["max"].as_f64().unwrap() - a).abs() < 1e-12);
    assert!((x["time_of_max"].as_f64().unwrap() - 10.0).abs() < 1e-9);
    assert_eq!(x["linked"]["at_max"]["fairlead.x"], x["max"]);
    assert_eq!(summary["statistics"]["start"].as_f64(), Some(8.0));
    assert_eq!(
        summary["statistics"]["linked_channels"][0].as_str(),
        Some("fairlead.x")
    );

    // Every channel: the same numbers as in memory from the file read back (to 1 ulp:
    // serde_json's default float parser may miss the last bit).
    let same = |j: Option<f64>, x: Option<f64>| match (j, x) {
        (Some(j), Some(x)) => (j - x).abs() <= 2.0 * f64::EPSILON * x.abs(),
        (j, x) => j == x,
    };
    let ts = read_timeseries(&dir).unwrap();
    let columns: Vec<&[f64]> = ts.values.iter().map(|v| v.as_slice()).collect();
    let stats = statistics_of(&ts.time, &columns, loaded.statistics.clone());
    for (c, s) in ts.channels.iter().zip(&stats) {
        let j = &summary["channels"][&c.name];
        assert!(same(j["max"].as_f64(), Some(s.max)), "{}", c.name);
        assert!(same(j["std"].as_f64(), Some(s.std)), "{}", c.name);
        assert!(
            same(
                j["zero_up_crossing_period"].as_f64(),
                s.zero_up_crossing_period
            ),
            "{}",
            c.name
        );
        assert_eq!(j["unit"].as_str(), Some(c.unit.as_str()));
    }

    // The range graph over the same window: node 0's largest tension is the largest end A
    // tension (the same quantity, the same samples), and the strength check reports it.
    let ranges: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("line_ranges.json")).unwrap())
            .unwrap();
    let wire = &ranges["lines"]["wire"];
    assert_eq!(wire["samples"].as_u64(), Some(321));
    let top = summary["channels"]["wire.end_a.tension"]["max"]
        .as_f64()
        .unwrap();
    assert_eq!(wire["max"][0].as_f64(), Some(top));
    let worst = &summary["lines"]["wire"]["strength"]["worst"];
    assert_eq!(worst["max_tension"].as_f64(), Some(top));
    assert_eq!(worst["at"].as_f64(), Some(0.0));
    assert_eq!(
        worst["design_utilisation"].as_f64(),
        Some(top / (4.0e5 / 2.5))
    );
    assert_eq!(
        wire["sections"][0]["permissible_tension"].as_f64(),
        Some(4.0e5 / 2.5)
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
