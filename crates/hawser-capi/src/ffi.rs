//! The `hawser_*` C functions. Every function returns a [`HawserStatus`]; on an error the
//! message is kept for the calling thread ([`hawser_last_error`]). No panic crosses the
//! boundary: each body runs inside `catch_unwind`, and a panic is returned as
//! [`HawserStatus::Panic`] with its message.
//!
//! Arrays of coupled kinematics and forces have [`hawser_coupled_dofs`] entries, per coupled
//! body x, y, z [m], roll, pitch, yaw [rad] (velocities [m/s], angular velocities [rad/s] about
//! the global axes; forces [N], moments about the body origin [N·m]) or, per body on a coupled
//! pin, its pin's x, y, z only (velocity [m/s]; force: the one the body puts on its pin [N]),
//! in input order (MoorDyn's layout for `CoupledPinned` bodies), then per coupled point x, y,
//! z. Lines and points are numbered from 0 in input order.

use crate::host::{Convention, ErrorKind, Host, HostError};
use crate::{clear_error, guard, set_error};
use std::ffi::{CStr, c_char, c_int};
use std::path::Path;

/// Status of every `hawser_*` call: 0 on success, a negative code otherwise
/// ([`hawser_last_error`] has the message).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HawserStatus {
    /// Success.
    Ok = 0,
    /// A null pointer, an index out of range, an array of the wrong length.
    InvalidArgument = -1,
    /// The scenario or deck could not be read or is invalid (the message names file, line,
    /// key, value and a hint).
    InputError = -2,
    /// The statics, a step or the coupling failed (divergence with time, line and node;
    /// kinematics that are not finite; an interval that does not start at the session's time).
    SimulationError = -3,
    /// Called out of order: a step or query before `hawser_init`, a second `hawser_init`.
    StateError = -4,
    /// A checkpoint of another model, of another format version, or damaged.
    CheckpointError = -5,
    /// The caller's buffer is too small; the size needed was written.
    BufferTooSmall = -6,
    /// A panic inside hawser (a bug: please report the message).
    Panic = -7,
    /// A file could not be written.
    IoError = -8,
}

impl From<ErrorKind> for HawserStatus {
    fn from(k: ErrorKind) -> Self {
        match k {
            ErrorKind::InvalidArgument => Self::InvalidArgument,
            ErrorKind::Input => Self::InputError,
            ErrorKind::Simulation => Self::SimulationError,
            ErrorKind::State => Self::StateError,
            ErrorKind::Checkpoint => Self::CheckpointError,
            ErrorKind::BufferTooSmall => Self::BufferTooSmall,
            ErrorKind::Panic => Self::Panic,
            ErrorKind::Io => Self::IoError,
        }
    }
}

/// A run driven by a host: created from an input file, initialised with the coupled
/// kinematics, stepped, queried, checkpointed, closed. One thread at a time may use a
/// session; different sessions may run on different threads.
pub struct HawserSession {
    host: Host,
}

fn status(f: impl FnOnce() -> Result<(), HostError>) -> HawserStatus {
    match guard(f) {
        Ok(()) => {
            clear_error();
            HawserStatus::Ok
        }
        Err(e) => {
            set_error(&e.message);
            e.kind.into()
        }
    }
}

fn invalid(what: &str) -> HostError {
    HostError::new(ErrorKind::InvalidArgument, what)
}

/// The session behind a pointer.
///
/// # Safety
/// `s` is null or a pointer from `hawser_create` not yet closed, used by one thread at a time.
unsafe fn session<'a>(s: *mut HawserSession) -> Result<&'a mut Host, HostError> {
    // SAFETY: the caller's contract.
    unsafe { s.as_mut() }
        .map(|s| &mut s.host)
        .ok_or_else(|| invalid("the session pointer is null"))
}

/// `n` numbers at `p` (null allowed when `n` is 0).
///
/// # Safety
/// `p` is null or points to `n` readable doubles.
unsafe fn input<'a>(p: *const f64, n: usize, what: &str) -> Result<&'a [f64], HostError> {
    if n == 0 {
        return Ok(&[]);
    }
    if p.is_null() {
        return Err(invalid(&format!("{what} is null")));
    }
    // SAFETY: the caller's contract.
    Ok(unsafe { std::slice::from_raw_parts(p, n) })
}

/// `n` writable numbers at `p` (null allowed when `n` is 0).
///
/// # Safety
/// `p` is null or points to `n` writable doubles.
unsafe fn output<'a>(p: *mut f64, n: usize, what: &str) -> Result<&'a mut [f64], HostError> {
    if n == 0 {
        return Ok(&mut []);
    }
    if p.is_null() {
        return Err(invalid(&format!("{what} is null")));
    }
    // SAFETY: the caller's contract.
    Ok(unsafe { std::slice::from_raw_parts_mut(p, n) })
}

/// # Safety
/// `p` is null or points to a writable `T`.
unsafe fn put<T>(p: *mut T, value: T, what: &str) -> Result<(), HostError> {
    // SAFETY: the caller's contract.
    let r = unsafe { p.as_mut() }.ok_or_else(|| invalid(&format!("{what} is null")))?;
    *r = value;
    Ok(())
}

/// Reads a hawser scenario (TOML) or a MoorDyn v2 deck at `path` (UTF-8) and writes a new
/// session to `*out` (NULL on an error). A deck's `Coupled`/`Vessel` points are the host's
/// coupled points. Nothing is solved yet: call [`hawser_init`].
///
/// # Safety
/// `path` is a NUL-terminated string; `out` points to a writable pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hawser_create(
    path: *const c_char,
    out: *mut *mut HawserSession,
) -> HawserStatus {
    status(|| {
        // SAFETY: the caller's contract.
        let out = unsafe { out.as_mut() }.ok_or_else(|| invalid("the output pointer is null"))?;
        *out = std::ptr::null_mut();
        if path.is_null() {
            return Err(invalid("the path is null"));
        }
        // SAFETY: the caller's contract.
        let path = unsafe { CStr::from_ptr(path) }
            .to_str()
            .map_err(|_| invalid("the path is not UTF-8"))?;
        let host = Host::open(Path::new(path))?;
        *out = Box::into_raw(Box::new(HawserSession { host }));
        Ok(())
    })
}

/// Writes the number of coupled degrees of freedom to `*n`: 6 per coupled body, then 3 per
/// coupled point (MoorDyn's layout).
///
/// # Safety
/// `s` is a live session; `n` points to a writable size.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hawser_coupled_dofs(s: *mut HawserSession, n: *mut usize) -> HawserStatus {
    status(|| {
        // SAFETY: the caller's contract.
        let h = unsafe { session(s) }?;
        // SAFETY: the caller's contract.
        unsafe { put(n, h.coupled_dofs(), "n") }
    })
}

/// Places the coupled objects at `x`, solves the static equilibrium there, and sets their
/// initial velocities `xd` (arrays of [`hawser_coupled_dofs`] entries; NULL when there are
/// none).
///
/// # Safety
/// `s` is a live session; `x` and `xd` point to [`hawser_coupled_dofs`] doubles each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hawser_init(
    s: *mut HawserSession,
    x: *const f64,
    xd: *const f64,
) -> HawserStatus {
    status(|| {
        // SAFETY: the caller's contract.
        let h = unsafe { session(s) }?;
        let n = h.coupled_dofs();
        // SAFETY: the caller's contract.
        let (x, xd) = unsafe { (input(x, n, "x")?, input(xd, n, "xd")?) };
        h.init(x, xd)
    })
}

/// Computes the coupling interval [t, t + dt] [s]: `x`, `xd` (and `xdd`, accelerations, or
/// NULL) are the coupled objects' kinematics at its end, t + dt; inside it they follow the
/// cubic Hermite interpolant of the kinematics at both ends (quintic with accelerations at
/// both). `t` is the session's time, or the start of the interval just computed to compute it
/// again with corrected kinematics (the session goes back to t). Writes the loads of the
/// lines on the coupled objects at t + dt into `forces`: for a point the force of its lines'
/// ends, each the end node's share of the line's forces less its share of the line's inertia
/// [N]; for a body the force and moment about its origin.
///
/// # Safety
/// `s` is a live session; the arrays have [`hawser_coupled_dofs`] doubles each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hawser_step(
    s: *mut HawserSession,
    t: f64,
    dt: f64,
    x: *const f64,
    xd: *const f64,
    xdd: *const f64,
    forces: *mut f64,
) -> HawserStatus {
    status(|| {
        // SAFETY: the caller's contract.
        let h = unsafe { session(s) }?;
        let n = h.coupled_dofs();
        // SAFETY: the caller's contract.
        let (x, xd, f) = unsafe {
            (
                input(x, n, "x")?,
                input(xd, n, "xd")?,
                output(forces, n, "forces")?,
            )
        };
        let xdd = if xdd.is_null() {
            None
        } else {
            // SAFETY: the caller's contract.
            Some(unsafe { input(xdd, n, "xdd") }?)
        };
        h.step(Convention::End, t, dt, x, xd, xdd, f).map(|_| ())
    })
}

/// Writes the loads on the coupled objects at the session's time into `forces`, as
/// [`hawser_step`] does.
///
/// # Safety
/// `s` is a live session; `forces` has [`hawser_coupled_dofs`] doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hawser_forces(s: *mut HawserSession, forces: *mut f64) -> HawserStatus {
    status(|| {
        // SAFETY: the caller's contract.
        let h = unsafe { session(s) }?;
        let n = h.coupled_dofs();
        // SAFETY: the caller's contract.
        let f = unsafe { output(forces, n, "forces") }?;
        h.forces(Convention::End, f)
    })
}

/// Writes the session's simulated time [s] to `*t`.
///
/// # Safety
/// `s` is a live session; `t` points to a writable double.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hawser_time(s: *mut HawserSession, t: *mut f64) -> HawserStatus {
    status(|| {
        // SAFETY: the caller's contract.
        let h = unsafe { session(s) }?;
        let now = h.session()?.time();
        // SAFETY: the caller's contract.
        unsafe { put(t, now, "t") }
    })
}

/// Writes the number of lines to `*n`.
///
/// # Safety
/// `s` is a live session; `n` points to a writable size.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hawser_line_count(s: *mut HawserSession, n: *mut usize) -> HawserStatus {
    status(|| {
        // SAFETY: the caller's contract.
        let h = unsafe { session(s) }?;
        // SAFETY: the caller's contract.
        unsafe { put(n, h.lines(), "n") }
    })
}

/// Writes the number of nodes of line `line` to `*n` (after [`hawser_init`]).
///
/// # Safety
/// `s` is a live session; `n` points to a writable size.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hawser_line_node_count(
    s: *mut HawserSession,
    line: usize,
    n: *mut usize,
) -> HawserStatus {
    status(|| {
        // SAFETY: the caller's contract.
        let h = unsafe { session(s) }?;
        let nodes = h.line_nodes(line)?;
        // SAFETY: the caller's contract.
        unsafe { put(n, nodes, "n") }
    })
}

/// Writes the effective tension [N] at every node of line `line`, end A to end B, into
/// `tensions` (`len` = the node count): the mean of the adjacent elements' tensions inside,
/// the magnitude of the end force at the ends.
///
/// # Safety
/// `s` is a live session; `tensions` has `len` writable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hawser_line_tensions(
    s: *mut HawserSession,
    line: usize,
    tensions: *mut f64,
    len: usize,
) -> HawserStatus {
    status(|| {
        // SAFETY: the caller's contract.
        let h = unsafe { session(s) }?;
        // SAFETY: the caller's contract.
        let out = unsafe { output(tensions, len, "tensions") }?;
        h.line_samples(line, false, out)
    })
}

/// Writes x, y, z [m] of every node of line `line`, end A to end B, into `positions`
/// (`len` = 3 × the node count).
///
/// # Safety
/// `s` is a live session; `positions` has `len` writable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hawser_line_node_positions(
    s: *mut HawserSession,
    line: usize,
    positions: *mut f64,
    len: usize,
) -> HawserStatus {
    status(|| {
        // SAFETY: the caller's contract.
        let h = unsafe { session(s) }?;
        // SAFETY: the caller's contract.
        let out = unsafe { output(positions, len, "positions") }?;
        h.line_samples(line, true, out)
    })
}

/// Writes the force [N] line `line` exerts on the attachment of its end B (`end_b` ≠ 0) or
/// A into `force[3]` (the reaction [`hawser_step`] sums), and the net force of the line on its
/// end node without the node's inertia into `node_force[3]` (MoorDyn's `Fnet`; its magnitude
/// is the `FairTen`/`AnchTen` channel). Either may be NULL.
///
/// # Safety
/// `s` is a live session; `force` and `node_force` are NULL or have 3 writable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hawser_line_end_force(
    s: *mut HawserSession,
    line: usize,
    end_b: c_int,
    force: *mut f64,
    node_force: *mut f64,
) -> HawserStatus {
    status(|| {
        // SAFETY: the caller's contract.
        let h = unsafe { session(s) }?;
        let reaction = h.end_force(line, end_b != 0)?;
        let net = h.end_node_force(line, end_b != 0)?;
        for (p, v) in [(force, reaction), (node_force, net)] {
            if !p.is_null() {
                // SAFETY: the caller's contract.
                unsafe { output(p, 3, "force") }?.copy_from_slice(v.as_slice());
            }
        }
        Ok(())
    })
}

/// Writes the number of points to `*n`.
///
/// # Safety
/// `s` is a live session; `n` points to a writable size.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hawser_point_count(s: *mut HawserSession, n: *mut usize) -> HawserStatus {
    status(|| {
        // SAFETY: the caller's contract.
        let h = unsafe { session(s) }?;
        // SAFETY: the caller's contract.
        unsafe { put(n, h.points(), "n") }
    })
}

/// Writes the position [m] of point `point` into `position[3]` and the force of the lines
/// attached to it [N] into `force[3]`. Either may be NULL.
///
/// # Safety
/// `s` is a live session; `position` and `force` are NULL or have 3 writable doubles.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hawser_point(
    s: *mut HawserSession,
    point: usize,
    position: *mut f64,
    force: *mut f64,
) -> HawserStatus {
    status(|| {
        // SAFETY: the caller's contract.
        let h = unsafe { session(s) }?;
        let (x, f) = h.point(point)?;
        for (p, v) in [(position, x), (force, f)] {
            if !p.is_null() {
                // SAFETY: the caller's contract.
                unsafe { output(p, 3, "output") }?.copy_from_slice(v.as_slice());
            }
        }
        Ok(())
    })
}

/// Saves the session to bytes: writes their number to `*len`, and the bytes to `buffer`
/// when it holds `capacity` ≥ `*len` bytes. Call it with `buffer` NULL to learn the size
/// (status OK); a buffer too small gives [`HawserStatus::BufferTooSmall`].
///
/// # Safety
/// `s` is a live session; `buffer` is NULL or has `capacity` writable bytes; `len` points to
/// a writable size.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hawser_checkpoint_save(
    s: *mut HawserSession,
    buffer: *mut u8,
    capacity: usize,
    len: *mut usize,
) -> HawserStatus {
    status(|| {
        // SAFETY: the caller's contract.
        let h = unsafe { session(s) }?;
        let bytes = h.checkpoint()?;
        // SAFETY: the caller's contract.
        unsafe { put(len, bytes.len(), "len") }?;
        if buffer.is_null() {
            return Ok(());
        }
        if capacity < bytes.len() {
            return Err(HostError::new(
                ErrorKind::BufferTooSmall,
                format!(
                    "the checkpoint has {} bytes and the buffer {capacity}",
                    bytes.len()
                ),
            ));
        }
        // SAFETY: the caller's contract; the two do not overlap (`bytes` is ours).
        unsafe { std::ptr::copy_nonoverlapping(bytes.as_ptr(), buffer, bytes.len()) };
        Ok(())
    })
}

/// Continues the session from `len` bytes saved by [`hawser_checkpoint_save`] from a session
/// of the same input (initialised with the same positions). It may be called before or
/// after [`hawser_init`]; it replaces the run in progress.
///
/// # Safety
/// `s` is a live session; `buffer` has `len` readable bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hawser_checkpoint_load(
    s: *mut HawserSession,
    buffer: *const u8,
    len: usize,
) -> HawserStatus {
    status(|| {
        // SAFETY: the caller's contract.
        let h = unsafe { session(s) }?;
        if buffer.is_null() {
            return Err(invalid("the buffer is null"));
        }
        // SAFETY: the caller's contract.
        let bytes = unsafe { std::slice::from_raw_parts(buffer, len) };
        h.restore(bytes)
    })
}

/// Frees the session (NULL is allowed and does nothing).
///
/// # Safety
/// `s` is NULL or a live session, not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn hawser_close(s: *mut HawserSession) -> HawserStatus {
    status(|| {
        if !s.is_null() {
            // SAFETY: the caller's contract: `s` came from `Box::into_raw` in hawser_create.
            drop(unsafe { Box::from_raw(s) });
        }
        Ok(())
    })
}

/// The message of the last failed `hawser_*` call on this thread ("" after a successful
/// one). The string stays valid until the next `hawser_*` call on this thread.
#[unsafe(no_mangle)]
pub extern "C" fn hawser_last_error() -> *const c_char {
    crate::last_error_ptr()
}

/// hawser's version, "0.1.0".
#[unsafe(no_mangle)]
pub extern "C" fn hawser_version() -> *const c_char {
    concat!(env!("CARGO_PKG_VERSION"), "\0").as_ptr().cast()
}
