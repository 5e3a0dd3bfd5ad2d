//! Range graphs: the minimum, mean and maximum effective tension at every node of a line over
//! a run, collected from [`View::line_samples`] at each output sample. Sized once; a sample
//! allocates nothing.

use crate::math::Real;
use crate::session::{Decoder, Encoder, View};

/// Tension statistics along one line over the samples pushed.
#[derive(Clone, Debug, PartialEq)]
pub struct RangeGraph {
    /// Unstretched arc length of each node from end A at the last sample [m] (a line on a
    /// winch changes it; other lines keep it).
    pub arc_length: Vec<Real>,
    /// Smallest effective tension at each node [N].
    pub min: Vec<Real>,
    /// Largest effective tension at each node [N].
    pub max: Vec<Real>,
    /// Time of the largest tension at each node [s].
    pub time_of_max: Vec<Real>,
    /// Sum of the tensions at each node [N], for the mean.
    sum: Vec<Real>,
    /// Samples pushed.
    pub samples: u64,
}

impl RangeGraph {
    /// An empty range graph of a line of `nodes` nodes.
    pub fn new(nodes: usize) -> Self {
        Self {
            arc_length: vec![0.0; nodes],
            min: vec![Real::INFINITY; nodes],
            max: vec![Real::NEG_INFINITY; nodes],
            time_of_max: vec![Real::NAN; nodes],
            sum: vec![0.0; nodes],
            samples: 0,
        }
    }

    /// Adds the node tensions of line `line` in `view` as the sample at `time` [s] (the
    /// sample's time as written, which may differ from `view.time` by round-off).
    pub fn push(&mut self, view: &View<'_>, line: usize, time: Real) {
        self.samples += 1;
        for n in view.line_samples(line) {
            let i = n.node;
            self.arc_length[i] = n.arc_length;
            self.min[i] = self.min[i].min(n.tension);
            if n.tension > self.max[i] {
                self.max[i] = n.tension;
                self.time_of_max[i] = time;
            }
            self.sum[i] += n.tension;
        }
    }

    /// Mean effective tension at node `i` [N] (NaN before the first sample).
    pub fn mean(&self, i: usize) -> Real {
        self.sum[i] / self.samples as Real
    }

    /// Saves the range graph exactly (a checkpoint of a writer).
    pub fn encode(&self, e: &mut Encoder) {
        for v in [
            &self.arc_length,
            &self.min,
            &self.max,
            &self.time_of_max,
            &self.sum,
        ] {
            e.f64s(v);
        }
        e.u64(self.samples);
    }

    /// A range graph saved by [`RangeGraph::encode`].
    pub fn decode(d: &mut Decoder) -> Result<Self, crate::SimulationError> {
        Ok(Self {
            arc_length: d.f64s()?,
            min: d.f64s()?,
            max: d.f64s()?,
            time_of_max: d.f64s()?,
            sum: d.f64s()?,
            samples: d.u64()?,
        })
    }
}
