//! Checkpoints: a session saved to bytes and restored, so that a run can stop and resume
//! bit for bit, a host can save and load its mooring state (MoorDyn_SaveState /
//! MoorDyn_LoadState), and a Python session can be pickled.
//!
//! Format (little-endian): the magic `HAWSERCK`, the format version (u32), the model's hash
//! ([`model_hash`], u64), then the run: samples taken and the last sample time, the clock, the
//! stability limit and what sets it, the state vector, the scheme's history (the three-level
//! scheme's previous level and last step; generalized-α's accelerations, step controller,
//! Jacobian and, from version 4, its counts of steps, iterations and Jacobians), the line
//! failures' releases (version 2), `scheme = "auto"`'s switching between generalized-α and
//! RK4 (version 3), the coupling tracks and interval, and the saved start of
//! the coupling interval. Every number is stored exactly (f64 bits), so a restored run steps exactly as the
//! saved one would have. A checkpoint of another model, of another format version or a
//! truncated one is refused with [`SimulationError::Checkpoint`].

use super::stepper::{Clock, Saved};
use super::{Session, SessionOptions};
use crate::error::SimulationError;
use crate::integrate::choice::SchemeSwitch;
use crate::math::{Real, Vec3, quat_from_coords};
use crate::model::{BodyTrack, Model, PointTrack};
use crate::system::CouplingTracks;

const MAGIC: &[u8; 8] = b"HAWSERCK";
/// The checkpoint format version this build writes and reads.
pub const CHECKPOINT_VERSION: u32 = 4;

/// FNV-1a (64 bits) of `bytes`: stable across platforms and Rust versions.
pub fn fnv1a(bytes: &[u8]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in bytes {
        h ^= *b as u64;
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

/// A hash of everything in a model (its `Debug` form, which prints every number in its
/// shortest exact form): equal for equal models, different when any key differs.
pub fn model_hash(model: &Model) -> u64 {
    fnv1a(format!("{model:?}").as_bytes())
}

/// Appends numbers to a byte buffer (the checkpoint codec).
#[derive(Default)]
pub struct Encoder {
    /// The bytes so far.
    pub bytes: Vec<u8>,
}

impl Encoder {
    /// A u64.
    pub fn u64(&mut self, x: u64) {
        self.bytes.extend_from_slice(&x.to_le_bytes());
    }
    /// An f64, exactly.
    pub fn f64(&mut self, x: Real) {
        self.u64(x.to_bits());
    }
    /// A bool.
    pub fn bool(&mut self, x: bool) {
        self.bytes.push(x as u8);
    }
    /// A slice of f64 with its length.
    pub fn f64s(&mut self, x: &[Real]) {
        self.u64(x.len() as u64);
        x.iter().for_each(|&v| self.f64(v));
    }
    /// A 3-vector.
    pub fn vec3(&mut self, v: &Vec3) {
        v.iter().for_each(|&x| self.f64(x));
    }
    /// An optional 3-vector.
    pub fn opt_vec3(&mut self, v: &Option<Vec3>) {
        self.bool(v.is_some());
        self.vec3(&v.unwrap_or_else(Vec3::zeros));
    }
    /// A string with its length.
    pub fn str(&mut self, s: &str) {
        self.u64(s.len() as u64);
        self.bytes.extend_from_slice(s.as_bytes());
    }
}

/// Reads what an [`Encoder`] wrote; every read checks the length left.
pub struct Decoder<'a> {
    bytes: &'a [u8],
}

fn truncated() -> SimulationError {
    SimulationError::Checkpoint {
        what: "the checkpoint is truncated or corrupt (it ends before its contents do)".into(),
    }
}

impl<'a> Decoder<'a> {
    /// A decoder over `bytes`.
    pub fn new(bytes: &'a [u8]) -> Self {
        Self { bytes }
    }
    fn take(&mut self, n: usize) -> Result<&'a [u8], SimulationError> {
        if self.bytes.len() < n {
            return Err(truncated());
        }
        let (a, b) = self.bytes.split_at(n);
        self.bytes = b;
        Ok(a)
    }
    /// A u64.
    pub fn u64(&mut self) -> Result<u64, SimulationError> {
        let b = self.take(8)?;
        Ok(u64::from_le_bytes(b.try_into().expect("8 bytes")))
    }
    /// An f64.
    pub fn f64(&mut self) -> Result<Real, SimulationError> {
        Ok(Real::from_bits(self.u64()?))
    }
    /// A bool.
    pub fn bool(&mut self) -> Result<bool, SimulationError> {
        Ok(self.take(1)?[0] != 0)
    }
    /// A slice of f64 (length first), checked against the bytes left.
    pub fn f64s(&mut self) -> Result<Vec<Real>, SimulationError> {
        let n = self.u64()? as usize;
        if n > self.bytes.len() / 8 {
            return Err(truncated());
        }
        (0..n).map(|_| self.f64()).collect()
    }
    /// A 3-vector.
    pub fn vec3(&mut self) -> Result<Vec3, SimulationError> {
        Ok(Vec3::new(self.f64()?, self.f64()?, self.f64()?))
    }
    /// An optional 3-vector.
    pub fn opt_vec3(&mut self) -> Result<Option<Vec3>, SimulationError> {
        let some = self.bool()?;
        let v = self.vec3()?;
        Ok(some.then_some(v))
    }
    /// A string.
    pub fn str(&mut self) -> Result<String, SimulationError> {
        let n = self.u64()? as usize;
        let b = self.take(n)?;
        String::from_utf8(b.to_vec()).map_err(|_| truncated())
    }
    /// The bytes not read yet.
    pub fn rest(&self) -> &'a [u8] {
        self.bytes
    }
}

fn put_clock(e: &mut Encoder, c: &Clock) {
    for x in [c.step, c.nominal, c.anchor, c.interval] {
        e.f64(x);
    }
    for x in [c.since_anchor, c.steps_done, c.next_output] {
        e.u64(x);
    }
}

fn get_clock(d: &mut Decoder) -> Result<Clock, SimulationError> {
    Ok(Clock {
        step: d.f64()?,
        nominal: d.f64()?,
        anchor: d.f64()?,
        interval: d.f64()?,
        since_anchor: d.u64()?,
        steps_done: d.u64()?,
        next_output: d.u64()?,
    })
}

fn put_saved(e: &mut Encoder, s: &Saved) {
    e.f64s(&s.state);
    put_clock(e, &s.clock);
    e.f64s(&s.history);
    e.f64(s.last_step);
    // Line failures: per failure, whether it released, and when, at what tension, why.
    e.u64(s.releases.len() as u64);
    for r in &s.releases {
        e.bool(r.is_some());
        let r = r.unwrap_or(super::Release {
            time: 0.0,
            tension: 0.0,
            cause: super::ReleaseCause::Host,
        });
        e.f64(r.time);
        e.f64(r.tension);
        e.u64(match r.cause {
            super::ReleaseCause::Time => 0,
            super::ReleaseCause::Tension => 1,
            super::ReleaseCause::Host => 2,
        });
    }
    let w = &s.switch;
    e.bool(w.explicit);
    e.u64(w.since_output);
    e.f64(w.work);
    e.u64(w.losses as u64);
    e.u64(w.switches);
    e.u64(w.explicit_outputs);
    e.f64(w.implicit_nominal);
}

fn get_saved(d: &mut Decoder) -> Result<Saved, SimulationError> {
    Ok(Saved {
        state: d.f64s()?,
        clock: get_clock(d)?,
        history: d.f64s()?,
        last_step: d.f64()?,
        releases: {
            let n = d.u64()? as usize;
            // Each release takes 25 bytes: a count beyond the bytes left is corrupt.
            if n > d.rest().len() / 25 {
                return Err(truncated());
            }
            let mut releases = Vec::with_capacity(n);
            for _ in 0..n {
                let happened = d.bool()?;
                let (time, tension) = (d.f64()?, d.f64()?);
                let cause = match d.u64()? {
                    0 => super::ReleaseCause::Time,
                    1 => super::ReleaseCause::Tension,
                    2 => super::ReleaseCause::Host,
                    _ => return Err(truncated()),
                };
                releases.push(happened.then_some(super::Release {
                    time,
                    tension,
                    cause,
                }));
            }
            releases
        },
        switch: SchemeSwitch {
            explicit: d.bool()?,
            since_output: d.u64()?,
            work: d.f64()?,
            losses: u32::try_from(d.u64()?).map_err(|_| truncated())?,
            switches: d.u64()?,
            explicit_outputs: d.u64()?,
            implicit_nominal: d.f64()?,
        },
    })
}

fn put_point_track(e: &mut Encoder, t: &PointTrack) {
    e.f64(t.t0);
    e.f64(t.t1);
    for (x, v, a) in [&t.start, &t.end] {
        e.vec3(x);
        e.vec3(v);
        e.opt_vec3(a);
    }
}

fn get_point_track(d: &mut Decoder) -> Result<PointTrack, SimulationError> {
    let (t0, t1) = (d.f64()?, d.f64()?);
    let start = (d.vec3()?, d.vec3()?, d.opt_vec3()?);
    let end = (d.vec3()?, d.vec3()?, d.opt_vec3()?);
    Ok(PointTrack { t0, t1, start, end })
}

fn put_tracks(e: &mut Encoder, c: &CouplingTracks) {
    for t in c.points.iter().flatten() {
        put_point_track(e, t);
    }
    for t in c.bodies.iter().flatten() {
        put_point_track(e, &t.origin);
        let q = t.orientation0.coords;
        (0..4).for_each(|i| e.f64(q[i]));
        e.vec3(&t.rotation);
        e.vec3(&t.angular_velocity.0);
        e.vec3(&t.angular_velocity.1);
        e.opt_vec3(&t.angular_acceleration.0);
        e.opt_vec3(&t.angular_acceleration.1);
    }
}

fn get_tracks(d: &mut Decoder, c: &mut CouplingTracks) -> Result<(), SimulationError> {
    for t in c.points.iter_mut().flatten() {
        *t = get_point_track(d)?;
    }
    for t in c.bodies.iter_mut().flatten() {
        let origin = get_point_track(d)?;
        let q = [d.f64()?, d.f64()?, d.f64()?, d.f64()?];
        *t = BodyTrack {
            origin,
            orientation0: quat_from_coords(q),
            rotation: d.vec3()?,
            angular_velocity: (d.vec3()?, d.vec3()?),
            angular_acceleration: (d.opt_vec3()?, d.opt_vec3()?),
        };
    }
    Ok(())
}

impl Session {
    /// The run saved to bytes: everything the next step needs (state, clock, multistep
    /// history, coupling tracks), tagged with the model's hash and the format version. The
    /// observers keep their own state (the CLI's writer saves it beside this).
    pub fn checkpoint(&self) -> Vec<u8> {
        let mut e = Encoder::default();
        e.bytes.extend_from_slice(MAGIC);
        e.bytes.extend_from_slice(&CHECKPOINT_VERSION.to_le_bytes());
        e.u64(model_hash(&self.model));
        e.u64(self.samples);
        e.f64(self.last_sample);
        let mut saved = Saved::default();
        self.stepper.save(&mut saved);
        put_saved(&mut e, &saved);
        let (limit, culprit) = self.stepper.stable_step();
        e.f64(limit);
        e.str(culprit);
        put_tracks(&mut e, &self.stepper.ws.coupling);
        e.bool(self.coupling.interval.is_some());
        let (t0, t1) = self.coupling.interval.unwrap_or((0.0, 0.0));
        e.f64(t0);
        e.f64(t1);
        put_saved(&mut e, &self.coupling.start);
        e.u64(self.coupling.start_samples.0);
        e.f64(self.coupling.start_samples.1);
        // The static positions of the wave kinematics cache: recorded at the start of the run,
        // not where the run is now.
        let tables = self.system.wave_table_positions(self.stepper.workspace());
        e.bool(tables.is_some());
        for line in tables.iter().flatten() {
            e.u64(line.len() as u64);
            line.iter().for_each(|p| e.vec3(p));
        }
        e.bytes
    }

    /// A session of `model` continued from `checkpoint` ([`Session::checkpoint`]), without
    /// its initial statics: it steps exactly as the saved session would have. Refused when
    /// the checkpoint is of another model, another format version, or damaged.
    pub fn restore(
        model: Model,
        checkpoint: &[u8],
        options: SessionOptions,
    ) -> Result<Self, SimulationError> {
        let bad = |what: String| SimulationError::Checkpoint { what };
        if checkpoint.len() < 20 || &checkpoint[..8] != MAGIC {
            return Err(bad(
                "these bytes are not a hawser checkpoint (no HAWSERCK header)".into(),
            ));
        }
        let version = u32::from_le_bytes(checkpoint[8..12].try_into().expect("4 bytes"));
        if version != CHECKPOINT_VERSION {
            return Err(bad(format!(
                "the checkpoint has format version {version}, this hawser reads version \
                 {CHECKPOINT_VERSION}: resume it with the hawser that wrote it"
            )));
        }
        let mut d = Decoder::new(&checkpoint[12..]);
        let hash = d.u64()?;
        let expected = model_hash(&model);
        if hash != expected {
            return Err(bad(format!(
                "the checkpoint was written for another model (model hash {hash:016x}, this \
                 model's {expected:016x}): resume it with the scenario it was written from, \
                 unchanged"
            )));
        }
        let samples = d.u64()?;
        let last_sample = d.f64()?;
        let saved = get_saved(&mut d)?;
        let limit = d.f64()?;
        let culprit = d.str()?;
        let mut session = Self::from_state(model, saved.state.clone(), options)?;
        if session.stepper.state.len() != saved.state.len() {
            return Err(bad("the checkpoint's state has another length".into()));
        }
        if !session.stepper.restore(&saved) {
            return Err(bad(
                "the checkpoint's integrator history or line failures do not fit this run".into(),
            ));
        }
        session.stepper.apply_releases(&mut session.system);
        session.stepper.save(&mut session.sampled);
        session.stepper.stable_step = (limit, culprit);
        get_tracks(&mut d, &mut session.stepper.ws.coupling)?;
        let open = d.bool()?;
        let interval = (d.f64()?, d.f64()?);
        session.coupling.interval = open.then_some(interval);
        session.coupling.start = get_saved(&mut d)?;
        session.coupling.start_samples = (d.u64()?, d.f64()?);
        if d.bool()? {
            let mut positions = Vec::new();
            for l in 0..session.system.lines.len() {
                let n = d.u64()? as usize;
                if n != session.system.fluid_points(l) {
                    return Err(bad(
                        "the checkpoint's wave kinematics points do not match".into()
                    ));
                }
                positions.push((0..n).map(|_| d.vec3()).collect::<Result<Vec<_>, _>>()?);
            }
            session
                .system
                .restore_wave_tables(&positions, &mut session.stepper.ws);
        }
        session.samples = samples;
        session.last_sample = last_sample;
        if !d.rest().is_empty() {
            return Err(bad(format!(
                "the checkpoint has {} bytes more than its contents",
                d.rest().len()
            )));
        }
        Ok(session)
    }
}
