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
        let n = l.mesh.elements();
        let last = l.vectors() - 1;
        let hermite = matches!(
            l.discretisation,
            crate::formulation::Discretisation::Hermite(_)
        );
        for e in 0..n {
            let s = l.mesh.section(e);
            let k = s.law.stiffness.max_tangent() / s.element_length
                + env.seabed.stiffness * s.line_type.diameter * s.element_length;
            // The vectors the element couples; a cubic element's rows sum to about twice a
            // linear one's, and a tangent's to l² times a position's.
            let vectors: &[usize] = if hermite {
                &crate::formulation::hermite::element_vectors(e, n)
            } else {
                &[e, e + 1]
            };
            for &j in vectors {
                let m = if hermite { 4.0 * k } else { 2.0 * k }
                    * if l.is_tangent(j) {
                        s.element_length * s.element_length
                    } else {
                        1.0
                    };
                if j >= 1 && j < last {
                    mass[o + j - 1] += m;
                } else {
                    let p = if j == 0 { l.end_a } else { l.end_b };
                    if let Some(po) = system.layout.point_offset[p] {
                        mass[po / 3] += m;
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
