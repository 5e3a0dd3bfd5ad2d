//! `[[line_types]]`: materials and hydrodynamic coefficients, checked and converted into
//! [`hawser::model::LineType`].

use super::{Builder, Check, NON_NEGATIVE, POSITIVE, span_of};
use crate::scenario::schema::*;
use hawser::model::*;
use hawser::physics::hydrodynamics::{DragModel, LoadingFunction};
use hawser::physics::material::{AxialDamping, AxialStiffness};
use std::collections::HashMap;

pub(super) fn build_line_types(
    b: &mut Builder,
    specs: &[LineTypeSpec],
) -> (Vec<LineType>, HashMap<String, usize>) {
    let mut out = Vec::new();
    let mut index = HashMap::new();
    for (i, t) in specs.iter().enumerate() {
        let k = |key: &str| format!("line_types[{i}].{key}");
        let name = t.name.get_ref().clone();
        if let Some(first) = index.insert(name.clone(), i) {
            let line = b.line_of(specs[first].name.span());
            let d = b
                .diag(
                    Some(t.name.span()),
                    &k("name"),
                    format!("line type `{name}` is defined twice"),
                )
                .hint(format!(
                    "`{name}` is first defined on line {line}; give each line type its own name"
                ));
            b.push(d);
        }
        let diameter = b.num(
            &t.diameter,
            &k("diameter"),
            Check {
                ok: POSITIVE,
                expected: "m, > 0",
            },
            "the nominal (hydrodynamic) diameter, e.g. 0.09 for a 90 mm chain's equivalent",
        );
        let mass = b.num(
            &t.mass_per_length,
            &k("mass_per_length"),
            Check {
                ok: POSITIVE,
                expected: "kg/m, > 0",
            },
            "mass per metre of unstretched line in air",
        );
        let stiffness = match (&t.axial_stiffness, &t.tension_strain) {
            (Some(ea), None) => AxialStiffness::Linear(b.num(
                ea,
                &k("axial_stiffness"),
                Check {
                    ok: POSITIVE,
                    expected: "N, > 0 (EA)",
                },
                "EA = Young's modulus × area, e.g. 3.8e8 N",
            )),
            (None, Some(table)) => {
                let rows = table.get_ref();
                let num = |x: f64| match x.abs() >= 1e4 {
                    true => format!("{x:e}"),
                    false => format!("{x}"),
                };
                let problem = if rows.iter().flatten().any(|x| !x.is_finite()) {
                    Some("the tension–strain table has a non-finite number".to_string())
                } else if rows.len() < 2 {
                    Some("the tension–strain table needs at least two rows".to_string())
                } else if rows[0] != [0.0, 0.0] {
                    Some(format!(
                        "the tension–strain table must start at [0, 0], not [{}, {}]",
                        num(rows[0][0]),
                        num(rows[0][1])
                    ))
                } else if let Some(r) = rows.windows(2).position(|w| !(w[1][0] > w[0][0])) {
                    Some(format!(
                        "strain must increase down the tension–strain table: row {} has {} after {}",
                        r + 2,
                        rows[r + 1][0],
                        rows[r][0]
                    ))
                } else if let Some(r) = rows.windows(2).position(|w| w[1][1] < w[0][1]) {
                    Some(format!(
                        "tension must not decrease down the tension–strain table: row {} has {} N after {} N",
                        r + 2,
                        num(rows[r + 1][1]),
                        num(rows[r][1])
                    ))
                } else if !(rows[rows.len() - 1][1] > 0.0) {
                    Some("the tension–strain table never rises above zero tension".to_string())
                } else {
                    None
                };
                let physical = problem.is_some()
                    || rows
                        .iter()
                        .all(|r| b.physical(Some(table.span()), &k("tension_strain"), r));
                if !physical {
                    AxialStiffness::Linear(1.0)
                } else if let Some(problem) = problem {
                    let d = b
                        .diag(Some(table.span()), &k("tension_strain"), problem)
                        .expected("rows [strain, tension] in - and N, starting at [0, 0], strain increasing, tension non-decreasing")
                        .hint("e.g. [[0, 0], [0.01, 2e6], [0.02, 5e6]]");
                    b.push(d);
                    AxialStiffness::Linear(1.0)
                } else {
                    AxialStiffness::Table {
                        strain: rows.iter().map(|r| r[0]).collect(),
                        tension: rows.iter().map(|r| r[1]).collect(),
                    }
                }
            }
            (Some(ea), Some(_)) => {
                let d = b
                    .diag(
                        Some(ea.span()),
                        &k("axial_stiffness"),
                        "give either `axial_stiffness` or `tension_strain`, not both",
                    )
                    .expected("`axial_stiffness` in N (EA), or a `tension_strain` table in - and N")
                    .hint("remove one of them");
                b.push(d);
                AxialStiffness::Linear(1.0)
            }
            (None, None) => {
                let d = b
                    .diag(
                        Some(t.name.span()),
                        &k("axial_stiffness"),
                        format!("line type `{name}` has no axial stiffness"),
                    )
                    .expected("`axial_stiffness` in N (EA) or a `tension_strain` table")
                    .hint("add e.g. `axial_stiffness = 3.84e8`");
                b.push(d);
                AxialStiffness::Linear(1.0)
            }
        };
        let damping = match (&t.axial_damping, &t.axial_damping_ratio) {
            (Some(c), None) => AxialDamping::Coefficient(b.num(
                c,
                &k("axial_damping"),
                Check {
                    ok: NON_NEGATIVE,
                    expected: "N·s, ≥ 0",
                },
                "the coefficient c of T = EA ε + c dε/dt",
            )),
            (None, Some(z)) => AxialDamping::Ratio(b.num(
                z,
                &k("axial_damping_ratio"),
                Check {
                    ok: NON_NEGATIVE,
                    expected: "-, ≥ 0 (fraction of critical)",
                },
                "MoorDyn's BA = -ζ; 0.8 is common for chain",
            )),
            (None, None) => AxialDamping::Coefficient(0.0),
            (Some(c), Some(_)) => {
                let d = b
                    .diag(
                        Some(c.span()),
                        &k("axial_damping"),
                        "give either `axial_damping` or `axial_damping_ratio`, not both",
                    )
                    .hint("remove one of them");
                b.push(d);
                AxialDamping::Coefficient(0.0)
            }
        };
        let drag = match (&t.loading_functions, &t.normal_drag, &t.tangential_drag) {
            (Some(lf), None, None) => {
                // The coefficients carry no span of their own: errors point at the type's name.
                for (which, f) in [("normal", &lf.normal), ("tangential", &lf.tangential)] {
                    for (part, c) in [("cos", &f.cos), ("sin", &f.sin)] {
                        let key = k(&format!("loading_functions.{which}.{part}"));
                        if c.iter().any(|x| !x.is_finite()) {
                            let d = b
                                .diag(
                                    Some(t.name.span()),
                                    &key,
                                    format!("`{key}` has a non-finite coefficient"),
                                )
                                .expected("finite Fourier coefficients [-]")
                                .hint("nan and inf are not allowed here");
                            b.push(d);
                        } else {
                            b.physical(Some(t.name.span()), &key, c);
                        }
                    }
                }
                DragModel::LoadingFunctions {
                    normal: LoadingFunction {
                        cos: lf.normal.cos.clone(),
                        sin: lf.normal.sin.clone(),
                    },
                    tangential: LoadingFunction {
                        cos: lf.tangential.cos.clone(),
                        sin: lf.tangential.sin.clone(),
                    },
                }
            }
            (None, Some(n), Some(tg)) => DragModel::Morison {
                normal: b.num(
                    n,
                    &k("normal_drag"),
                    Check {
                        ok: NON_NEGATIVE,
                        expected: "-, ≥ 0",
                    },
                    "about 1.2 for wire rope, 2.4 for studless chain on d",
                ),
                tangential: b.num(
                    tg,
                    &k("tangential_drag"),
                    Check {
                        ok: NON_NEGATIVE,
                        expected: "-, ≥ 0 (on the area d per length)",
                    },
                    "a MoorDyn CdAx on π·d becomes π·CdAx here",
                ),
            },
            (Some(_), _, _) => {
                let span = span_of(&t.normal_drag).or(span_of(&t.tangential_drag));
                let d = b
                    .diag(
                        span,
                        &k("normal_drag"),
                        "give drag coefficients or `loading_functions`, not both",
                    )
                    .hint("remove one of them");
                b.push(d);
                DragModel::Morison {
                    normal: 0.0,
                    tangential: 0.0,
                }
            }
            (None, n, _) => {
                let missing = if n.is_none() {
                    "normal_drag"
                } else {
                    "tangential_drag"
                };
                let d = b
                    .diag(Some(t.name.span()), &k(missing), format!("line type `{name}` has no `{missing}`"))
                    .expected("`normal_drag` and `tangential_drag` (dimensionless, on the area d per length), or `loading_functions`")
                    .hint("e.g. `normal_drag = 1.2` and `tangential_drag = 0.02`");
                b.push(d);
                DragModel::Morison {
                    normal: 0.0,
                    tangential: 0.0,
                }
            }
        };
        let minimum_breaking_load = t.minimum_breaking_load.as_ref().map(|v| {
            b.num(
                v,
                &k("minimum_breaking_load"),
                Check {
                    ok: POSITIVE,
                    expected: "N, > 0",
                },
                "the catalogue's minimum breaking load, e.g. 6.4e6 N for a 76 mm R3 chain",
            )
        });
        let design_safety_factor = t.design_safety_factor.as_ref().map(|v| {
            let sf = b.num(
                v,
                &k("design_safety_factor"),
                Check {
                    ok: |x| x >= 1.0,
                    expected: "-, ≥ 1",
                },
                "the permissible tension is MBL / SF, e.g. 1.67 for an intact mooring",
            );
            if minimum_breaking_load.is_none() {
                let d = b
                    .diag(
                        Some(v.span()),
                        &k("design_safety_factor"),
                        format!("line type `{name}` has a design safety factor but no minimum breaking load"),
                    )
                    .expected("`minimum_breaking_load` in N beside it")
                    .hint("add e.g. `minimum_breaking_load = 6.4e6`, or remove the safety factor");
                b.push(d);
            }
            sf
        });
        out.push(LineType {
            name,
            diameter,
            mass_per_length: mass,
            axial_stiffness: stiffness,
            axial_damping: damping,
            compression: t.compression.unwrap_or(false),
            bending_stiffness: b.opt(
                &t.bending_stiffness,
                &k("bending_stiffness"),
                0.0,
                Check {
                    ok: NON_NEGATIVE,
                    expected: "N·m², ≥ 0",
                },
                "EI; 0 for a perfectly flexible cable",
            ),
            bending_damping: b.opt(
                &t.bending_damping,
                &k("bending_damping"),
                0.0,
                Check {
                    ok: NON_NEGATIVE,
                    expected: "N·m²·s, ≥ 0",
                },
                "0 unless known",
            ),
            drag,
            normal_added_mass: b.opt(
                &t.normal_added_mass,
                &k("normal_added_mass"),
                1.0,
                Check {
                    ok: NON_NEGATIVE,
                    expected: "-, ≥ 0",
                },
                "1 for a circular cylinder",
            ),
            tangential_added_mass: b.opt(
                &t.tangential_added_mass,
                &k("tangential_added_mass"),
                0.0,
                Check {
                    ok: NON_NEGATIVE,
                    expected: "-, ≥ 0",
                },
                "usually 0",
            ),
            minimum_breaking_load,
            design_safety_factor,
        });
    }
    (out, index)
}
