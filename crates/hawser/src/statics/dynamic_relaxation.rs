//! Dynamic relaxation with kinetic damping (Barnes): the fallback of Newton statics.
//!
//! Each unknown node moves under its static residual with a fictitious mass proportional to
//! its stiffness, m_i = 2 Σ k (Gershgorin bound for a unit step), so all nodes converge at
//! similar rates; the velocities are reset whenever the kinetic energy peaks.

use super::newton::{effective_tolerance, residual};
use crate::math::{Real, get3, set3};
use crate::system::{System, Workspace};

/// Relaxes the positions in `y` toward equilibrium; returns the final largest imbalance [N].
pub fn relax(system: &System, y: &mut [Real], tol: Real, ws: &mut Workspace) -> Real {
    let len = y.len();
    let mut r = vec![0.0; len];
    let mut vel = vec![0.0; len];
    // Fictitious nodal masses from the axial and seabed stiffness of adjacent elements.
    let mut mass = vec![0.0; len / 3];
    let env = &system.environment;
    for (li, l) in system.lines.iter().enumerate() {
        let o = system.layout.line_offset[li] / 3;
        let n = l.fe.elements();
        for e in 0..n {
            let s = &l.fe.sections[l.fe.element_section[e]];
            let k = s.law.stiffness.max_tangent() / s.element_length
                + env.seabed.stiffness * s.line_type.diameter * s.element_length;
            for node in [e, e + 1] {
                if node >= 1 && node < n {
                    mass[o + node - 1] += 2.0 * k;
                } else {
                    let p = if node == 0 { l.end_a } else { l.end_b };
                    if let Some(po) = system.layout.point_offset[p] {
                        mass[po / 3] += 2.0 * k;
                    }
                }
            }
        }
    }
    let mut last_ke = 0.0;
    let mut norm = Real::INFINITY;
    for _ in 0..200_000 {
        let (n, _) = residual(system, y, 1.0, ws, &mut r);
        norm = n;
        if !(norm > effective_tolerance(tol, ws)) {
            break;
        }
        let mut ke = 0.0;
        for i in 0..len / 3 {
            if mass[i] == 0.0 {
                continue;
            }
            let v = get3(&vel, i) + get3(&r, i) / mass[i];
            ke += mass[i] * v.norm_squared();
            set3(&mut vel, i, &v);
        }
        if ke < last_ke {
            vel.iter_mut().for_each(|v| *v = 0.0);
            last_ke = 0.0;
            continue;
        }
        last_ke = ke;
        for i in 0..len / 3 {
            let p = get3(y, i) + get3(&vel, i);
            set3(y, i, &p);
        }
    }
    norm
}
