//! LINE TYPES: MoorDyn line types into `[[line_types]]` (diameter, mass, stiffness or a
//! tension–strain table, damping, drag and added mass).

use super::{Converter, LINE_TYPE_COLUMNS, spanned};
use crate::moordyn::deck::{Section, Token};
use crate::scenario::schema::*;
use crate::scenario::tables::{parse_number, read_tension_strain};
use std::path::Path;

pub(super) fn convert_line_types(c: &mut Converter, s: &Section, dir: &Path) -> Vec<LineTypeSpec> {
    const S: &str = "LINE TYPES";
    let mut out = Vec::new();
    for row in &s.rows {
        if !c.check_columns(S, row, LINE_TYPE_COLUMNS, 10) {
            continue;
        }
        let t = &row.tokens;
        if t.len() == 12 {
            let d = c
                .diag(
                    Some(t[11].span.clone()),
                    &format!("{S} › {} › dF", t[0].text),
                    "`dF` without `cF`",
                )
                .expected("10 columns, 11 with the VIV lift coefficient Cl, or 13 with Cl dF cF")
                .hint("give both dF and cF, or neither");
            c.errors.push(d);
            continue;
        }
        if let Some(cl) = t.get(10) {
            match c.number(cl, &format!("{S} › {}", t[0].text), "Cl", "-") {
                Some(x) if x != 0.0 => {
                    let d = c
                        .diag(Some(cl.span.clone()), &format!("{S} › {} › Cl", t[0].text), "vortex-induced vibration (Cl > 0) is not supported")
                        .expected("Cl = 0")
                        .hint("hawser has no VIV model; set Cl to 0 (or drop the VIV columns) to run without it");
                    c.errors.push(d);
                }
                Some(_) => c.note(
                    row.line,
                    format!(
                        "line type `{}`: VIV columns with Cl = 0 have no effect",
                        t[0].text
                    ),
                ),
                None => {}
            }
        }
        let i = out.len();
        let name = t[0].text.clone();
        let key = |f: &str| format!("line_types[{i}].{f}");
        for (field, col) in [
            ("name", "TypeName"),
            ("diameter", "Diam"),
            ("mass_per_length", "Mass/m"),
            ("axial_stiffness", "EA"),
            ("tension_strain", "EA"),
            ("axial_damping", "BA/-zeta"),
            ("axial_damping_ratio", "BA/-zeta"),
            ("bending_stiffness", "EI"),
            ("normal_drag", "Cd"),
            ("normal_added_mass", "Ca"),
            ("tangential_drag", "CdAx"),
            ("tangential_added_mass", "CaAx"),
        ] {
            c.name_key(key(field), format!("{S} › {name} › {col}"));
        }
        let diameter = c.number(&t[1], &format!("{S} › {}", t[0].text), "Diam", "m");
        let mass = c.number(&t[2], &format!("{S} › {}", t[0].text), "Mass/m", "kg/m");
        let (axial_stiffness, tension_strain) = match parse_number(&t[3].text) {
            Some(ea) => (Some(spanned(&t[3], ea)), None),
            None if t[3].text.contains('|') => {
                let d = c
                    .diag(
                        Some(t[3].span.clone()),
                        &format!("{S} › {name} › EA"),
                        "visco-elastic `EA|EAd` stiffness is not supported",
                    )
                    .expected("EA as a number in N, or the name of a tension–strain table file")
                    .hint(
                        "give the static stiffness EA; hawser's axial damping is in the BA column",
                    );
                c.errors.push(d);
                (None, None)
            }
            None => match read_tension_strain(&dir.join(&t[3].text)) {
                Ok(rows) => {
                    let line = row.line;
                    c.note(
                        line,
                        format!(
                            "line type `{name}`: tension–strain table read from {} ({} points)",
                            t[3].text,
                            rows.len()
                        ),
                    );
                    (None, Some(spanned(&t[3], rows)))
                }
                Err(msg) => {
                    let d = c
                        .diag(
                            Some(t[3].span.clone()),
                            &format!("{S} › {name} › EA"),
                            format!("`EA` is neither a number nor a readable table file: {msg}"),
                        )
                        .expected(
                            "EA in N, or a file of rows `strain tension` relative to the deck",
                        )
                        .hint("the file path is relative to the deck's folder");
                    c.errors.push(d);
                    (None, None)
                }
            },
        };
        let ba = if parse_number(&t[4].text).is_none()
            && (t[4].text.contains('|')
                || !t[4]
                    .text
                    .starts_with(|ch: char| ch == '-' || ch == '.' || ch.is_ascii_digit()))
        {
            let d = c
                .diag(Some(t[4].span.clone()), &format!("{S} › {name} › BA/-zeta"), "nonlinear or dynamic-spring axial damping (`BA` table file or `BA|BAd`) is not supported")
                .expected("a damping coefficient in N·s, or −ζ (a fraction of critical damping)")
                .hint("give a constant BA");
            c.errors.push(d);
            None
        } else {
            c.number(
                &t[4],
                &format!("{S} › {}", t[0].text),
                "BA/-zeta",
                "N·s (or −ζ, a fraction of critical)",
            )
        };
        if parse_number(&t[5].text).is_none()
            && !t[5]
                .text
                .starts_with(|ch: char| ch == '-' || ch == '.' || ch.is_ascii_digit())
        {
            let d = c
                .diag(
                    Some(t[5].span.clone()),
                    &format!("{S} › {name} › EI"),
                    "a bending moment–curvature table is not supported",
                )
                .expected("EI in N·m²")
                .hint("give a constant EI");
            c.errors.push(d);
        }
        let (axial_damping, axial_damping_ratio) = match ba {
            Some(x) if x < 0.0 => (None, Some(spanned(&t[4], -x))),
            Some(x) => (Some(spanned(&t[4], x)), None),
            None => (None, None),
        };
        let ei = parse_number(&t[5].text);
        if ei.is_some_and(|x| x > 0.0) {
            c.note(
                row.line,
                format!(
                    "line type `{name}`: EI = {} N·m² is kept as `bending_stiffness`; MoorDyn \
                     applies it as nodal bending moments, hawser's `fe` lines carry no bending, \
                     so this line is modelled without it",
                    t[5].text
                ),
            );
        }
        let cd = c.number(&t[6], &format!("{S} › {}", t[0].text), "Cd", "-");
        let ca = c.number(&t[7], &format!("{S} › {}", t[0].text), "Ca", "-");
        let cdax = c.number(&t[8], &format!("{S} › {}", t[0].text), "CdAx", "-");
        let caax = c.number(&t[9], &format!("{S} › {}", t[0].text), "CaAx", "-");
        if let Some(x) = cdax
            && x != 0.0
        {
            c.note(
                row.line,
                format!(
                    "line type `{name}`: CdAx {} on π·d becomes tangential_drag {} on d (× π)",
                    t[8].text,
                    x * std::f64::consts::PI
                ),
            );
        }
        let f = |v: Option<f64>, tok: &Token| v.map(|x| spanned(tok, x));
        out.push(LineTypeSpec {
            name: spanned(&t[0], name.clone()),
            diameter: spanned(&t[1], diameter.unwrap_or(1.0)),
            mass_per_length: spanned(&t[2], mass.unwrap_or(1.0)),
            axial_stiffness,
            tension_strain,
            axial_damping,
            axial_damping_ratio,
            normal_drag: f(cd, &t[6]),
            tangential_drag: f(cdax.map(|x| x * std::f64::consts::PI), &t[8]),
            loading_functions: None,
            normal_added_mass: f(ca, &t[7]),
            tangential_added_mass: f(caax, &t[9]),
            compression: None,
            bending_stiffness: f(ei.filter(|&x| x != 0.0), &t[5]),
            bending_damping: None,
            minimum_breaking_load: None,
            design_safety_factor: None,
        });
    }
    out
}
