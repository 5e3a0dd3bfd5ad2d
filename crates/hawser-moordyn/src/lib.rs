//! A MoorDyn v2 compatible C library: the coupling subset of MoorDyn-C 2.7's `MoorDyn2.h` and
//! `Line.h` with MoorDyn's names, signatures, status codes and conventions, computed by
//! hawser, so that a host built against MoorDyn's library links this one instead
//! (`include/MoorDyn2.h` declares the same functions; docs/c-api.md lists what differs).
//!
//! MoorDyn's conventions kept:
//! - `MoorDyn_Step(x, xd, f, t, dt)`: `x`, `xd` at the start of the interval, held at constant
//!   velocity through it ([`hawser::Session::set_coupled_constant_velocity`]); `*t` becomes
//!   t + dt; `dt` ≤ 0 only returns the forces.
//! - Forces: the net force of the lines' end nodes on each coupled point, without the nodes'
//!   inertia (MoorDyn's `Fnet`); on each coupled body their force and moment about its origin;
//!   on each `CoupledPinned` body (3 entries in `x`, `xd` and `f`: its pin's position, velocity
//!   and force) the force it puts on its pin, F6net − M a over the translations (MoorDyn's
//!   `Body::getFnet`).
//! - A coupled body's angles in `x` are MoorDyn's, R = R_x(r) R_y(p) R_z(y), turned into
//!   hawser's roll, pitch, yaw of the same rotation.
//! - Lines numbered from 1 in `MoorDyn_GetLine`; nodes from 0 (end A) to N (end B).
//! - Status codes `MOORDYN_SUCCESS` (0) and the negative `MOORDYN_*` errors; errors printed on
//!   standard error, as MoorDyn prints them.
#![warn(missing_docs)]
// `!(x > 0.0)` is deliberate: it rejects NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use hawser::math::{Quat, Vec3};
use hawser_capi::guard;
use hawser_capi::host::{Convention, ErrorKind, Host, HostError};
use std::ffi::{CStr, c_char, c_int, c_uint};
use std::path::Path;

/// MoorDyn's status codes (MoorDynAPI.h).
const MOORDYN_SUCCESS: c_int = 0;
const MOORDYN_INVALID_INPUT_FILE: c_int = -1;
const MOORDYN_INVALID_OUTPUT_FILE: c_int = -2;
const MOORDYN_INVALID_INPUT: c_int = -3;
const MOORDYN_NAN_ERROR: c_int = -4;
const MOORDYN_INVALID_VALUE: c_int = -6;
const MOORDYN_UNHANDLED_ERROR: c_int = -255;

/// The system behind a `MoorDyn` handle.
pub struct System {
    host: Host,
    /// One handle per line, 1-based in `MoorDyn_GetLine`; each points back to the system.
    lines: Vec<Line>,
    /// The host's positions with every coupled body's angles in hawser's convention (sized
    /// at creation; the coupled bodies come first, 6 entries each, 3 for a coupled pin).
    x: Vec<f64>,
    /// Offset in `x` of the angles of each coupled body with a pose (not of coupled pins).
    angles: Vec<usize>,
}

impl System {
    /// The host's positions `x` with each coupled body's MoorDyn angles (R = R_x(r) R_y(p)
    /// R_z(y), MoorDyn's `Euler2Quat`) turned into hawser's roll, pitch, yaw of the same
    /// rotation (R = R_z R_y R_x). Angular velocities pass as they are (both global).
    fn hawser_positions(&mut self, x: &[f64]) -> &[f64] {
        self.x.copy_from_slice(x);
        for &o in &self.angles {
            let a = &mut self.x[o..o + 3];
            let q = Quat::from_axis_angle(&Vec3::x_axis(), a[0])
                * Quat::from_axis_angle(&Vec3::y_axis(), a[1])
                * Quat::from_axis_angle(&Vec3::z_axis(), a[2]);
            let (roll, pitch, yaw) = q.euler_angles();
            a.copy_from_slice(&[roll, pitch, yaw]);
        }
        &self.x
    }
}

/// The line behind a `MoorDynLine` handle.
pub struct Line {
    system: *mut System,
    /// Index from 0.
    index: usize,
}

fn code(e: &HostError) -> c_int {
    match e.kind {
        ErrorKind::Input => MOORDYN_INVALID_INPUT_FILE,
        ErrorKind::InvalidArgument | ErrorKind::State | ErrorKind::BufferTooSmall => {
            MOORDYN_INVALID_VALUE
        }
        ErrorKind::Simulation if e.message.contains("not finite") => MOORDYN_NAN_ERROR,
        ErrorKind::Simulation | ErrorKind::Checkpoint => MOORDYN_INVALID_INPUT,
        ErrorKind::Panic => MOORDYN_UNHANDLED_ERROR,
        ErrorKind::Io => MOORDYN_INVALID_OUTPUT_FILE,
    }
}

/// Runs `f` behind the boundary: errors are printed (as MoorDyn does) and kept as the
/// thread's last error of hawser's C ABI; panics are caught.
fn run(function: &str, f: impl FnOnce() -> Result<(), HostError>) -> c_int {
    match guard(f) {
        Ok(()) => MOORDYN_SUCCESS,
        Err(e) => {
            eprintln!("Error in {function} (hawser): {}", e.message);
            hawser_capi::set_error(&e.message);
            code(&e)
        }
    }
}

fn invalid(what: impl Into<String>) -> HostError {
    HostError::new(ErrorKind::InvalidArgument, what)
}

/// # Safety
/// `s` is null or a live handle from `MoorDyn_Create`.
unsafe fn system<'a>(s: *mut System) -> Result<&'a mut System, HostError> {
    // SAFETY: the caller's contract.
    unsafe { s.as_mut() }.ok_or_else(|| invalid("Null system received"))
}

/// # Safety
/// `l` is null or a live handle from `MoorDyn_GetLine`.
unsafe fn line<'a>(l: *mut Line) -> Result<(&'a mut Host, usize), HostError> {
    // SAFETY: the caller's contract.
    let l = unsafe { l.as_ref() }.ok_or_else(|| invalid("Null line received"))?;
    // SAFETY: a line handle lives inside its system, which is live while the handle is.
    let s = unsafe { l.system.as_mut() }.ok_or_else(|| invalid("Null system received"))?;
    Ok((&mut s.host, l.index))
}

/// # Safety
/// `p` is null or points to `n` readable doubles.
unsafe fn slice<'a>(p: *const f64, n: usize, what: &str) -> Result<&'a [f64], HostError> {
    if n == 0 {
        return Ok(&[]);
    }
    if p.is_null() {
        return Err(invalid(format!("Null pointer received for {what}")));
    }
    // SAFETY: the caller's contract.
    Ok(unsafe { std::slice::from_raw_parts(p, n) })
}

/// # Safety
/// `p` is null or points to `n` writable values.
unsafe fn slice_mut<'a, T>(p: *mut T, n: usize, what: &str) -> Result<&'a mut [T], HostError> {
    if n == 0 {
        return Ok(&mut []);
    }
    if p.is_null() {
        return Err(invalid(format!("Null pointer received for {what}")));
    }
    // SAFETY: the caller's contract.
    Ok(unsafe { std::slice::from_raw_parts_mut(p, n) })
}

/// # Safety
/// `p` is null or a NUL-terminated string.
unsafe fn path(p: *const c_char, default: &str) -> Result<&str, HostError> {
    if p.is_null() {
        return Ok(default);
    }
    // SAFETY: the caller's contract.
    let s = unsafe { CStr::from_ptr(p) }
        .to_str()
        .map_err(|_| invalid("the path is not UTF-8"))?;
    Ok(if s.is_empty() { default } else { s })
}

/// Reads the deck (`Mooring/lines.txt` when `infilename` is NULL or empty, as MoorDyn); NULL
/// on an error, printed on standard error.
///
/// # Safety
/// `infilename` is NULL or a NUL-terminated string.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn MoorDyn_Create(infilename: *const c_char) -> *mut System {
    let mut out = std::ptr::null_mut();
    run("MoorDyn_Create", || {
        // SAFETY: the caller's contract.
        let file = unsafe { path(infilename, "Mooring/lines.txt") }?;
        let host = Host::open(Path::new(file))?;
        let n = host.lines();
        let mut angles = Vec::new();
        let mut o = 0;
        for b in &host.model().bodies {
            let n = b.kind.coupled_dofs();
            if n == 6 {
                angles.push(o + 3);
            }
            o += n;
        }
        let s = Box::into_raw(Box::new(System {
            x: vec![0.0; host.coupled_dofs()],
            angles,
            host,
            lines: Vec::with_capacity(n),
        }));
        // SAFETY: `s` was just allocated; the line handles point back to it.
        let sys = unsafe { &mut *s };
        sys.lines
            .extend((0..n).map(|index| Line { system: s, index }));
        out = s;
        Ok(())
    });
    out
}

/// Writes the number of coupled degrees of freedom to `*n`.
///
/// # Safety
/// `system` is a live handle; `n` points to a writable unsigned int.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn MoorDyn_NCoupledDOF(system: *mut System, n: *mut c_uint) -> c_int {
    run("MoorDyn_NCoupledDOF", || {
        // SAFETY: the caller's contract.
        let s = unsafe { self::system(system) }?;
        // SAFETY: the caller's contract.
        unsafe { slice_mut(n, 1, "n") }?[0] = s.host.coupled_dofs() as c_uint;
        Ok(())
    })
}

/// Places the coupled points at `x` and solves the initial condition there (hawser's Newton
/// statics in place of MoorDyn's dynamic relaxation).
///
/// # Safety
/// `system` is a live handle; `x`, `xd` have `MoorDyn_NCoupledDOF` doubles each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn MoorDyn_Init(system: *mut System, x: *const f64, xd: *const f64) -> c_int {
    run("MoorDyn_Init", || {
        // SAFETY: the caller's contract.
        let s = unsafe { self::system(system) }?;
        let n = s.host.coupled_dofs();
        // SAFETY: the caller's contract.
        let (x, xd) = unsafe { (slice(x, n, "x")?, slice(xd, n, "xd")?) };
        let x = s.hawser_positions(x).to_vec();
        s.host.init(&x, xd)
    })
}

/// Advances from `*t` to `*t + *dt` with the coupled points at `x` moving at `xd` from `*t`
/// on, writes the coupled forces to `f` and `*t + *dt` to `*t`. `*t` must be the system's time
/// (or the start of the interval just computed, which is then computed again); `*dt` ≤ 0 only
/// writes the forces.
///
/// # Safety
/// `system` is a live handle; `x`, `xd`, `f` have `MoorDyn_NCoupledDOF` doubles each; `t`
/// and `dt` point to doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn MoorDyn_Step(
    system: *mut System,
    x: *const f64,
    xd: *const f64,
    f: *mut f64,
    t: *mut f64,
    dt: *mut f64,
) -> c_int {
    run("MoorDyn_Step", || {
        // SAFETY: the caller's contract.
        let s = unsafe { self::system(system) }?;
        let n = s.host.coupled_dofs();
        // SAFETY: the caller's contract.
        let (t, dt) = unsafe {
            (
                slice_mut(t, 1, "t")?,
                *slice_mut(dt, 1, "dt")?.first().unwrap_or(&0.0),
            )
        };
        // SAFETY: the caller's contract.
        let f = unsafe { slice_mut(f, n, "f") }?;
        if !(dt > 0.0) {
            return s.host.forces(Convention::Start, f);
        }
        // SAFETY: the caller's contract.
        let (x, xd) = unsafe { (slice(x, n, "x")?, slice(xd, n, "xd")?) };
        s.hawser_positions(x);
        let positions = std::mem::take(&mut s.x);
        let result = s
            .host
            .step(Convention::Start, t[0], dt, &positions, xd, None, f);
        s.x = positions;
        t[0] = result?;
        Ok(())
    })
}

/// Frees the system and its line handles.
///
/// # Safety
/// `system` is a live handle, not used afterwards (nor its lines).
#[unsafe(no_mangle)]
pub unsafe extern "C" fn MoorDyn_Close(system: *mut System) -> c_int {
    run("MoorDyn_Close", || {
        if system.is_null() {
            return Err(invalid("Null system received"));
        }
        // SAFETY: the caller's contract: `system` came from `Box::into_raw` in MoorDyn_Create.
        drop(unsafe { Box::from_raw(system) });
        Ok(())
    })
}

/// Writes the number of lines to `*n`.
///
/// # Safety
/// `system` is a live handle; `n` points to a writable unsigned int.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn MoorDyn_GetNumberLines(system: *mut System, n: *mut c_uint) -> c_int {
    run("MoorDyn_GetNumberLines", || {
        // SAFETY: the caller's contract.
        let s = unsafe { self::system(system) }?;
        // SAFETY: the caller's contract.
        unsafe { slice_mut(n, 1, "n") }?[0] = s.lines.len() as c_uint;
        Ok(())
    })
}

/// The line `l` (from 1 to the number of lines); NULL when out of range.
///
/// # Safety
/// `system` is a live handle.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn MoorDyn_GetLine(system: *mut System, l: c_uint) -> *mut Line {
    let mut out = std::ptr::null_mut();
    run("MoorDyn_GetLine", || {
        // SAFETY: the caller's contract.
        let s = unsafe { self::system(system) }?;
        let n = s.lines.len();
        let i = (l as usize)
            .checked_sub(1)
            .filter(|&i| i < n)
            .ok_or_else(|| invalid(format!("Invalid line index {l}: lines are 1 to {n}")))?;
        out = &mut s.lines[i] as *mut Line;
        Ok(())
    });
    out
}

/// The FAST v7 tensions of the first `*numLines` lines: horizontal and vertical components of
/// the net force of the line on its fairlead (end B) and anchor (end A) nodes [N], as floats.
/// The vertical components are those of that force (MoorDyn also subtracts the node's
/// M₁₁·g from them).
///
/// # Safety
/// `system` is a live handle; the four arrays have `*numLines` writable floats.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn MoorDyn_GetFASTtens(
    system: *mut System,
    num_lines: *const c_int,
    fair_h_ten: *mut f32,
    fair_v_ten: *mut f32,
    anch_h_ten: *mut f32,
    anch_v_ten: *mut f32,
) -> c_int {
    run("MoorDyn_GetFASTtens", || {
        // SAFETY: the caller's contract.
        let s = unsafe { self::system(system) }?;
        // SAFETY: the caller's contract.
        let n = unsafe { num_lines.as_ref() }.ok_or_else(|| invalid("Null numLines"))?;
        let n = usize::try_from(*n).map_err(|_| invalid(format!("numLines = {n}")))?;
        if n > s.lines.len() {
            return Err(invalid(format!("There is not {n} lines")));
        }
        // SAFETY: the caller's contract.
        let (fh, fv, ah, av) = unsafe {
            (
                slice_mut(fair_h_ten, n, "FairHTen")?,
                slice_mut(fair_v_ten, n, "FairVTen")?,
                slice_mut(anch_h_ten, n, "AnchHTen")?,
                slice_mut(anch_v_ten, n, "AnchVTen")?,
            )
        };
        for l in 0..n {
            let fb = s.host.end_node_force(l, true)?;
            let fa = s.host.end_node_force(l, false)?;
            fh[l] = fb.xy().norm() as f32;
            fv[l] = fb.z as f32;
            ah[l] = fa.xy().norm() as f32;
            av[l] = fa.z as f32;
        }
        Ok(())
    })
}

/// Writes the line's number (its deck ID order, from 1) to `*id`.
///
/// # Safety
/// `l` is a live line handle; `id` points to a writable int.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn MoorDyn_GetLineID(l: *mut Line, id: *mut c_int) -> c_int {
    run("MoorDyn_GetLineID", || {
        // SAFETY: the caller's contract.
        let (_, i) = unsafe { line(l) }?;
        // SAFETY: the caller's contract.
        unsafe { slice_mut(id, 1, "id") }?[0] = (i + 1) as c_int;
        Ok(())
    })
}

/// Writes the number of segments to `*n`.
///
/// # Safety
/// `l` is a live line handle; `n` points to a writable unsigned int.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn MoorDyn_GetLineN(l: *mut Line, n: *mut c_uint) -> c_int {
    run("MoorDyn_GetLineN", || {
        // SAFETY: the caller's contract.
        let (h, i) = unsafe { line(l) }?;
        let nodes = h.line_nodes(i)?;
        // SAFETY: the caller's contract.
        unsafe { slice_mut(n, 1, "n") }?[0] = (nodes - 1) as c_uint;
        Ok(())
    })
}

/// Writes the number of nodes (segments + 1) to `*n`.
///
/// # Safety
/// `l` is a live line handle; `n` points to a writable unsigned int.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn MoorDyn_GetLineNumberNodes(l: *mut Line, n: *mut c_uint) -> c_int {
    run("MoorDyn_GetLineNumberNodes", || {
        // SAFETY: the caller's contract.
        let (h, i) = unsafe { line(l) }?;
        let nodes = h.line_nodes(i)?;
        // SAFETY: the caller's contract.
        unsafe { slice_mut(n, 1, "n") }?[0] = nodes as c_uint;
        Ok(())
    })
}

/// Writes the position [m] of node `i` (0 at end A) to `pos`.
///
/// # Safety
/// `l` is a live line handle; `pos` has 3 writable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn MoorDyn_GetLineNodePos(l: *mut Line, i: c_uint, pos: *mut f64) -> c_int {
    run("MoorDyn_GetLineNodePos", || {
        // SAFETY: the caller's contract.
        let (h, li) = unsafe { line(l) }?;
        let nodes = h.line_nodes(li)?;
        let i = node_index(i, nodes, li)?;
        let mut all = vec![0.0; 3 * nodes];
        h.line_samples(li, true, &mut all)?;
        // SAFETY: the caller's contract.
        unsafe { slice_mut(pos, 3, "pos") }?.copy_from_slice(&all[3 * i..3 * i + 3]);
        Ok(())
    })
}

fn node_index(i: c_uint, nodes: usize, line: usize) -> Result<usize, HostError> {
    let i = i as usize;
    if i >= nodes {
        return Err(invalid(format!(
            "Asking node {i} of line {}, which only has {nodes} nodes",
            line + 1
        )));
    }
    Ok(i)
}

/// Writes the tension vector [N] at node `i`: the magnitude of hawser's node tension (the
/// mean of the adjacent segments' inside, the end force's at an end) along the line's
/// direction there (the chord of the neighbouring nodes; from node N−1 to N at end B, from
/// node 0 to 1 at end A, as MoorDyn's segment tension vectors point).
///
/// # Safety
/// `l` is a live line handle; `t` has 3 writable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn MoorDyn_GetLineNodeTen(l: *mut Line, i: c_uint, t: *mut f64) -> c_int {
    run("MoorDyn_GetLineNodeTen", || {
        // SAFETY: the caller's contract.
        let (h, li) = unsafe { line(l) }?;
        let nodes = h.line_nodes(li)?;
        let i = node_index(i, nodes, li)?;
        let mut x = vec![0.0; 3 * nodes];
        let mut tension = vec![0.0; nodes];
        h.line_samples(li, true, &mut x)?;
        h.line_samples(li, false, &mut tension)?;
        let (a, b) = (i.saturating_sub(1), (i + 1).min(nodes - 1));
        let chord = hawser::math::Vec3::from_fn(|k, _| x[3 * b + k] - x[3 * a + k]);
        let dir = chord / chord.norm();
        // SAFETY: the caller's contract.
        unsafe { slice_mut(t, 3, "t") }?.copy_from_slice((dir * tension[i]).as_slice());
        Ok(())
    })
}

/// Writes the net force [N] on node `i` at an end (the line's force on the end node without
/// its inertia, MoorDyn's `Fnet`); inside the line, the node tension vector (hawser does not
/// keep interior nodes' net forces).
///
/// # Safety
/// `l` is a live line handle; `f` has 3 writable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn MoorDyn_GetLineNodeForce(l: *mut Line, i: c_uint, f: *mut f64) -> c_int {
    run("MoorDyn_GetLineNodeForce", || {
        // SAFETY: the caller's contract.
        let (h, li) = unsafe { line(l) }?;
        let nodes = h.line_nodes(li)?;
        let i = node_index(i, nodes, li)?;
        if i != 0 && i != nodes - 1 {
            return Err(HostError::new(
                ErrorKind::InvalidArgument,
                format!(
                    "hawser gives the net force of end nodes only (0 and {}), not of node {i}",
                    nodes - 1
                ),
            ));
        }
        let v = h.end_node_force(li, i != 0)?;
        // SAFETY: the caller's contract.
        unsafe { slice_mut(f, 3, "f") }?.copy_from_slice(v.as_slice());
        Ok(())
    })
}

/// Writes the tension at the fairlead (end B) [N] to `*t`: hawser's tension at the end node
/// (the magnitude of the line's force on its attachment). MoorDyn gives the end segment's
/// tension here; the two differ by the end node's share of weight, drag and inertia.
///
/// # Safety
/// `l` is a live line handle; `t` points to a writable double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn MoorDyn_GetLineFairTen(l: *mut Line, t: *mut f64) -> c_int {
    run("MoorDyn_GetLineFairTen", || {
        // SAFETY: the caller's contract.
        let (h, li) = unsafe { line(l) }?;
        let nodes = h.line_nodes(li)?;
        let mut tension = vec![0.0; nodes];
        h.line_samples(li, false, &mut tension)?;
        // SAFETY: the caller's contract.
        unsafe { slice_mut(t, 1, "t") }?[0] = tension[nodes - 1];
        Ok(())
    })
}

/// Saves the system's state to `filepath` (hawser's checkpoint format, not MoorDyn's: a file
/// written by one library is refused by the other).
///
/// # Safety
/// `system` is a live handle; `filepath` is a NUL-terminated string.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn MoorDyn_SaveState(system: *mut System, filepath: *const c_char) -> c_int {
    run("MoorDyn_SaveState", || {
        // SAFETY: the caller's contract.
        let s = unsafe { self::system(system) }?;
        // SAFETY: the caller's contract.
        let file = unsafe { path(filepath, "") }?;
        let bytes = s.host.checkpoint()?;
        std::fs::write(file, bytes).map_err(|e| {
            HostError::new(
                ErrorKind::Io,
                format!("cannot write the state file {file}: {e}"),
            )
        })
    })
}

/// Loads a state saved by `MoorDyn_SaveState` from a system of the same deck and sets it.
///
/// # Safety
/// `system` is a live handle; `filepath` is a NUL-terminated string.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn MoorDyn_LoadState(system: *mut System, filepath: *const c_char) -> c_int {
    run("MoorDyn_LoadState", || {
        // SAFETY: the caller's contract.
        let s = unsafe { self::system(system) }?;
        // SAFETY: the caller's contract.
        let file = unsafe { path(filepath, "") }?;
        let bytes = std::fs::read(file).map_err(|e| {
            HostError::new(
                ErrorKind::Input,
                format!("cannot read the state file {file}: {e}"),
            )
        })?;
        s.host.restore(&bytes)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// OC3's lines on the points of a coupled body at the origin (MoorDyn's `Body1` points).
    const BODY_DECK: &str = "\
--- LINE TYPES ---
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
main 0.09 77.7066 384.243E6 -0.8 0 1.6 1.0 0.1 0.0
--- BODIES ---
ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG I Volume CdA Ca
1 Coupled 0 0 0 0 0 0 0 0 0 0 0 0
--- POINTS ---
ID Type X Y Z Mass Volume CdA Ca
1 Fixed 853.87 0 -320.0 0 0 0 0
2 Fixed -426.94 739.47 -320.0 0 0 0 0
3 Fixed -426.94 -739.47 -320.0 0 0 0 0
4 Body1 5.2 0.0 -70.0 0 0 0 0
5 Body1 -2.6 4.5 -70.0 0 0 0 0
6 Body1 -2.6 -4.5 -70.0 0 0 0 0
--- LINES ---
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
1 main 1 4 902.2 20 -
2 main 2 5 902.2 20 -
3 main 3 6 902.2 20 -
--- OPTIONS ---
0.002 dtM
320 WtrDpth
--- need this line ---
";

    /// A coupled body's angles from the host are MoorDyn's, R = R_x(r) R_y(p) R_z(y): after
    /// `MoorDyn_Init` and a step the body has that rotation (round-off), and six coupled
    /// degrees of freedom come first.
    #[test]
    fn coupled_body_angles_are_moordyns() {
        let dir = std::env::temp_dir().join(format!("hawser-moordyn-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let deck = dir.join("body.txt");
        std::fs::write(&deck, BODY_DECK).unwrap();
        let name = std::ffi::CString::new(deck.to_str().unwrap()).unwrap();
        let (r, p, y) = (0.05, -0.03, 0.4);
        let x = [1.0, -2.0, 0.5, r, p, y];
        let xd = [0.0; 6];
        let expected = Quat::from_axis_angle(&Vec3::x_axis(), r)
            * Quat::from_axis_angle(&Vec3::y_axis(), p)
            * Quat::from_axis_angle(&Vec3::z_axis(), y);
        // SAFETY: the handles come from MoorDyn_Create and live until MoorDyn_Close; the
        // arrays have NCoupledDOF = 6 entries.
        unsafe {
            let s = MoorDyn_Create(name.as_ptr());
            assert!(!s.is_null());
            let mut n: c_uint = 0;
            assert_eq!(MoorDyn_NCoupledDOF(s, &mut n), MOORDYN_SUCCESS);
            assert_eq!(n, 6);
            assert_eq!(MoorDyn_Init(s, x.as_ptr(), xd.as_ptr()), MOORDYN_SUCCESS);
            let (mut t, mut dt, mut f) = (0.0, 0.01, [0.0; 6]);
            assert_eq!(
                MoorDyn_Step(s, x.as_ptr(), xd.as_ptr(), f.as_mut_ptr(), &mut t, &mut dt),
                MOORDYN_SUCCESS
            );
            let session = (*s).host.session().unwrap();
            let b = session.coupled_bodies()[0];
            let k = &session.workspace().bodies[b];
            assert!(k.orientation.angle_to(&expected) < 1e-12);
            assert!((k.position - Vec3::new(1.0, -2.0, 0.5)).norm() < 1e-12);
            // The lines pull the body down and hold it: a vertical force of about three
            // fairleads' weight.
            assert!(f[2] < -1e6, "{f:?}");
            assert_eq!(MoorDyn_Close(s), MOORDYN_SUCCESS);
        }
        std::fs::remove_dir_all(&dir).ok();
    }
}
