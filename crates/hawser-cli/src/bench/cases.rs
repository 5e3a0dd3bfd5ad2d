//! Variants `hawser bench` measures against each other: the same lines with their free rigid
//! bodies or with point masses in their place (`--bodies`), and the same system in still
//! water, under a regular Airy wave or in a JONSWAP sea of N components (`--waves`).

use hawser::math::{Real, Vec3};
use hawser::model::{BodyKind, Model, PointKind};
use hawser::physics::environment::Environment;
use hawser::physics::waves::{
    IrregularSea, RegularWave, SeaState, Spectrum, Stretching, WaveSpec, Waves,
};
use std::f64::consts::PI;
use std::time::Instant;

/// The sea of one `--waves` case.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WaveCase {
    /// The scenario's own waves.
    AsIs,
    /// No waves (and the scenario's current).
    Still,
    /// One regular Airy wave, H 2 m, T 8 s, travelling along +x.
    Regular,
    /// A long-crested JONSWAP sea, γ 3.3, along +x: components, Hs [m], Tp [s] (`jonswap:N`
    /// is Hs 3 m, Tp 9 s).
    Jonswap(usize, Real, Real),
}

impl WaveCase {
    /// The label printed in the `waves` column.
    pub fn label(&self) -> String {
        match self {
            WaveCase::AsIs => "as-is".into(),
            WaveCase::Still => "still".into(),
            WaveCase::Regular => "regular".into(),
            WaveCase::Jonswap(n, hs, tp) if *hs == 3.0 && *tp == 9.0 => format!("jonswap:{n}"),
            WaveCase::Jonswap(n, hs, tp) => format!("jonswap:{n}:{hs}:{tp}"),
        }
    }
}

/// Parses `--waves`: as-is, still, regular, jonswap:N (N ≥ 1), jonswap:N:HS:TP (Hs [m], Tp
/// [s]) or all (still, regular, jonswap:50, jonswap:200), or a comma-separated list of them.
pub fn parse_waves(s: &str) -> Result<Vec<WaveCase>, String> {
    if s.contains(',') {
        let mut out = Vec::new();
        for part in s.split(',') {
            out.extend(parse_waves(part)?);
        }
        return Ok(out);
    }
    let bad = || {
        format!(
            "--waves {s}: expected as-is, still, regular, jonswap:N (N ≥ 1), jonswap:N:HS:TP \
             or all"
        )
    };
    Ok(match s {
        "as-is" => vec![WaveCase::AsIs],
        "still" => vec![WaveCase::Still],
        "regular" => vec![WaveCase::Regular],
        "all" => vec![
            WaveCase::Still,
            WaveCase::Regular,
            WaveCase::Jonswap(50, 3.0, 9.0),
            WaveCase::Jonswap(200, 3.0, 9.0),
        ],
        _ => {
            let Some(rest) = s.strip_prefix("jonswap:") else {
                return Err(bad());
            };
            let parts: Vec<&str> = rest.split(':').collect();
            let n = parts[0].parse::<usize>().ok().filter(|&n| n >= 1);
            let (hs, tp) = match parts.len() {
                1 => (Some(3.0), Some(9.0)),
                3 => (
                    parts[1].parse::<Real>().ok().filter(|x| *x > 0.0),
                    parts[2].parse::<Real>().ok().filter(|x| *x > 0.0),
                ),
                _ => (None, None),
            };
            match (n, hs, tp) {
                (Some(n), Some(hs), Some(tp)) => vec![WaveCase::Jonswap(n, hs, tp)],
                _ => return Err(bad()),
            }
        }
    })
}

/// The waves of `case` in `environment` (its depth and gravity), with no build-up ramp so that
/// the whole sea acts from t = 0. `AsIs` returns the environment's own waves.
pub fn waves_of(case: WaveCase, environment: &Environment) -> Result<Waves, String> {
    let sea = match case {
        WaveCase::AsIs => return Ok(environment.waves.clone()),
        WaveCase::Still => return Ok(Waves::None),
        WaveCase::Regular => SeaState::Regular(RegularWave {
            height: 2.0,
            period: 8.0,
            direction: 0.0,
        }),
        WaveCase::Jonswap(components, significant_height, peak_period) => {
            let fp = 1.0 / peak_period;
            SeaState::Irregular(IrregularSea {
                spectrum: Spectrum::Jonswap {
                    significant_height,
                    peak_period,
                    peak_enhancement: 3.3,
                },
                direction: 0.0,
                spreading: None,
                seed: 1,
                components,
                // The scenario default: 0.5 to 5 times the peak frequency.
                frequency_range: (2.0 * PI * 0.5 * fp, 2.0 * PI * 5.0 * fp),
            })
        }
    };
    let spec = WaveSpec {
        sea,
        ramp_time: 0.0,
        stretching: Stretching::Wheeler,
    };
    Waves::new(&spec, environment.depth, environment.gravity).map_err(|e| e.to_string())
}

/// Replaces every free rigid body by point masses: each point on the body becomes a free point
/// at its initial position carrying an equal share of the body's mass, displaced volume,
/// mean translational drag area C·A and mean translational added mass (as a coefficient on
/// its volume share; none when the body displaces nothing), and its share of the thrust at
/// t = 0 as a constant force in global axes at the initial orientation. The lines, their ends' initial
/// positions and their discretisation are unchanged; the rotational inertia, rotational drag,
/// moments, thrust schedules and wind are dropped. Prescribed bodies stay. Returns the number of bodies replaced.
///
/// This is the comparison "the same lines without bodies" of `hawser bench --bodies`: it
/// measures what the six rigid-body degrees of freedom (their equations, the coupling
/// loads at the body points, the body hydrodynamics) cost per step, not a physically
/// equivalent model.
pub fn bodies_as_points(model: &mut Model) -> usize {
    let free: Vec<bool> = model
        .bodies
        .iter()
        .map(|b| matches!(b.kind, BodyKind::Free))
        .collect();
    // New index of every kept body.
    let mut remap = vec![usize::MAX; model.bodies.len()];
    let mut kept = 0;
    for (i, f) in free.iter().enumerate() {
        if !f {
            remap[i] = kept;
            kept += 1;
        }
    }
    let water_density = model.environment.water_density;
    for bi in 0..model.bodies.len() {
        if !free[bi] {
            continue;
        }
        let on_body: Vec<usize> = model
            .points
            .iter()
            .enumerate()
            .filter(|(_, p)| matches!(p.kind, PointKind::Body { body, .. } if body == bi))
            .map(|(i, _)| i)
            .collect();
        if on_body.is_empty() {
            continue;
        }
        let b = &model.bodies[bi];
        let share = 1.0 / on_body.len() as Real;
        let volume = b.displacement.volume() * share;
        let added_mass = (b.added_mass[0] + b.added_mass[1] + b.added_mass[2]) / 3.0 * share;
        let added_mass_coefficient = if volume > 0.0 {
            added_mass / (water_density * volume)
        } else {
            0.0
        };
        let drag_area =
            (b.quadratic_drag[0] + b.quadratic_drag[1] + b.quadratic_drag[2]) / 3.0 * share;
        let (mass, position, orientation) = (b.mass * share, b.position, b.orientation);
        // The thrust at t = 0, turned into global axes at the initial orientation.
        let force = orientation * b.thrust.at(0.0).0 * share;
        for pi in on_body {
            let PointKind::Body { offset, .. } = model.points[pi].kind else {
                unreachable!("filtered on PointKind::Body")
            };
            let p = &mut model.points[pi];
            p.position = position + orientation * offset;
            p.kind = PointKind::Free {
                mass,
                volume,
                drag_area,
                added_mass_coefficient,
                force,
            };
        }
    }
    for p in &mut model.points {
        if let PointKind::Body { body, .. } = &mut p.kind {
            *body = remap[*body];
        }
    }
    let mut i = 0;
    model.bodies.retain(|_| {
        i += 1;
        !free[i - 1]
    });
    free.iter().filter(|f| **f).count()
}

/// Wall time of one evaluation of the fluid velocity and acceleration [ns], averaged over
/// `points` points spread over the water column from z = −0.9 h to the mean surface along the
/// waves' direction, each evaluated at `times` instants 0.01 s apart; best of 3. The sum of
/// the results is returned too so that the work cannot be optimised away. `separate`: by
/// [`Environment::fluid_velocity`] and [`Environment::fluid_acceleration`], two wave sums
/// (how the lines evaluated them before [`Environment::fluid_kinematics`], kept as the
/// reference of the saving); otherwise by `fluid_kinematics`, one sum, as the lines do.
pub fn kinematics_ns(
    environment: &Environment,
    points: usize,
    times: usize,
    separate: bool,
) -> (f64, f64) {
    let depth = environment.depth.min(1000.0);
    let positions: Vec<Vec3> = (0..points)
        .map(|i| {
            let s = (i as Real + 0.5) / points as Real;
            Vec3::new(37.0 * s, 11.0 * s, -0.9 * depth * s)
        })
        .collect();
    let mut best = f64::INFINITY;
    let mut sum = 0.0;
    for _ in 0..3 {
        let start = Instant::now();
        for k in 0..times {
            let t = 5.0 + 0.01 * k as Real;
            for p in &positions {
                let (u, a) = if separate {
                    (
                        environment.fluid_velocity(p, t),
                        environment.fluid_acceleration(p, t),
                    )
                } else {
                    environment.fluid_kinematics(p, t)
                };
                sum += u.x + a.z;
            }
        }
        let ns = start.elapsed().as_secs_f64() * 1e9 / (points * times) as f64;
        best = best.min(ns);
    }
    (best, sum)
}

/// CPU time of the calling thread [s] (`clock_gettime(CLOCK_THREAD_CPUTIME_ID)`, to the
/// nanosecond), `None` where the clock cannot be read.
pub fn thread_cpu_seconds() -> Option<f64> {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `ts` is a valid, writable timespec for the duration of the call.
    let rc = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    (rc == 0).then(|| ts.tv_sec as f64 + ts.tv_nsec as f64 * 1e-9)
}

/// The median of `values` (NaN when empty).
pub fn median(values: &mut [f64]) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    values.sort_by(f64::total_cmp);
    let n = values.len();
    if n % 2 == 1 {
        values[n / 2]
    } else {
        0.5 * (values[n / 2 - 1] + values[n / 2])
    }
}
