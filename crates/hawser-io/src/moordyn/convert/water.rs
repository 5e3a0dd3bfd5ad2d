//! MoorDyn's water kinematics files: `WaveKin 3` (a wave elevation time series,
//! `wave_elevation.txt`, turned into kinematics by FFT) and `Currents 2` (depth profiles
//! against time, `current_profile_dynamic.txt`), both read from the deck's folder as MoorDyn
//! does, converted into `[environment.waves]` and `[environment.current]` (docs/moordyn.md).

use super::options::Options;
use super::{Converter, Row, Token, parse_number, spanned};
use crate::scenario::schema::*;
use std::path::Path;

/// MoorDyn's default `dtWave` [s].
const MOORDYN_DT_WAVE: f64 = 0.25;
/// MoorDyn drops the elevation record's components above this frequency [Hz]
/// (`constructWaveGridElevationData`: "cut frequencies above 0.5 Hz").
const MOORDYN_CUTOFF_HZ: f64 = 0.5;

/// `WaveKin` into `[environment.waves]`: 0 none, 3 the elevation record; other modes are
/// refused. `dtWave` is read here (it only matters with waves).
pub(super) fn waves_of(c: &mut Converter, o: &Options, dir: &Path) -> Option<WavesSpec> {
    let dt_wave = o.get(&["dtwave"]);
    let Some((t, row)) = o.get(&["wavekin"]) else {
        note_unused_dt_wave(c, dt_wave);
        return None;
    };
    match parse_number(&t.text) {
        Some(0.0) => {
            note_unused_dt_wave(c, dt_wave);
            None
        }
        Some(3.0) => elevation_record(c, t, row, dt_wave, dir),
        _ => {
            let d = c
                .diag(
                    Some(t.span.clone()),
                    "OPTIONS › WaveKin",
                    format!("WaveKin mode `{}` is not supported", t.text),
                )
                .expected(
                    "0 (still water) or 3 (wave elevation time series from wave_elevation.txt)",
                )
                .hint(
                    "MoorDyn's other modes read grids, spectra or host-supplied kinematics; for \
                     a spectral sea write hawser's [environment.waves] (type = \"jonswap\"), \
                     or set WaveKin to 0",
                );
            c.errors.push(d);
            None
        }
    }
}

fn note_unused_dt_wave(c: &mut Converter, dt_wave: Option<(&Token, &Row)>) {
    if let Some((_, row)) = dt_wave {
        c.note(
            row.line,
            format!(
                "{} has no effect: waves are off (WaveKin 0)",
                row.tokens[1].text
            ),
        );
    }
}

/// `WaveKin 3`: `wave_elevation.txt` beside the deck (rows `t η`), resampled at `dtWave`
/// and cut above 0.5 Hz as MoorDyn does, travelling along +x, linear profiles (MoorDyn's grid
/// has no stretching).
fn elevation_record(
    c: &mut Converter,
    t: &Token,
    row: &Row,
    dt_wave: Option<(&Token, &Row)>,
    dir: &Path,
) -> Option<WavesSpec> {
    let path = dir.join("wave_elevation.txt");
    if let Err(e) = crate::scenario::build::read_elevation_file(&path) {
        let d = c
            .diag(
                Some(t.span.clone()),
                "OPTIONS › WaveKin",
                format!("WaveKin 3 needs {e}"),
            )
            .expected("wave_elevation.txt beside the deck: rows `t η` [s, m]")
            .hint("put the elevation record next to the deck, or set WaveKin to 0");
        c.errors.push(d);
        return None;
    }
    let dt = match dt_wave {
        Some((v, r)) => {
            let x = c.number(v, "OPTIONS", &r.tokens[1].text.clone(), "s")?;
            spanned(v, x)
        }
        None => spanned(t, MOORDYN_DT_WAVE),
    };
    c.name_key(
        "environment.waves.resample_interval".into(),
        "OPTIONS › dtWave".into(),
    );
    c.name_key(
        "environment.waves.elevation_file".into(),
        "OPTIONS › WaveKin (wave_elevation.txt)".into(),
    );
    let absolute = std::fs::canonicalize(&path).unwrap_or(path);
    c.note(
        row.line,
        format!(
            "WaveKin 3: the elevation record {} resampled every {} s, its components up to \
             {MOORDYN_CUTOFF_HZ} Hz as in MoorDyn, summed at every point (linear profiles, no \
             stretching, the record's mean left out); the sea builds up over two periods of \
             its largest component from hawser's calm static state (MoorDyn starts it at full \
             height). `kinematics = \"static-position\"` in [environment.waves] is faster",
            absolute.display(),
            dt.get_ref()
        ),
    );
    Some(WavesSpec {
        kind: spanned(t, WaveKind::ElevationRecord),
        height: None,
        period: None,
        significant_height: None,
        peak_period: None,
        gamma: None,
        direction: None,
        spreading: None,
        seed: None,
        components: None,
        frequency_range: None,
        ramp_time: None,
        stretching: Some(StretchingSpec::Vertical),
        kinematics: None,
        sample_interval: None,
        elevation: None,
        elevation_file: Some(spanned(t, absolute.display().to_string())),
        resample_interval: Some(dt),
        cutoff_frequency: Some(spanned(t, MOORDYN_CUTOFF_HZ)),
    })
}

/// `Currents 2`: `current_profile_dynamic.txt` beside the deck, in MoorDyn's layout: four
/// header lines, the heights z [m] on line 5, line 6 ignored, then one row per time: t [s],
/// then ux at every height, optionally uy and uz at every height [m/s].
pub(super) fn dynamic_current(
    c: &mut Converter,
    t: &Token,
    row: &Row,
    dir: &Path,
) -> Option<CurrentSpec> {
    let path = dir.join("current_profile_dynamic.txt");
    let table =
        match read_dynamic_profile(&path) {
            Ok(x) => x,
            Err(e) => {
                let d = c
                .diag(Some(t.span.clone()), "OPTIONS › Currents", format!("Currents 2 needs {e}"))
                .expected(
                    "current_profile_dynamic.txt beside the deck: 4 header lines, the heights z \
                     [m] on line 5, then rows `t ux(z1..zn) [uy(z1..zn) [uz(z1..zn)]]` from line 7",
                )
                .hint("put the profile file next to the deck, or set Currents to 0");
                c.errors.push(d);
                return None;
            }
        };
    let (z, times, ux, uy, uz) = table;
    c.note(
        row.line,
        format!(
            "Currents 2: {} heights × {} times read from {}, interpolated linearly in height and \
             time as in MoorDyn; unlike MoorDyn, hawser applies the current's ∂u/∂t in the fluid \
             inertia (Froude–Krylov and added mass)",
            z.len(),
            times.len(),
            path.display()
        ),
    );
    Some(CurrentSpec {
        kind: spanned(t, CurrentKind::ProfileTable),
        velocity: None,
        profile: None,
        z: Some(spanned(t, z)),
        times: Some(spanned(t, times)),
        ux: Some(spanned(t, ux)),
        uy: uy.map(|v| spanned(t, v)),
        uz: uz.map(|v| spanned(t, v)),
    })
}

/// The heights, times and velocity rows (ux, and uy, uz when every row has them) of a
/// MoorDyn `current_profile_dynamic.txt`. Errors name the file and line.
#[allow(clippy::type_complexity)]
pub fn read_dynamic_profile(
    path: &Path,
) -> Result<
    (
        Vec<f64>,
        Vec<f64>,
        Vec<Vec<f64>>,
        Option<Vec<Vec<f64>>>,
        Option<Vec<Vec<f64>>>,
    ),
    String,
> {
    let text = crate::scenario::tables::read_text_file(path)
        .map_err(|e| format!("{}: cannot read it: {e}", path.display()))?;
    let lines: Vec<&str> = text.lines().collect();
    let at = |n: usize| format!("{}:{}", path.display(), n + 1);
    if lines.len() < 7 {
        return Err(format!(
            "{}: {} lines, at least 7 are needed (4 header lines, heights, a line, a time row)",
            path.display(),
            lines.len()
        ));
    }
    let numbers = |n: usize| -> Result<Vec<f64>, String> {
        lines[n]
            .split([' ', '\t', ','])
            .filter(|s| !s.is_empty())
            .map(|s| parse_number(s).ok_or_else(|| format!("{}: `{s}` is not a number", at(n))))
            .collect()
    };
    let z = numbers(4)?;
    if z.is_empty() {
        return Err(format!("{}: the heights row is empty", at(4)));
    }
    let nz = z.len();
    let (mut times, mut ux, mut uy, mut uz) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let (mut has_y, mut has_z) = (false, false);
    for n in 6..lines.len() {
        if lines[n].trim().is_empty() {
            continue;
        }
        let v = numbers(n)?;
        if v.len() < nz + 1 {
            return Err(format!(
                "{}: a row needs the time and {nz} x velocities, it has {} numbers",
                at(n),
                v.len()
            ));
        }
        // As MoorDyn: a row without the y (z) block has zero y (z) velocities.
        has_y |= v.len() > 2 * nz;
        has_z |= v.len() > 3 * nz;
        times.push(v[0]);
        ux.push(v[1..=nz].to_vec());
        uy.push(
            v.get(nz + 1..=2 * nz)
                .map_or(vec![0.0; nz], <[f64]>::to_vec),
        );
        uz.push(
            v.get(2 * nz + 1..=3 * nz)
                .map_or(vec![0.0; nz], <[f64]>::to_vec),
        );
    }
    if times.is_empty() {
        return Err(format!("{}: no time rows from line 7 on", path.display()));
    }
    Ok((z, times, ux, has_y.then_some(uy), has_z.then_some(uz)))
}
