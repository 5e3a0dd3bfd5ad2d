//! Checks of a static state: the equilibrium was found, but is it one an engineer can sign?
//! Each finding is a [`Warning`] with its numbers; the thresholds are the constants of
//! [`crate::warning`], each justified there.

use super::newton::evaluate;
use crate::math::{Real, Vec3};
use crate::physics::material::AxialStiffness;
use crate::system::{System, Workspace};
use crate::warning::{
    COMPRESSED_RATIO, DG_TWIN_MISMATCH, LINEAR_STRAIN_LIMIT, TOUCHDOWN_ELEMENTS, Warning,
};

/// The warnings of the static state `y` of `system`: compressed elements, strain beyond the
/// axial law, free points and bodies below the seabed, unresolved touchdowns.
pub fn state_warnings(system: &System, y: &[Real]) -> Vec<Warning> {
    let mut ws = system.workspace();
    evaluate(system, y, &mut ws);
    let mut out = Vec::new();
    for li in 0..system.lines.len() {
        line_warnings(system, &ws, li, &mut out);
    }
    below_seabed(system, y, &ws, &mut out);
    out
}

/// The `dg` lines of `system` whose own tensions at the state `y` differ from those of its
/// statics twin `twin` (its [`System::statics_twin`]) at the twin's equilibrium `y_twin`.
pub(super) fn twin_warnings(
    system: &System,
    y: &[Real],
    twin: &System,
    y_twin: &[Real],
) -> Vec<Warning> {
    if !system.has_dg_lines() {
        return Vec::new();
    }
    let mut ws = system.workspace();
    evaluate(system, y, &mut ws);
    let mut tws = twin.workspace();
    evaluate(twin, y_twin, &mut tws);
    (0..system.lines.len())
        .filter(|&li| system.lines[li].dg().is_some())
        .filter_map(|li| twin_mismatch(system, &ws, twin, &tws, li))
        .collect()
}

/// The strain of an element [-] beyond which its axial law is extrapolated: the last strain
/// of a tension–strain table, [`LINEAR_STRAIN_LIMIT`] for a linear law.
fn strain_limit(stiffness: &AxialStiffness) -> Real {
    match stiffness {
        AxialStiffness::Linear(_) => LINEAR_STRAIN_LIMIT,
        AxialStiffness::Table { strain, .. } => strain.last().copied().unwrap_or(0.0),
    }
}

/// Compressed elements, strain beyond the law and an unresolved touchdown on line `li`.
fn line_warnings(system: &System, ws: &Workspace, li: usize, out: &mut Vec<Warning>) {
    let l = &system.lines[li];
    let el = &ws.lines[li].elements;
    let n = l.mesh.elements();
    let mut compressed = 0;
    let mut shortest: Option<(usize, Real)> = None;
    let mut strained: Option<(usize, Real, Real)> = None;
    for e in 0..n {
        let sec = l.mesh.section(e);
        let strain = el.strain[e];
        if !sec.law.compression && 1.0 + strain < COMPRESSED_RATIO {
            compressed += 1;
            if shortest.is_none_or(|(_, r)| 1.0 + strain < r) {
                shortest = Some((e, 1.0 + strain));
            }
        }
        let limit = strain_limit(&sec.law.stiffness);
        if strain > limit && strained.is_none_or(|(_, s, lim)| strain / limit > s / lim) {
            strained = Some((e, strain, limit));
        }
    }
    if let Some((element, ratio)) = shortest {
        out.push(Warning::CompressedElements {
            line: l.name.clone(),
            elements: compressed,
            element,
            ratio,
        });
    }
    if let Some((element, strain, limit)) = strained {
        out.push(Warning::StrainBeyondMaterial {
            line: l.name.clone(),
            element,
            strain,
            tension: el.tension[element],
            limit,
        });
    }
    if let Some(w) = touchdown(system, ws, li) {
        out.push(w);
    }
}

/// The touchdown check of line `li`: nodes on or below the seabed under them rest on it (the
/// bilinear bed holds them with a small penetration; an anchor sits on it). At each change from resting to suspended nodes,
/// the element between them holds the touchdown; it must be short against the suspended run
/// that follows it and against the resting run before it.
fn touchdown(system: &System, ws: &Workspace, li: usize) -> Option<Warning> {
    let env = &system.environment;
    if !(env.has_seabed() && env.seabed.stiffness > 0.0) {
        return None;
    }
    let l = &system.lines[li];
    let lw = &ws.lines[li];
    let n = l.mesh.elements();
    let resting: Vec<bool> = (0..=n)
        .map(|i| {
            let p = lw.position[l.node_vector(i)];
            p.z <= env.seabed_at(p.x, p.y).z
        })
        .collect();
    if resting.iter().all(|&r| r) || !resting.iter().any(|&r| r) {
        return None;
    }
    let arc: Vec<Real> = (0..=n).map(|i| l.mesh.arc_length(i)).collect();
    // Runs of equal contact: (first node, last node, resting).
    let mut runs: Vec<(usize, usize, bool)> = Vec::new();
    for (i, &r) in resting.iter().enumerate() {
        match runs.last_mut() {
            Some(run) if run.2 == r => run.1 = i,
            _ => runs.push((i, i, r)),
        }
    }
    let mut worst: Option<(Real, Warning)> = None;
    for pair in runs.windows(2) {
        let (rest, hang) = if pair[0].2 {
            (pair[0], pair[1])
        } else {
            (pair[1], pair[0])
        };
        // A line end alone on the bed is an anchor the line rises from: its first element
        // leaves the bed at once.
        if rest.0 == rest.1 && (rest.0 == 0 || rest.0 == n) {
            continue;
        }
        // The element between the two runs holds the touchdown.
        let e = pair[0].1;
        let element_length = l.mesh.section(e).element_length;
        let contact = arc[rest.1] - arc[rest.0];
        // The suspended run from the touchdown element to its far end.
        let suspended = arc[hang.1] - arc[hang.0] + element_length;
        let badness = (element_length * TOUCHDOWN_ELEMENTS / suspended)
            .max(element_length / contact.max(Real::MIN_POSITIVE));
        if badness > 1.0 && worst.as_ref().is_none_or(|(b, _)| badness > *b) {
            worst = Some((
                badness,
                Warning::TouchdownUnresolved {
                    line: l.name.clone(),
                    element_length,
                    suspended,
                    contact,
                },
            ));
        }
    }
    worst.map(|(_, w)| w)
}

/// Free points without seabed contact and free bodies whose centre of gravity rests below the
/// seabed.
fn below_seabed(system: &System, y: &[Real], ws: &Workspace, out: &mut Vec<Warning>) {
    let env = &system.environment;
    if !env.has_seabed() {
        return;
    }
    for &p in &system.free_points {
        let point = &system.points[p];
        let position = ws.points[p].position;
        let (z, bed) = (position.z, env.seabed_at(position.x, position.y).z);
        if !point.has_seabed_contact() && z < bed {
            out.push(Warning::BelowSeabed {
                object: format!("point {}", point.name),
                depth: bed - z,
            });
        }
    }
    for &b in &system.free_bodies {
        let o = system.layout.body_offset[b].expect("free body");
        let k = crate::bodies::read_state(&y[o..o + crate::bodies::STATE_LEN]);
        let body = &system.bodies[b].body;
        let cog: Vec3 = k.position + k.orientation * body.centre_of_gravity;
        let bed = env.seabed_at(cog.x, cog.y).z;
        if cog.z < bed {
            out.push(Warning::BelowSeabed {
                object: format!("body {}", body.name),
                depth: bed - cog.z,
            });
        }
    }
}

/// The largest relative difference of `dg` line `li`'s tensions (its two ends and its largest
/// node tension) from its statics twin's, as a warning when above [`DG_TWIN_MISMATCH`].
fn twin_mismatch(
    system: &System,
    ws: &Workspace,
    twin: &System,
    tws: &Workspace,
    li: usize,
) -> Option<Warning> {
    let largest = |s: &System, w: &Workspace| {
        (0..s.lines[li].nodes())
            .map(|i| s.node_tension(w, li, i))
            .fold(0.0, Real::max)
    };
    let twin_largest = largest(twin, tws);
    let places = [
        (
            "end A".to_string(),
            system.end_force(ws, li, false).norm(),
            twin.end_force(tws, li, false).norm(),
        ),
        (
            "end B".to_string(),
            system.end_force(ws, li, true).norm(),
            twin.end_force(tws, li, true).norm(),
        ),
        (
            "its most loaded node".to_string(),
            largest(system, ws),
            twin_largest,
        ),
    ];
    // Relative to the twin's largest tension, so that a slack end does not divide by 0.
    let scale = twin_largest.max(Real::MIN_POSITIVE);
    let (place, dg, twin_t) = places
        .into_iter()
        .max_by(|a, b| (a.1 - a.2).abs().total_cmp(&(b.1 - b.2).abs()))?;
    (!((dg - twin_t).abs() <= DG_TWIN_MISMATCH * scale)).then(|| Warning::DgTwinMismatch {
        line: system.lines[li].name.clone(),
        place,
        dg,
        twin: twin_t,
    })
}
