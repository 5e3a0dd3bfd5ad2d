//! `[environment]`: water, air, seabed, current and waves, checked and converted into
//! [`hawser::physics::environment::Environment`].

use super::toml_errors::key_span;
use super::{Builder, Check, NON_NEGATIVE, POSITIVE, span_of};
use crate::scenario::schema::*;
use hawser::math::Vec3;
use hawser::physics::environment::{Current, Environment};
use hawser::physics::seabed::{Bathymetry, ContactDamping, FrictionLaw, Seabed, SeabedGrid};
use hawser::physics::waves::{
    IrregularSea, MAX_SPREADING, RegularWave, SeaState, Spectrum, Stretching, WaveSpec, Waves,
    wavenumber,
};
use std::path::Path;
use toml::Spanned;

pub(super) fn build_environment(b: &mut Builder, spec: Option<&EnvironmentSpec>) -> Environment {
    let default = EnvironmentSpec::default();
    let e = spec.unwrap_or(&default);
    let mut env = Environment {
        gravity: b.opt(
            &e.gravity,
            "environment.gravity",
            9.80665,
            Check {
                ok: NON_NEGATIVE,
                expected: "m/s², ≥ 0",
            },
            "9.80665 on Earth",
        ),
        water_density: b.opt(
            &e.water_density,
            "environment.water_density",
            1025.0,
            Check {
                ok: POSITIVE,
                expected: "kg/m³, > 0",
            },
            "sea water is about 1025 kg/m³",
        ),
        air_density: b.opt(
            &e.air_density,
            "environment.air_density",
            1.225,
            Check {
                ok: NON_NEGATIVE,
                expected: "kg/m³, ≥ 0",
            },
            "air is about 1.225 kg/m³",
        ),
        depth: f64::INFINITY,
        seabed: Seabed::default(),
        bathymetry: Default::default(),
        current: Current::None,
        waves: Waves::None,
        wave_kinematics: Default::default(),
        obstacles: Vec::new(),
    };
    if let Some(d) = &e.depth {
        let errors = b.errors.len();
        env.depth = b.num(
            d,
            "environment.depth",
            Check {
                ok: POSITIVE,
                expected: "m, > 0 (the seabed is at z = −depth)",
            },
            "depth is positive; the seabed lies at z = −depth",
        );
        if b.errors.len() > errors {
            env.depth = f64::INFINITY;
        }
    }
    if let Some(s) = &e.seabed {
        let d = Seabed::default();
        env.seabed = Seabed {
            stiffness: b.opt(
                &s.stiffness,
                "environment.seabed.stiffness",
                d.stiffness,
                Check {
                    ok: NON_NEGATIVE,
                    expected: "Pa/m, ≥ 0",
                },
                "3e6 Pa/m is a firm bed",
            ),
            damping: match (&s.damping_ratio, &s.damping) {
                (Some(_), Some(c)) => {
                    let d = b
                        .diag(
                            Some(c.span()),
                            "environment.seabed.damping",
                            "give either `damping_ratio` or `damping`, not both",
                        )
                        .hint("`damping_ratio` scales with each cable's mass; `damping` is per contact area");
                    b.push(d);
                    ContactDamping::Ratio(1.0)
                }
                (_, Some(c)) => ContactDamping::PerArea(b.num(
                    c,
                    "environment.seabed.damping",
                    Check {
                        ok: NON_NEGATIVE,
                        expected: "Pa·s/m, ≥ 0",
                    },
                    "MoorDyn's cBot, e.g. 3e5 Pa·s/m",
                )),
                (ratio, None) => ContactDamping::Ratio(b.opt(
                    ratio,
                    "environment.seabed.damping_ratio",
                    1.0,
                    Check {
                        ok: NON_NEGATIVE,
                        expected: "-, ≥ 0 (1 = critical)",
                    },
                    "use 1 for critical damping",
                )),
            },
            friction_coefficient: b.opt(
                &s.friction_coefficient,
                "environment.seabed.friction_coefficient",
                d.friction_coefficient,
                Check {
                    ok: NON_NEGATIVE,
                    expected: "-, ≥ 0",
                },
                "typical values are 0.2–1.0",
            ),
            friction_velocity: b.opt(
                &s.friction_velocity,
                "environment.seabed.friction_velocity",
                d.friction_velocity,
                Check {
                    ok: POSITIVE,
                    expected: "m/s, > 0",
                },
                "a small speed such as 0.01 m/s",
            ),
            friction_law: match &s.friction_damping {
                Some(c) => FrictionLaw::Viscous {
                    damping: b.num(
                        c,
                        "environment.seabed.friction_damping",
                        Check {
                            ok: POSITIVE,
                            expected: "N·s/m per node, > 0",
                        },
                        "MoorDyn's default FricDamp is 200 N·s/m",
                    ),
                    static_scale: b.opt(
                        &s.static_friction_scale,
                        "environment.seabed.static_friction_scale",
                        1.0,
                        Check {
                            ok: POSITIVE,
                            expected: "-, > 0",
                        },
                        "1 makes static and dynamic friction equal",
                    ),
                },
                None => {
                    b.not_for(
                        s.static_friction_scale.is_some(),
                        span_of(&s.static_friction_scale),
                        "environment.seabed.static_friction_scale",
                        "the tanh friction law",
                        "MoorDyn's friction law, with `friction_damping`",
                    );
                    FrictionLaw::Tanh
                }
            },
        };
        env.bathymetry = build_bathymetry(b, s, &mut env.depth);
        if env.depth.is_infinite() && e.depth.is_none() {
            let span = key_span(b.source, &["environment", "seabed"]);
            let d = b
                .diag(
                    span,
                    "environment.depth",
                    "a seabed is given but no `environment.depth`",
                )
                .value("")
                .expected("m, > 0 (the seabed is at z = −depth)")
                .hint("set `depth` in [environment], or remove the seabed for deep water");
            b.push(d);
        }
    }
    if let Some(c) = &e.current {
        match c.kind.get_ref() {
            CurrentKind::Uniform => {
                b.not_for(
                    c.profile.is_some(),
                    span_of(&c.profile),
                    "environment.current.profile",
                    "a uniform current",
                    "`type = \"profile\"`",
                );
                match &c.velocity {
                    Some(v) => {
                        env.current = Current::Uniform(b.vec3(v, "environment.current.velocity"))
                    }
                    None => {
                        let d = b
                            .diag(
                                Some(c.kind.span()),
                                "environment.current.velocity",
                                "a uniform current needs `velocity`",
                            )
                            .expected("[ux, uy, uz] in m/s");
                        b.push(d);
                    }
                }
            }
            CurrentKind::Profile => {
                b.not_for(
                    c.velocity.is_some(),
                    span_of(&c.velocity),
                    "environment.current.velocity",
                    "a current profile",
                    "`type = \"uniform\"`",
                );
                match &c.profile {
                    Some(p) => {
                        let rows = p.get_ref();
                        let increasing = rows.windows(2).all(|w| w[1][0] > w[0][0]);
                        if rows.is_empty()
                            || !increasing
                            || rows.iter().flatten().any(|x| !x.is_finite())
                        {
                            let d = b
                                .diag(Some(p.span()), "environment.current.profile", "the current profile must have rows with strictly increasing z")
                                .expected("rows [z, ux, uy, uz] in m and m/s, z increasing")
                                .hint("list the deepest point first, e.g. [[-100, 0, 0, 0], [0, 0.5, 0, 0]]");
                            b.push(d);
                        } else if rows
                            .iter()
                            .all(|r| b.physical(Some(p.span()), "environment.current.profile", r))
                        {
                            env.current = Current::Profile {
                                z: rows.iter().map(|r| r[0]).collect(),
                                velocity: rows
                                    .iter()
                                    .map(|r| Vec3::new(r[1], r[2], r[3]))
                                    .collect(),
                            };
                        }
                    }
                    None => {
                        let d = b
                            .diag(
                                Some(c.kind.span()),
                                "environment.current.profile",
                                "a current profile needs `profile`",
                            )
                            .expected("rows [z, ux, uy, uz] in m and m/s");
                        b.push(d);
                    }
                }
            }
            CurrentKind::ProfileTable => {
                if let Some(table) = super::sea::current_table(b, c) {
                    env.current = table;
                }
            }
        }
    }
    if let Some(w) = &e.waves {
        env.waves = build_waves(b, w, env.depth, env.gravity);
        env.wave_kinematics = super::sea::wave_kinematics(b, w, &env.waves);
    }
    env
}

/// A required number of `[environment.waves]` for the wave type at `kind`.
fn wave_value(
    b: &mut Builder,
    v: &Option<Spanned<f64>>,
    kind: &Spanned<WaveKind>,
    name: &str,
    check: Check,
    hint: &str,
) -> f64 {
    let key = format!("environment.waves.{name}");
    match v {
        Some(v) => b.num(v, &key, check, hint),
        None => {
            let what = match kind.get_ref() {
                WaveKind::Regular => "a regular wave",
                WaveKind::Jonswap => "a JONSWAP sea",
                WaveKind::PiersonMoskowitz => "a Pierson–Moskowitz sea",
                WaveKind::ElevationRecord => "an elevation record",
            };
            let d = b
                .diag(Some(kind.span()), &key, format!("{what} needs `{name}`"))
                .value("")
                .expected(check.expected)
                .hint(hint);
            b.push(d);
            1.0
        }
    }
}

/// `[environment.waves]` into [`Waves`] for water of `depth` [m] under `gravity` [m/s²].
fn build_waves(b: &mut Builder, w: &WavesSpec, depth: f64, gravity: f64) -> Waves {
    use std::f64::consts::PI;
    let errors = b.errors.len();
    let kind = *w.kind.get_ref();
    let regular_keys = [
        ("height", span_of(&w.height)),
        ("period", span_of(&w.period)),
    ];
    let irregular_keys = [
        ("significant_height", span_of(&w.significant_height)),
        ("peak_period", span_of(&w.peak_period)),
        ("gamma", span_of(&w.gamma)),
        ("spreading", span_of(&w.spreading)),
        ("seed", span_of(&w.seed)),
        ("components", span_of(&w.components)),
        ("frequency_range", span_of(&w.frequency_range)),
    ];
    let (misplaced, kind_name, applies): (&[_], _, _) = match kind {
        WaveKind::Regular => (
            &irregular_keys,
            "a regular wave",
            "irregular seas, `type = \"jonswap\"` or `\"pierson-moskowitz\"`",
        ),
        WaveKind::ElevationRecord => (&[], "", ""),
        _ => (&regular_keys, "an irregular sea", "`type = \"regular\"`"),
    };
    if kind != WaveKind::ElevationRecord {
        for (name, span) in super::sea::record_keys(w) {
            b.not_for(
                span.is_some(),
                span,
                &format!("environment.waves.{name}"),
                "a regular wave or a spectral sea",
                "`type = \"elevation-record\"`",
            );
        }
    }
    for (name, span) in misplaced {
        b.not_for(
            span.is_some(),
            span.clone(),
            &format!("environment.waves.{name}"),
            kind_name,
            applies,
        );
    }
    if kind == WaveKind::PiersonMoskowitz {
        b.not_for(
            w.gamma.is_some(),
            span_of(&w.gamma),
            "environment.waves.gamma",
            "a Pierson–Moskowitz sea",
            "`type = \"jonswap\"` (γ = 1 is Pierson–Moskowitz)",
        );
    }
    if !(gravity > 0.0) {
        let d = b
            .diag(
                Some(w.kind.span()),
                "environment.gravity",
                "waves need gravity",
            )
            .value(format!("{gravity}"))
            .expected("m/s², > 0 with [environment.waves]")
            .hint("set `gravity` > 0 (9.80665 on Earth) or remove [environment.waves]");
        b.push(d);
    }
    let direction = b
        .opt(
            &w.direction,
            "environment.waves.direction",
            0.0,
            Check {
                ok: |_| true,
                expected: "deg, finite",
            },
            "the direction the waves travel toward, from +x toward +y",
        )
        .to_radians();
    let (sea, period) = match kind {
        WaveKind::ElevationRecord => match super::sea::elevation_record(b, w, direction) {
            Some(r) => r,
            None => return Waves::None,
        },
        WaveKind::Regular => {
            let height = wave_value(
                b,
                &w.height,
                &w.kind,
                "height",
                Check {
                    ok: POSITIVE,
                    expected: "m, > 0 (crest to trough)",
                },
                "the height H from crest to trough, e.g. `height = 2.0`",
            );
            let period = wave_value(
                b,
                &w.period,
                &w.kind,
                "period",
                Check {
                    ok: POSITIVE,
                    expected: "s, > 0",
                },
                "the wave period T, e.g. `period = 8.0`",
            );
            if b.errors.len() == errors
                && let Some(h) = &w.height
            {
                // Miche's limit: a steeper wave breaks.
                let k = wavenumber(2.0 * PI / period, depth, gravity);
                let tanh_kh = if depth.is_finite() {
                    (k * depth).tanh()
                } else {
                    1.0
                };
                let limit = 0.142 * 2.0 * PI / k * tanh_kh;
                if height > limit {
                    let d = b
                        .diag(
                            Some(h.span()),
                            "environment.waves.height",
                            format!("a {height} m, {period} s wave breaks in this water"),
                        )
                        .expected(format!(
                            "m, ≤ {limit:.3}: Miche's breaking limit H/L = 0.142 tanh kh \
                             (wavelength L = {:.2} m)",
                            2.0 * PI / k
                        ))
                        .hint("linear (Airy) waves need a lower wave or a longer period");
                    b.push(d);
                }
            }
            (
                SeaState::Regular(RegularWave {
                    height,
                    period,
                    direction,
                }),
                period,
            )
        }
        WaveKind::Jonswap | WaveKind::PiersonMoskowitz => {
            let significant_height = wave_value(
                b,
                &w.significant_height,
                &w.kind,
                "significant_height",
                Check {
                    ok: POSITIVE,
                    expected: "m, > 0",
                },
                "Hs = 4√m0, e.g. `significant_height = 4.0`",
            );
            let peak_period = wave_value(
                b,
                &w.peak_period,
                &w.kind,
                "peak_period",
                Check {
                    ok: POSITIVE,
                    expected: "s, > 0",
                },
                "the period Tp of the spectral peak, e.g. `peak_period = 10.0`",
            );
            let spectrum = if kind == WaveKind::Jonswap {
                Spectrum::Jonswap {
                    significant_height,
                    peak_period,
                    peak_enhancement: b.opt(
                        &w.gamma,
                        "environment.waves.gamma",
                        3.3,
                        Check {
                            ok: |x| x >= 1.0,
                            expected: "-, ≥ 1 (1 gives Pierson–Moskowitz)",
                        },
                        "3.3 is the mean JONSWAP sea; 1–7 is the usual range",
                    ),
                }
            } else {
                Spectrum::PiersonMoskowitz {
                    significant_height,
                    peak_period,
                }
            };
            let spreading = w.spreading.as_ref().map(|s| {
                b.num(
                    s,
                    "environment.waves.spreading",
                    Check {
                        ok: |s| s > 0.0 && s <= MAX_SPREADING,
                        expected: "-, > 0 and ≤ 1000",
                    },
                    "the cos-2s exponent s: 1–20 for wind seas, larger for swell; omit it for a long-crested sea",
                )
            });
            let components = match &w.components {
                Some(n) if !(1..=100_000).contains(n.get_ref()) => {
                    let d = b
                        .diag(
                            Some(n.span()),
                            "environment.waves.components",
                            "the component count is out of range",
                        )
                        .expected("an integer from 1 to 100000")
                        .hint("100–500 components are usual; the default is 200");
                    b.push(d);
                    1
                }
                Some(n) => *n.get_ref() as usize,
                None => 200,
            };
            let fp = 1.0 / peak_period;
            let frequency_range = match &w.frequency_range {
                Some(r) => {
                    let [lo, hi] = *r.get_ref();
                    if !(lo.is_finite() && hi.is_finite() && lo > 0.0 && hi > lo) {
                        let d = b
                            .diag(
                                Some(r.span()),
                                "environment.waves.frequency_range",
                                "the frequency range must be increasing and positive",
                            )
                            .expected("[lowest, highest] in Hz, 0 < lowest < highest")
                            .hint(format!(
                                "the default is [{:.4}, {:.4}] Hz: 0.5 and 5 times 1/Tp",
                                0.5 * fp,
                                5.0 * fp
                            ));
                        b.push(d);
                    } else {
                        b.physical(
                            Some(r.span()),
                            "environment.waves.frequency_range",
                            &[lo, hi],
                        );
                    }
                    (2.0 * PI * lo, 2.0 * PI * hi)
                }
                None => (2.0 * PI * 0.5 * fp, 2.0 * PI * 5.0 * fp),
            };
            (
                SeaState::Irregular(IrregularSea {
                    spectrum,
                    direction,
                    spreading,
                    seed: w.seed.as_ref().map_or(1, |s| *s.get_ref() as u64),
                    components,
                    frequency_range,
                }),
                peak_period,
            )
        }
    };
    let ramp_time = b.opt(
        &w.ramp_time,
        "environment.waves.ramp_time",
        2.0 * period,
        Check {
            ok: NON_NEGATIVE,
            expected: "s, ≥ 0 (0: no ramp)",
        },
        "the sea builds up from calm over this time; the default is two (peak) periods",
    );
    let stretching = match w.stretching {
        Some(StretchingSpec::Vertical) => Stretching::Vertical,
        Some(StretchingSpec::Wheeler) | None => Stretching::Wheeler,
    };
    if b.errors.len() > errors {
        return Waves::None;
    }
    let spec = WaveSpec {
        sea,
        ramp_time,
        stretching,
    };
    match Waves::new(&spec, depth, gravity) {
        Ok(waves) => waves,
        Err(e) => {
            let d = b.diag(Some(w.kind.span()), "environment.waves", e.to_string());
            b.push(d);
            Waves::None
        }
    }
}

/// The shape of `[environment.seabed]`: flat, a sloping plane (`gradient` or `normal`), or a
/// grid of heights from a file (`grid`). Over a grid without `environment.depth`, `depth`
/// becomes the negated mean of its heights (MoorDyn's average depth), for the waves.
fn build_bathymetry(b: &mut Builder, s: &SeabedSpec, depth: &mut f64) -> Bathymetry {
    let given: Vec<(&str, std::ops::Range<usize>)> = [
        ("gradient", span_of(&s.gradient)),
        ("normal", span_of(&s.normal)),
        ("grid", span_of(&s.grid)),
    ]
    .into_iter()
    .filter_map(|(k, span)| span.map(|s| (k, s)))
    .collect();
    if given.len() > 1 {
        let d = b
            .diag(
                Some(given[1].1.clone()),
                &format!("environment.seabed.{}", given[1].0),
                format!(
                    "the seabed's shape is given twice (`{}` and `{}`)",
                    given[0].0, given[1].0
                ),
            )
            .expected("one shape: `gradient` [-], `normal` [-] or `grid` (a file)")
            .hint("give one of `gradient`, `normal` or `grid`");
        b.push(d);
        return Bathymetry::Flat;
    }
    if let Some(g) = &s.gradient {
        let v = g.get_ref();
        if v.iter().any(|x| !x.is_finite()) {
            let d = b
                .diag(
                    Some(g.span()),
                    "environment.seabed.gradient",
                    "`environment.seabed.gradient` has a non-finite component",
                )
                .expected("[∂z/∂x, ∂z/∂y], two finite numbers [-]")
                .hint("0.05 rises 5 m per 100 m");
            b.push(d);
            return Bathymetry::Flat;
        }
        if !b.physical(Some(g.span()), "environment.seabed.gradient", v) {
            return Bathymetry::Flat;
        }
        return Bathymetry::Plane { gradient: *v };
    }
    if let Some(n) = &s.normal {
        let v = n.get_ref();
        if !(v.iter().all(|x| x.is_finite()) && v[2] > 0.0) {
            let d = b
                .diag(
                    Some(n.span()),
                    "environment.seabed.normal",
                    "`environment.seabed.normal` must point up",
                )
                .expected("[nx, ny, nz], finite, nz > 0 [-]")
                .hint("the bed's upward normal; [0, 0, 1] is flat");
            b.push(d);
            return Bathymetry::Flat;
        }
        if !b.physical(Some(n.span()), "environment.seabed.normal", v) {
            return Bathymetry::Flat;
        }
        return Bathymetry::Plane {
            gradient: [-v[0] / v[2], -v[1] / v[2]],
        };
    }
    let Some(f) = &s.grid else {
        return Bathymetry::Flat;
    };
    let path = b.file.parent().unwrap_or(Path::new(".")).join(f.get_ref());
    let grid = crate::scenario::tables::read_seabed_grid(&path).map(|g| {
        let flat: Vec<f64> = (0..g.z.len())
            .flat_map(|k| [g.x[k % g.x.len()], g.y[k / g.x.len()], g.z[k]])
            .collect();
        (g, flat)
    });
    let (grid, flat) = match grid {
        Ok(g) => g,
        Err(e) => {
            let d = b
                .diag(Some(f.span()), "environment.seabed.grid", e)
                .expected(
                    "a MoorDyn SeafloorFile (`nx ny`, x values, y values, rows `x y z`), a \
                     MoorDyn-F bathymetry file, or a CSV `x,y,z` (or `depth`), relative to the \
                     scenario file",
                )
                .hint("heights z are up (negative below the surface); depths are positive down");
            b.push(d);
            return Bathymetry::Flat;
        }
    };
    if !b.physical(Some(f.span()), "environment.seabed.grid", &flat) {
        return Bathymetry::Flat;
    }
    match SeabedGrid::new(grid.x, grid.y, grid.z) {
        Ok(g) => {
            if depth.is_infinite() {
                if !(g.mean() < 0.0) {
                    let d = b
                        .diag(
                            Some(f.span()),
                            "environment.seabed.grid",
                            format!(
                                "the grid's mean height is {} m: the bed is not under water",
                                g.mean()
                            ),
                        )
                        .expected("heights z below the surface (negative)")
                        .hint("give heights up (z < 0), or a CSV column `depth` for depths");
                    b.push(d);
                    return Bathymetry::Flat;
                }
                *depth = -g.mean();
            }
            Bathymetry::Grid(g)
        }
        Err(e) => {
            let d = b
                .diag(Some(f.span()), "environment.seabed.grid", e)
                .expected("x and y values increasing, heights finite [m]")
                .hint("the grid's x and y values must increase");
            b.push(d);
            Bathymetry::Flat
        }
    }
}
