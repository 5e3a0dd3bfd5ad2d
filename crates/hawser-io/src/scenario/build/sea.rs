//! The parts of `[environment.current]` and `[environment.waves]` beyond the steady currents
//! and spectral seas of `build.rs`: a current table of depth profiles against time
//! (`type = "profile-table"`), a sea from a recorded elevation (`type = "elevation-record"`,
//! by real FFT), and the wave-kinematics method (`kinematics`, `sample_interval`).

use super::{Builder, Check, POSITIVE, span_of};
use crate::scenario::schema::*;
use hawser::math::Vec3;
use hawser::physics::environment::Current;
use hawser::physics::static_kinematics::WaveKinematicsMethod;
use hawser::physics::waves::{ComponentSpec, SeaState, Waves};
use std::path::Path;
use toml::Spanned;

/// `type = "profile-table"`: heights `z`, `times` and velocity rows `ux` (`uy`, `uz`) into a
/// [`Current::Table`]; `None` (with diagnostics) when it is malformed.
pub(super) fn current_table(b: &mut Builder, c: &CurrentSpec) -> Option<Current> {
    for (present, span, key) in [
        (
            c.velocity.is_some(),
            span_of(&c.velocity),
            "environment.current.velocity",
        ),
        (
            c.profile.is_some(),
            span_of(&c.profile),
            "environment.current.profile",
        ),
    ] {
        b.not_for(
            present,
            span,
            key,
            "a current table",
            "`type = \"uniform\"` or `\"profile\"`",
        );
    }
    let need = |b: &mut Builder, name: &str, expected: &str| {
        let d = b
            .diag(
                Some(c.kind.span()),
                &format!("environment.current.{name}"),
                format!("a current table needs `{name}`"),
            )
            .expected(expected.to_string())
            .hint(
                "give `z` (heights, m), `times` (s) and `ux` (one row of m/s per time, one \
                 value per height), e.g. z = [-100, 0], times = [0, 600], \
                 ux = [[0, 0.2], [0, 0.6]]",
            );
        b.push(d);
    };
    let (Some(z), Some(times), Some(ux)) = (&c.z, &c.times, &c.ux) else {
        if c.z.is_none() {
            need(b, "z", "heights [m], strictly increasing");
        }
        if c.times.is_none() {
            need(b, "times", "times [s], strictly increasing");
        }
        if c.ux.is_none() {
            need(b, "ux", "one row of x velocities [m/s] per time");
        }
        return None;
    };
    let errors = b.errors.len();
    let increasing = |key: &str, v: &Spanned<Vec<f64>>, unit: &str, b: &mut Builder| {
        let x = v.get_ref();
        if x.is_empty() || x.iter().any(|v| !v.is_finite()) || x.windows(2).any(|w| w[1] <= w[0]) {
            let d = b
                .diag(
                    Some(v.span()),
                    key,
                    format!("`{key}` must be finite and strictly increasing"),
                )
                .expected(format!("{unit}, at least one value, strictly increasing"))
                .hint("list the deepest height and the earliest time first");
            b.push(d);
        }
    };
    increasing("environment.current.z", z, "m", b);
    increasing("environment.current.times", times, "s", b);
    b.physical(Some(z.span()), "environment.current.z", z.get_ref());
    b.physical(
        Some(times.span()),
        "environment.current.times",
        times.get_ref(),
    );
    let (nz, nt) = (z.get_ref().len(), times.get_ref().len());
    let rows = |name: &str, v: Option<&Spanned<Vec<Vec<f64>>>>, b: &mut Builder| {
        let Some(v) = v else {
            return vec![0.0; nz * nt];
        };
        let key = format!("environment.current.{name}");
        let r = v.get_ref();
        if r.len() != nt || r.iter().any(|row| row.len() != nz) {
            let d = b
                .diag(
                    Some(v.span()),
                    &key,
                    format!(
                        "`{name}` must have one row per time ({nt}) of one value per height ({nz})"
                    ),
                )
                .value(format!(
                    "{} rows of {} values",
                    r.len(),
                    r.iter()
                        .map(|row| row.len().to_string())
                        .collect::<Vec<_>>()
                        .join(", ")
                ))
                .expected(format!("{nt} rows of {nz} values [m/s]"));
            b.push(d);
            return vec![0.0; nz * nt];
        }
        if r.iter().flatten().any(|x| !x.is_finite()) {
            let d = b
                .diag(
                    Some(v.span()),
                    &key,
                    format!("`{name}` has a non-finite value"),
                )
                .expected("finite velocities [m/s]");
            b.push(d);
        }
        let flat: Vec<f64> = r.iter().flatten().copied().collect();
        b.physical(Some(v.span()), &key, &flat);
        flat
    };
    let x = rows("ux", Some(ux), b);
    let y = rows("uy", c.uy.as_ref(), b);
    let w = rows("uz", c.uz.as_ref(), b);
    if b.errors.len() > errors {
        return None;
    }
    Some(Current::Table {
        z: z.get_ref().clone(),
        time: times.get_ref().clone(),
        velocity: (0..nz * nt).map(|i| Vec3::new(x[i], y[i], w[i])).collect(),
    })
}

/// The keys only an elevation record takes, for the misplaced-key check of other wave types.
pub(super) fn record_keys(w: &WavesSpec) -> [(&'static str, Option<std::ops::Range<usize>>); 4] {
    [
        ("elevation", span_of(&w.elevation)),
        ("elevation_file", span_of(&w.elevation_file)),
        ("resample_interval", span_of(&w.resample_interval)),
        ("cutoff_frequency", span_of(&w.cutoff_frequency)),
    ]
}

/// `type = "elevation-record"`: the record (inline `elevation` or `elevation_file`) turned
/// into its Fourier components travelling toward `direction` [rad] ([`record_components`]),
/// and the period [s] of its largest component (for the default ramp). `None` with
/// diagnostics when it cannot be read.
pub(super) fn elevation_record(
    b: &mut Builder,
    w: &WavesSpec,
    direction: f64,
) -> Option<(SeaState, f64)> {
    for (name, span) in [
        ("height", span_of(&w.height)),
        ("period", span_of(&w.period)),
        ("significant_height", span_of(&w.significant_height)),
        ("peak_period", span_of(&w.peak_period)),
        ("gamma", span_of(&w.gamma)),
        ("spreading", span_of(&w.spreading)),
        ("seed", span_of(&w.seed)),
        ("components", span_of(&w.components)),
        ("frequency_range", span_of(&w.frequency_range)),
    ] {
        b.not_for(
            span.is_some(),
            span,
            &format!("environment.waves.{name}"),
            "an elevation record",
            "`type = \"regular\"`, `\"jonswap\"` or `\"pierson-moskowitz\"`",
        );
    }
    let (rows, span, key) = match (&w.elevation, &w.elevation_file) {
        (Some(e), None) => {
            let flat: Vec<f64> = e.get_ref().iter().flat_map(|r| [r[0], r[1]]).collect();
            if !b.physical(Some(e.span()), "environment.waves.elevation", &flat) {
                return None;
            }
            (
                e.get_ref().iter().map(|r| (r[0], r[1])).collect::<Vec<_>>(),
                e.span(),
                "environment.waves.elevation",
            )
        }
        (None, Some(f)) => {
            let path = b.file.parent().unwrap_or(Path::new(".")).join(f.get_ref());
            match read_elevation_file(&path) {
                Ok(rows) => {
                    let flat: Vec<f64> = rows.iter().flat_map(|&(t, e)| [t, e]).collect();
                    let key = "environment.waves.elevation_file";
                    if !b.physical(Some(f.span()), key, &flat) {
                        return None;
                    }
                    (rows, f.span(), key)
                }
                Err(e) => {
                    let d = b
                        .diag(Some(f.span()), "environment.waves.elevation_file", e)
                        .expected("a file of rows `t η` [s, m], relative to the scenario file")
                        .hint("MoorDyn's wave_elevation.txt has this format");
                    b.push(d);
                    return None;
                }
            }
        }
        (Some(e), Some(_)) => {
            let d = b
                .diag(
                    Some(e.span()),
                    "environment.waves.elevation",
                    "give the record inline (`elevation`) or as `elevation_file`, not both",
                )
                .hint("remove one of the two");
            b.push(d);
            return None;
        }
        (None, None) => {
            let d = b
                .diag(
                    Some(w.kind.span()),
                    "environment.waves.elevation",
                    "an elevation record needs `elevation` or `elevation_file`",
                )
                .expected("rows [t, η] in s and m, times increasing")
                .hint("e.g. elevation = [[0.0, 0.0], [0.5, 0.31], ...], or elevation_file = \"wave_elevation.txt\"");
            b.push(d);
            return None;
        }
    };
    let resample = w.resample_interval.as_ref().map(|v| {
        b.num(
            v,
            "environment.waves.resample_interval",
            Check {
                ok: POSITIVE,
                expected: "s, > 0",
            },
            "the record is resampled linearly at this interval before its Fourier transform",
        )
    });
    let cutoff = w.cutoff_frequency.as_ref().map(|v| {
        b.num(
            v,
            "environment.waves.cutoff_frequency",
            Check {
                ok: POSITIVE,
                expected: "Hz, > 0",
            },
            "components above this frequency are dropped (MoorDyn drops those above 0.5 Hz)",
        )
    });
    match record_components(
        &rows,
        resample,
        cutoff.map(|f| 2.0 * std::f64::consts::PI * f),
        direction,
    ) {
        Ok((components, period)) => Some((SeaState::Components(components), period)),
        Err(e) => {
            let d = b
                .diag(Some(span), key, e)
                .expected("at least 4 rows [t, η] in s and m, times strictly increasing, finite")
                .hint("a record of a few hundred periods of the sea gives a fine frequency resolution");
            b.push(d);
            None
        }
    }
}

/// Reads rows `t η` [s, m] (space, tab or comma separated); lines that do not start with a
/// number (headers, `#` comments) and blank lines are skipped. Errors name the file and line.
pub fn read_elevation_file(path: &Path) -> Result<Vec<(f64, f64)>, String> {
    let text = crate::scenario::tables::read_text_file(path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let mut rows = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let mut fields = line.split([' ', '\t', ',']).filter(|s| !s.is_empty());
        let Some(first) = fields.next() else { continue };
        let Ok(t) = first.parse::<f64>() else {
            continue;
        };
        let eta = fields
            .next()
            .and_then(|s| s.parse::<f64>().ok())
            .ok_or_else(|| {
                format!(
                    "{}:{}: a row needs a time and an elevation, `t η` [s, m]",
                    path.display(),
                    n + 1
                )
            })?;
        rows.push((t, eta));
    }
    Ok(rows)
}

/// The Fourier components of an elevation record η(t) at the origin (MoorDyn's `WaveKin 3`,
/// with its conventions): the record is resampled linearly at t_i = t₀ + i Δt (Δt =
/// `resample`, default the record's smallest step), i < N with N the largest even count that
/// fits the record; its real FFT X_j = Σ_i η_i e^{−2πi ij/N} gives for 1 ≤ j ≤ N/2 the
/// component ω_j = 2π j/(N Δt) of amplitude 2|X_j|/N (|X_j|/N at j = N/2) and phase
/// φ_j = ω_j t₀ − arg X_j in hawser's θ = k·x − ω t + φ, so that Σ a_j cos(φ_j − ω_j t)
/// passes through every resampled η_i once the mean X₀/N (a still-water offset, not a wave)
/// is set aside. Components above `cutoff` [rad/s] and of zero amplitude are dropped. The
/// sea is periodic with period N Δt. Returns the components and the period 2π/ω [s] of the
/// largest one.
pub fn record_components(
    rows: &[(f64, f64)],
    resample: Option<f64>,
    cutoff: Option<f64>,
    direction: f64,
) -> Result<(Vec<ComponentSpec>, f64), String> {
    use realfft::RealFftPlanner;
    use std::f64::consts::PI;
    if rows.len() < 4 {
        return Err(format!(
            "the elevation record has {} rows, at least 4 are needed",
            rows.len()
        ));
    }
    if rows.iter().any(|(t, e)| !t.is_finite() || !e.is_finite()) {
        return Err("the elevation record has a non-finite value".into());
    }
    if let Some(k) = rows.windows(2).position(|w| w[1].0 <= w[0].0) {
        return Err(format!(
            "the elevation record's times must increase strictly (row {} at t = {} s follows t = {} s)",
            k + 2,
            rows[k + 1].0,
            rows[k].0
        ));
    }
    let dt = resample.unwrap_or_else(|| {
        rows.windows(2)
            .map(|w| w[1].0 - w[0].0)
            .fold(f64::INFINITY, f64::min)
    });
    let (t0, t1) = (rows[0].0, rows[rows.len() - 1].0);
    let mut n = ((t1 - t0) / dt * (1.0 + 1e-12)).floor() as usize + 1;
    n -= n % 2;
    if n < 4 {
        return Err(format!(
            "the record spans {} s: fewer than 4 samples at the resample interval {dt} s",
            t1 - t0
        ));
    }
    // Linear resampling.
    let mut samples = Vec::with_capacity(n);
    let mut k = 1;
    for i in 0..n {
        let t = t0 + i as f64 * dt;
        while k < rows.len() - 1 && rows[k].0 < t {
            k += 1;
        }
        let (a, b) = (rows[k - 1], rows[k]);
        let w = ((t - a.0) / (b.0 - a.0)).clamp(0.0, 1.0);
        samples.push(a.1 * (1.0 - w) + b.1 * w);
    }
    let fft = RealFftPlanner::<f64>::new().plan_fft_forward(n);
    let mut spectrum = fft.make_output_vec();
    fft.process(&mut samples, &mut spectrum)
        .map_err(|e| format!("FFT of the elevation record failed: {e}"))?;
    let dw = 2.0 * PI / (n as f64 * dt);
    let mut out = Vec::new();
    let (mut largest, mut period) = (0.0, n as f64 * dt);
    for (j, x) in spectrum.iter().enumerate().skip(1) {
        let omega = j as f64 * dw;
        if cutoff.is_some_and(|c| omega > c) {
            break;
        }
        let scale = if j == n / 2 { 1.0 } else { 2.0 };
        let amplitude = scale * x.norm() / n as f64;
        if amplitude == 0.0 {
            continue;
        }
        if amplitude > largest {
            largest = amplitude;
            period = 2.0 * PI / omega;
        }
        out.push(ComponentSpec {
            amplitude,
            angular_frequency: omega,
            direction,
            phase: omega * t0 - x.im.atan2(x.re),
        });
    }
    if out.is_empty() {
        return Err("the elevation record has no wave component (a constant record, or all above the cutoff)".into());
    }
    Ok((out, period))
}

/// `kinematics` and `sample_interval` of `[environment.waves]` for the built `waves`.
pub(super) fn wave_kinematics(
    b: &mut Builder,
    w: &WavesSpec,
    waves: &Waves,
) -> WaveKinematicsMethod {
    let method = w.kinematics.as_ref().map(|k| *k.get_ref());
    if method != Some(WaveKinematicsSpec::StaticPosition) {
        b.not_for(
            w.sample_interval.is_some(),
            span_of(&w.sample_interval),
            "environment.waves.sample_interval",
            "direct kinematics",
            "`kinematics = \"static-position\"`",
        );
        return WaveKinematicsMethod::Direct;
    }
    let Some(field) = waves.field() else {
        return WaveKinematicsMethod::Direct;
    };
    let default = WaveKinematicsMethod::default_sample_interval(field);
    let sample_interval = b.opt(
        &w.sample_interval,
        "environment.waves.sample_interval",
        default,
        Check {
            ok: POSITIVE,
            expected: "s, > 0",
        },
        &format!(
            "the kinematics at each line point's static position are sampled at this interval \
             and interpolated (cubic) in time; the default {default:.4} s is 1/25 of the \
             shortest component's period"
        ),
    );
    WaveKinematicsMethod::StaticPosition { sample_interval }
}
