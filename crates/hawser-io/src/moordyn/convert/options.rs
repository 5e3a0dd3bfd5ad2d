//! OPTIONS: the option rows (used, noted, unknown), the environment they describe (water,
//! seabed, current profile) and the simulation settings.

use super::{Converter, spanned};
use crate::moordyn::deck::{Row, Token};
use crate::scenario::diagnostics::closest;
use crate::scenario::schema::*;
use crate::scenario::tables::{parse_number, read_current_profile};
use std::ops::Range;
use std::path::Path;
use toml::Spanned;

/// The OPTIONS rows by lower-case name: (value token, row).
pub(super) struct Options<'r> {
    rows: Vec<(String, &'r Token, &'r Row)>,
}

impl<'r> Options<'r> {
    pub(super) fn get(&self, names: &[&str]) -> Option<(&'r Token, &'r Row)> {
        self.rows
            .iter()
            .rev()
            .find(|(n, _, _)| names.contains(&n.as_str()))
            .map(|(_, t, r)| (*t, *r))
    }
}

/// Options hawser reads, with their MoorDyn-C 2.7 spellings (lower case).
const USED_OPTIONS: &[&str] = &[
    "dtm",
    "dt",
    "cfl",
    "tscheme",
    "g",
    "gravity",
    "rho",
    "wtrdnsty",
    "wtrdpth",
    "depth",
    "kbot",
    "kb",
    "cbot",
    "cb",
    "frictioncoefficient",
    "fricdamp",
    "statdynfricscale",
    "dtout",
    "wavekin",
    "dtwave",
    "currents",
    "seafloorfile",
];

/// Options read but without effect in hawser, and the note that follows the option's name.
const NOTED_OPTIONS: &[(&[&str], &str)] = &[
    (
        &[
            "dtic",
            "icdt",
            "tmaxic",
            "ictmax",
            "cdscaleic",
            "icdfac",
            "threshic",
            "icthresh",
            "icgendynamic",
            "gendynamicic",
        ],
        " (initial-condition control) is not used: hawser starts from its Newton static \
         equilibrium, the state MoorDyn's initial-condition solver approximates",
    ),
    (
        &["fileic", "icfile", "inputic"],
        " (initial-condition file) is not used: hawser starts from its Newton static \
         equilibrium, the state MoorDyn's initial-condition solver approximates",
    ),
    (
        &["writelog"],
        " has no effect: hawser reports on the terminal",
    ),
    (
        &["writeunits"],
        " has no effect: hawser's column headers always carry units",
    ),
    (
        &["disableoutput", "disableouttime"],
        " has no effect: hawser always writes its results and reports progress",
    ),
    (
        &["echo"],
        " has no effect: hawser prints conversion notes instead",
    ),
    (
        &["wavekin_rampt"],
        " has no effect: MoorDyn 2.7 does not read it (hawser ramps its waves up by its own \
         `ramp_time`)",
    ),
    (
        &["unifycurrentgrid"],
        " has no effect: the current profile is used as given",
    ),
];

/// Every option name hawser knows.
fn known_options() -> impl Iterator<Item = &'static str> {
    USED_OPTIONS.iter().copied().chain(
        NOTED_OPTIONS
            .iter()
            .flat_map(|(names, _)| names.iter().copied()),
    )
}

pub(super) fn read_options<'r>(c: &mut Converter, rows: &'r [Row]) -> Options<'r> {
    let mut out = Options { rows: Vec::new() };
    for row in rows {
        let Some(value) = row.tokens.first() else {
            continue;
        };
        let Some(name) = row.tokens.get(1) else {
            let d = c
                .diag(
                    Some(value.span.clone()),
                    "OPTIONS",
                    "an option row needs a value and a name",
                )
                .expected("`value name [description]`, e.g. `0.002 dtM`");
            c.errors.push(d);
            continue;
        };
        let lower = name.text.to_lowercase();
        if !known_options().any(|k| k == lower) {
            let hint = match closest(&lower, known_options()) {
                Some(k) => format!("did you mean `{k}`? (option names are case-insensitive here)"),
                None => "MoorDyn would ignore it too; remove it, or check the spelling".to_string(),
            };
            c.note(
                row.line,
                format!("unknown option `{}` is ignored ({hint})", name.text),
            );
            continue;
        }
        out.rows.push((lower, value, row));
    }
    out
}

pub(super) fn environment_of(
    c: &mut Converter,
    o: &Options,
    dir: &Path,
    points: &[PointSpec],
) -> EnvironmentSpec {
    let num = |c: &mut Converter, names: &[&str], unit: &str| -> Option<Spanned<f64>> {
        let (t, row) = o.get(names)?;
        let name = row.tokens[1].text.clone();
        c.number(t, "OPTIONS", &name, unit).map(|x| spanned(t, x))
    };
    let gravity = num(c, &["g", "gravity"], "m/s²");
    let water_density = num(c, &["rho", "wtrdnsty"], "kg/m³");
    let mut depth = num(c, &["wtrdpth", "depth"], "m");
    // MoorDyn: the depth is at least that of the deepest point (0 when not given).
    let deepest = points
        .iter()
        .filter_map(|p| p.position.as_ref())
        .map(|x| (-x.get_ref()[2], x.span()))
        .fold(None, |m: Option<(f64, Range<usize>)>, (d, s)| match m {
            Some((md, _)) if md >= d => m,
            _ => Some((d, s)),
        });
    if let Some((d, span)) = deepest
        && d > 0.0
        && depth.as_ref().is_none_or(|x| *x.get_ref() < d)
    {
        let line = c.line_of(&span);
        c.note(
            line,
            match &depth {
                Some(x) => format!(
                    "WtrDpth {} is above the deepest point: the seabed is lowered to z = −{d} m, as MoorDyn does",
                    x.get_ref()
                ),
                None => format!(
                    "no WtrDpth: the seabed is at the deepest point, z = −{d} m, as in MoorDyn"
                ),
            },
        );
        depth = Some(Spanned::new(span, d));
    }
    let kbot = num(c, &["kbot", "kb"], "Pa/m");
    let cbot = num(c, &["cbot", "cb"], "Pa·s/m");
    let mu = num(c, &["frictioncoefficient"], "-");
    for (k, v) in [
        ("environment.gravity", "g"),
        ("environment.water_density", "WtrDnsty"),
        ("environment.depth", "WtrDpth"),
        ("environment.seabed.stiffness", "kBot"),
        ("environment.seabed.damping", "cBot"),
        (
            "environment.seabed.friction_coefficient",
            "FrictionCoefficient",
        ),
    ] {
        c.name_key(k.to_string(), format!("OPTIONS › {v}"));
    }
    let friction_damping = num(c, &["fricdamp"], "N·s/m");
    let static_friction_scale = num(c, &["statdynfricscale"], "-");
    c.name_key(
        "environment.seabed.friction_damping".into(),
        "OPTIONS › FricDamp".into(),
    );
    c.name_key(
        "environment.seabed.static_friction_scale".into(),
        "OPTIONS › StatDynFricScale".into(),
    );
    // MoorDyn's friction law is always its own: FricDamp defaults to 200 N·s/m.
    let friction = mu.as_ref().filter(|m| *m.get_ref() > 0.0).map(|m| {
        let anchor = Token {
            text: String::new(),
            span: m.span(),
        };
        (
            friction_damping.unwrap_or_else(|| spanned(&anchor, 200.0)),
            static_friction_scale,
        )
    });
    let waves = super::water::waves_of(c, o, dir);
    if let Some((t, _)) = o.get(&["seafloorfile"]) {
        let d = c
            .diag(
                Some(t.span.clone()),
                "OPTIONS › SeafloorFile",
                "bathymetry files are not supported",
            )
            .expected("a flat seabed at WtrDpth")
            .hint("remove SeafloorFile to run on a flat bed at WtrDpth");
        c.errors.push(d);
    }
    let current = match o.get(&["currents"]) {
        Some((t, row)) => {
            match parse_number(&t.text) {
                Some(0.0) => None,
                Some(1.0) => current_profile(c, t, row, dir),
                Some(2.0) => super::water::dynamic_current(c, t, row, dir),
                _ => {
                    let d = c
                    .diag(
                        Some(t.span.clone()),
                        "OPTIONS › Currents",
                        format!("Currents mode `{}` is not supported", t.text),
                    )
                    .expected(
                        "0 (none), 1 (steady profile from current_profile.txt) or 2 (profiles \
                         against time from current_profile_dynamic.txt)",
                    )
                    .hint("MoorDyn's node-approach and 4D gridded currents are not read: use 1 or 2");
                    c.errors.push(d);
                    None
                }
            }
        }
        None => None,
    };
    let seabed = depth.as_ref().map(|_| SeabedSpec {
        stiffness: kbot,
        damping_ratio: None,
        damping: cbot,
        friction_coefficient: mu,
        friction_velocity: None,
        friction_damping: friction.as_ref().map(|f| f.0.clone()),
        static_friction_scale: friction.and_then(|f| f.1),
    });
    EnvironmentSpec {
        gravity,
        water_density,
        air_density: None,
        depth,
        seabed,
        current,
        waves,
    }
}

/// `Currents 1`: a steady profile from `current_profile.txt` beside the deck (MoorDyn reads
/// it from the deck's folder): rows `z ux uy uz` after three header lines.
fn current_profile(c: &mut Converter, t: &Token, row: &Row, dir: &Path) -> Option<CurrentSpec> {
    let path = dir.join("current_profile.txt");
    let mut rows = match read_current_profile(&path) {
        Ok(rows) => rows,
        Err(e) => {
            let d = c
                .diag(
                    Some(t.span.clone()),
                    "OPTIONS › Currents",
                    format!("Currents 1 needs {}: {e}", path.display()),
                )
                .expected("current_profile.txt beside the deck: rows `z ux uy uz` [m, m/s]")
                .hint("put the profile file next to the deck, or set Currents to 0");
            c.errors.push(d);
            return None;
        }
    };
    rows.sort_by(|a, b| a[0].total_cmp(&b[0]));
    c.note(
        row.line,
        format!(
            "Currents 1: {} depths read from {}",
            rows.len(),
            path.display()
        ),
    );
    Some(CurrentSpec {
        kind: spanned(t, CurrentKind::Profile),
        velocity: None,
        profile: Some(spanned(t, rows)),
        z: None,
        times: None,
        ux: None,
        uy: None,
        uz: None,
    })
}

pub(super) fn simulation_of(
    c: &mut Converter,
    o: &Options,
    duration: Option<f64>,
    vessel_end: Option<f64>,
    channels: Vec<Spanned<String>>,
    line_outputs: bool,
    coupled: usize,
) -> SimulationSpec {
    let mut time_step = None;
    if let Some((t, row)) = o.get(&["dtm", "dt"])
        && let Some(x) = c.number(t, "OPTIONS", &row.tokens[1].text, "s")
    {
        time_step = Some(spanned(t, TimeStepSpec::Value(x)));
        c.name_key("simulation.time_step".into(), "OPTIONS › dtM".into());
    }
    if let Some((t, row)) = o.get(&["cfl"]) {
        c.note(
            row.line,
            format!(
                "CFL {}: hawser takes its time step from its own stability bound{}",
                t.text,
                if time_step.is_some() {
                    " only where dtM exceeds it"
                } else {
                    " (time_step = \"auto\")"
                }
            ),
        );
    }
    if let Some((t, row)) = o.get(&["tscheme"]) {
        if t.text.eq_ignore_ascii_case("rk4") {
        } else {
            c.note(
                row.line,
                format!(
                    "tScheme {}: hawser integrates with RK4 (fourth order; it needs no smaller \
                     step than MoorDyn's schemes)",
                    t.text
                ),
            );
        }
    }
    let mut output_interval = None;
    if let Some((t, row)) = o.get(&["dtout"])
        && let Some(x) = c.number(t, "OPTIONS", &row.tokens[1].text, "s")
    {
        if x > 0.0 {
            output_interval = Some(spanned(t, x));
            c.name_key(
                "simulation.output_interval".into(),
                "OPTIONS › dtOut".into(),
            );
        } else if let Some(TimeStepSpec::Value(dt)) = time_step.as_ref().map(|s| s.get_ref()) {
            output_interval = Some(spanned(t, *dt));
            c.note(row.line, "dtOut 0: a sample every time step");
        }
    }
    for (names, note) in NOTED_OPTIONS {
        for (_, _, row) in o
            .rows
            .iter()
            .filter(|(n, _, _)| names.contains(&n.as_str()))
        {
            c.note(row.line, format!("{}{note}", row.tokens[1].text));
        }
    }
    let duration = match (duration, vessel_end) {
        (Some(d), _) => d,
        (None, Some(d)) if coupled > 0 => d,
        _ => {
            c.note(
                0,
                "a MoorDyn deck has no duration: running 60 s (give --duration to change it)",
            );
            60.0
        }
    };
    let anchor = Token {
        text: String::new(),
        span: 0..0,
    };
    SimulationSpec {
        duration: spanned(&anchor, duration),
        time_step,
        safety_factor: None,
        scheme: Some(SchemeSpec::Rk4),
        // dtM was chosen for MoorDyn's integrator.
        step_above_limit: Some(StepAboveLimitSpec::Auto),
        output_interval: output_interval.clone(),
        snapshot_interval: if line_outputs {
            Some(output_interval.unwrap_or_else(|| spanned(&anchor, 0.1)))
        } else {
            None
        },
        formats: None,
        initial_condition: Some(spanned(&anchor, InitialConditionSpec::Statics)),
        release: Vec::new(),
        channels,
    }
}
