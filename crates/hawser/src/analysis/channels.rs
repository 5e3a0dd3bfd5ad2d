//! Output channels: the scalar quantities a run records (tensions, end forces, positions,
//! strains, body motions and loads, obstacle loads, line lengths, relative positions), their
//! names and units, how they are read from an evaluated workspace, and how a name is parsed
//! against a model. The scenario readers, the writers and the bindings all use these.

use crate::math::Real;
use crate::model::{Model, PointKind};
use crate::system::{System, Workspace};

use super::obstacles;

/// A scalar output channel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Channel {
    /// Magnitude of the force a line exerts on the attachment of an end [N].
    EndTension {
        /// Line index.
        line: usize,
        /// End B (true) or A.
        end_b: bool,
    },
    /// Component of the force a line exerts on an end's attachment [N].
    EndForce {
        /// Line index.
        line: usize,
        /// End B (true) or A.
        end_b: bool,
        /// 0, 1, 2 for x, y, z.
        axis: usize,
    },
    /// Magnitude of the net force of the line on its end node, without the node's inertia
    /// [N]: the end segment's tension plus the end node's share of weight, buoyancy, drag and
    /// seabed contact. This is MoorDyn's `FairTen`/`AnchTen`; it differs from
    /// [`Channel::EndTension`] by the inertia of the end node's share of the line.
    EndNodeForce {
        /// Line index.
        line: usize,
        /// End B (true) or A.
        end_b: bool,
    },
    /// Tension at a node [N].
    NodeTension {
        /// Line index.
        line: usize,
        /// Node index (0 at end A).
        node: usize,
    },
    /// Node position component [m].
    NodePosition {
        /// Line index.
        line: usize,
        /// Node index.
        node: usize,
        /// Axis.
        axis: usize,
    },
    /// Node velocity component [m/s].
    NodeVelocity {
        /// Line index.
        line: usize,
        /// Node index.
        node: usize,
        /// Axis.
        axis: usize,
    },
    /// Element strain [-].
    ElementStrain {
        /// Line index.
        line: usize,
        /// Element index.
        element: usize,
    },
    /// Curvature at an element's midpoint [1/m] (formulations with bending; 0 for `fe`).
    ElementCurvature {
        /// Line index.
        line: usize,
        /// Element index.
        element: usize,
    },
    /// Bending moment at an element's midpoint [N·m] (formulations with bending).
    ElementBendingMoment {
        /// Line index.
        line: usize,
        /// Element index.
        element: usize,
    },
    /// Shear force |dM/ds| in an element [N] (formulations with bending).
    ElementShearForce {
        /// Line index.
        line: usize,
        /// Element index.
        element: usize,
    },
    /// Point position component [m].
    PointPosition {
        /// Point index.
        point: usize,
        /// Axis.
        axis: usize,
    },
    /// Point velocity component [m/s].
    PointVelocity {
        /// Point index.
        point: usize,
        /// Axis.
        axis: usize,
    },
    /// Component of the net force the attached lines exert on a point [N]: the sum of their
    /// end-node forces without inertia (MoorDyn's `P#FX` of a coupled point, the mooring force
    /// on the vessel).
    PointForce {
        /// Point index.
        point: usize,
        /// Axis.
        axis: usize,
    },
    /// Body motion: position of its origin [m] (dof 0–2) or its roll, pitch, yaw [deg]
    /// (dof 3–5; R = R_z(yaw) R_y(pitch) R_x(roll)).
    BodyMotion {
        /// Body index.
        body: usize,
        /// 0–5: x, y, z, roll, pitch, yaw.
        dof: usize,
    },
    /// Body velocity: of its origin [m/s] (dof 0–2) or its angular velocity in global axes
    /// [rad/s] (dof 3–5).
    BodyVelocity {
        /// Body index.
        body: usize,
        /// 0–5: vx, vy, vz, wx, wy, wz.
        dof: usize,
    },
    /// The net load the lines put on a body through the points on it: force [N] (dof 0–2) and
    /// moment about the body origin [N·m] (dof 3–5), global axes.
    BodyLineLoad {
        /// Body index.
        body: usize,
        /// 0–5: fx, fy, fz, mx, my, mz.
        dof: usize,
    },
    /// Component of the total contact force the lines exert on an obstacle [N]
    /// ([`obstacles`]).
    ObstacleForce {
        /// Obstacle index in the environment.
        obstacle: usize,
        /// Axis.
        axis: usize,
    },
    /// Unstretched length of cable in contact with an obstacle [m] ([`obstacles`]).
    ObstacleContactLength {
        /// Obstacle index in the environment.
        obstacle: usize,
    },
    /// Unstretched length of a line [m]: L(t) of a line on a winch, its fixed length
    /// otherwise.
    LineLength {
        /// Line index.
        line: usize,
    },
    /// Stretched length of a line [m] ([`stretched_length`]).
    LineStretchedLength {
        /// Line index.
        line: usize,
    },
    /// Relative stretch of a line [-]: stretched length / unstretched length − 1.
    LineStretch {
        /// Line index.
        line: usize,
    },
    /// Winch tension [N]: the magnitude of the force the line exerts on the attachment at its
    /// winch's end (as [`Channel::EndTension`] there). Lines with a winch only.
    WinchTension {
        /// Line index.
        line: usize,
    },
    /// Position of an object relative to a reference [m] (the elastic-link paper's "position
    /// of the vehicle relative to the vessel", §5): the object's position (a point's, or a
    /// body's origin) minus the reference's, in the reference body's axes,
    /// Rᵀ (x_object − x_reference) with R the reference's orientation, or in global axes
    /// when the reference is a point.
    RelativePosition {
        /// The object whose position is reported.
        object: Object,
        /// The reference it is measured from.
        reference: Object,
        /// 0, 1, 2 for x, y, z (of the reference body's axes, or global).
        axis: usize,
    },
}

/// A point or a body, as the object or reference of [`Channel::RelativePosition`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Object {
    /// Point index.
    Point(usize),
    /// Body index.
    Body(usize),
}

impl Object {
    fn name(self, system: &System) -> &str {
        match self {
            Object::Point(p) => &system.points[p].name,
            Object::Body(b) => &system.bodies[b].body.name,
        }
    }

    fn position(self, ws: &Workspace) -> crate::math::Vec3 {
        match self {
            Object::Point(p) => ws.points[p].position,
            Object::Body(b) => ws.bodies[b].position,
        }
    }
}

/// Position of `object` relative to `reference` [m] from a workspace that holds an
/// evaluation: Rᵀ (x_object − x_reference) in the axes of a reference body, the global
/// difference for a reference point ([`Channel::RelativePosition`]).
pub fn relative_position(ws: &Workspace, object: Object, reference: Object) -> crate::math::Vec3 {
    let d = object.position(ws) - reference.position(ws);
    match reference {
        Object::Body(b) => ws.bodies[b].orientation.inverse_transform_vector(&d),
        Object::Point(_) => d,
    }
}

/// Stretched length [m] of line `line` from a workspace that holds an evaluation: `fe`, the
/// sum of its element chords |r_{i+1} − r_i|; `hermite`, ∫ |r'| ds over each cubic element
/// by its four-point Gauss rule (the rule of its forces); `dg`, Σ l_e (λ_a + λ_b)/2 with λ
/// the stretch 1 + ε at the element's two ends (trapezoidal). Unstretched lengths are the
/// current ones ([`System::line_mesh`]).
pub fn stretched_length(system: &System, ws: &Workspace, line: usize) -> Real {
    use crate::formulation::{Discretisation, hermite};
    let l = &system.lines[line];
    let mesh = system.line_mesh(ws, line);
    let lw = &ws.lines[line];
    let n = mesh.elements();
    match l.discretisation {
        Discretisation::Fe { .. } => (0..n)
            .map(|e| (lw.position[e + 1] - lw.position[e]).norm())
            .sum(),
        Discretisation::Hermite(_) => (0..n)
            .map(|e| {
                let h = mesh.section(e).element_length;
                hermite::GAUSS
                    .iter()
                    .map(|&(xi, w)| {
                        w * h
                            * hermite::point_on_element(mesh, &lw.position, e, xi)
                                .1
                                .norm()
                    })
                    .sum::<Real>()
            })
            .sum(),
        Discretisation::Dg(_) => (0..n)
            .map(|e| mesh.section(e).element_length * (1.0 + lw.elements.strain[e]))
            .sum(),
    }
}

/// Unstretched length [m] of line `line` at the last evaluation in `ws`.
pub fn unstretched_length(system: &System, ws: &Workspace, line: usize) -> Real {
    match &ws.winches[line] {
        Some(w) => w.length,
        None => system.lines[line].mesh.length(),
    }
}

/// Channel suffixes of a body's motion, velocity and line load.
pub const BODY_MOTION: [&str; 6] = ["x", "y", "z", "roll", "pitch", "yaw"];
/// See [`BODY_MOTION`].
pub const BODY_VELOCITY: [&str; 6] = ["vx", "vy", "vz", "wx", "wy", "wz"];
/// See [`BODY_MOTION`].
pub const BODY_LINE_LOAD: [&str; 6] = ["fx", "fy", "fz", "mx", "my", "mz"];

const AXES: [&str; 3] = ["x", "y", "z"];

impl Channel {
    /// Column name, e.g. `L1.end_b.tension`, `L1.node3.x`, `buoy.vz`.
    pub fn name(&self, system: &System) -> String {
        let line = |l: usize| system.lines[l].name.as_str();
        let end = |b: bool| if b { "end_b" } else { "end_a" };
        match *self {
            Channel::EndTension { line: l, end_b } => format!("{}.{}.tension", line(l), end(end_b)),
            Channel::EndForce {
                line: l,
                end_b,
                axis,
            } => format!("{}.{}.f{}", line(l), end(end_b), AXES[axis]),
            Channel::EndNodeForce { line: l, end_b } => {
                format!("{}.{}.node_force", line(l), end(end_b))
            }
            Channel::NodeTension { line: l, node } => format!("{}.node{}.tension", line(l), node),
            Channel::NodePosition {
                line: l,
                node,
                axis,
            } => format!("{}.node{}.{}", line(l), node, AXES[axis]),
            Channel::NodeVelocity {
                line: l,
                node,
                axis,
            } => format!("{}.node{}.v{}", line(l), node, AXES[axis]),
            Channel::ElementStrain { line: l, element } => {
                format!("{}.element{}.strain", line(l), element)
            }
            Channel::ElementCurvature { line: l, element } => {
                format!("{}.element{}.curvature", line(l), element)
            }
            Channel::ElementBendingMoment { line: l, element } => {
                format!("{}.element{}.bending_moment", line(l), element)
            }
            Channel::ElementShearForce { line: l, element } => {
                format!("{}.element{}.shear_force", line(l), element)
            }
            Channel::PointPosition { point, axis } => {
                format!("{}.{}", system.points[point].name, AXES[axis])
            }
            Channel::PointVelocity { point, axis } => {
                format!("{}.v{}", system.points[point].name, AXES[axis])
            }
            Channel::PointForce { point, axis } => {
                format!("{}.f{}", system.points[point].name, AXES[axis])
            }
            Channel::BodyMotion { body, dof } => {
                format!("{}.{}", system.bodies[body].body.name, BODY_MOTION[dof])
            }
            Channel::BodyVelocity { body, dof } => {
                format!("{}.{}", system.bodies[body].body.name, BODY_VELOCITY[dof])
            }
            Channel::BodyLineLoad { body, dof } => {
                format!("{}.{}", system.bodies[body].body.name, BODY_LINE_LOAD[dof])
            }
            Channel::ObstacleForce { obstacle, axis } => {
                let name = &system.environment.obstacles[obstacle].name;
                format!("{name}.force_{}", AXES[axis])
            }
            Channel::ObstacleContactLength { obstacle } => {
                format!(
                    "{}.contact_length",
                    system.environment.obstacles[obstacle].name
                )
            }
            Channel::LineLength { line: l } => format!("{}.length", line(l)),
            Channel::LineStretchedLength { line: l } => format!("{}.stretched_length", line(l)),
            Channel::LineStretch { line: l } => format!("{}.stretch", line(l)),
            Channel::WinchTension { line: l } => format!("{}.winch_tension", line(l)),
            Channel::RelativePosition {
                object,
                reference,
                axis,
            } => format!(
                "{}.relative_to.{}.{}",
                object.name(system),
                reference.name(system),
                AXES[axis]
            ),
        }
    }

    /// Unit of the channel.
    pub fn unit(&self) -> &'static str {
        match self {
            Channel::EndTension { .. }
            | Channel::EndForce { .. }
            | Channel::EndNodeForce { .. }
            | Channel::NodeTension { .. }
            | Channel::ElementShearForce { .. }
            | Channel::PointForce { .. }
            | Channel::ObstacleForce { .. }
            | Channel::WinchTension { .. } => "N",
            Channel::ElementCurvature { .. } => "1/m",
            Channel::ElementBendingMoment { .. } => "N·m",
            Channel::NodePosition { .. }
            | Channel::PointPosition { .. }
            | Channel::ObstacleContactLength { .. }
            | Channel::LineLength { .. }
            | Channel::LineStretchedLength { .. }
            | Channel::RelativePosition { .. } => "m",
            Channel::NodeVelocity { .. } | Channel::PointVelocity { .. } => "m/s",
            Channel::ElementStrain { .. } | Channel::LineStretch { .. } => "-",
            Channel::BodyMotion { dof, .. } => ["m", "deg"][dof / 3],
            Channel::BodyVelocity { dof, .. } => ["m/s", "rad/s"][dof / 3],
            Channel::BodyLineLoad { dof, .. } => ["N", "N·m"][dof / 3],
        }
    }

    /// Value from a workspace that holds a right-hand-side evaluation at time `time` [s]
    /// (the obstacle channels need it for moving obstacles).
    pub fn value_at(&self, system: &System, ws: &Workspace, time: Real) -> Real {
        match *self {
            Channel::ObstacleForce { obstacle, axis } => {
                obstacles::obstacle_load(system, ws, time, obstacle).force[axis]
            }
            Channel::ObstacleContactLength { obstacle } => {
                obstacles::obstacle_load(system, ws, time, obstacle).contact_length
            }
            _ => self.value(system, ws),
        }
    }

    /// Value from a workspace that holds a right-hand-side evaluation; obstacle channels
    /// with their obstacles where they are at t = 0 (use [`Channel::value_at`] for moving
    /// obstacles).
    pub fn value(&self, system: &System, ws: &Workspace) -> Real {
        match *self {
            Channel::EndTension { line, end_b } => system.end_force(ws, line, end_b).norm(),
            Channel::EndForce { line, end_b, axis } => system.end_force(ws, line, end_b)[axis],
            Channel::EndNodeForce { line, end_b } => {
                let lw = &ws.lines[line];
                let node = if end_b { lw.force.len() - 1 } else { 0 };
                lw.force[node].norm()
            }
            Channel::NodeTension { line, node } => system.node_tension(ws, line, node),
            Channel::NodePosition { line, node, axis } => {
                ws.lines[line].position[system.lines[line].node_vector(node)][axis]
            }
            Channel::NodeVelocity { line, node, axis } => {
                ws.lines[line].velocity[system.lines[line].node_vector(node)][axis]
            }
            Channel::ElementStrain { line, element } => ws.lines[line].elements.strain[element],
            Channel::ElementCurvature { line, element } => {
                ws.lines[line].elements.curvature[element]
            }
            Channel::ElementBendingMoment { line, element } => {
                ws.lines[line].elements.bending_moment[element]
            }
            Channel::ElementShearForce { line, element } => {
                ws.lines[line].elements.shear_force[element]
            }
            Channel::PointPosition { point, axis } => ws.points[point].position[axis],
            Channel::RelativePosition {
                object,
                reference,
                axis,
            } => relative_position(ws, object, reference)[axis],
            Channel::PointVelocity { point, axis } => ws.points[point].velocity[axis],
            Channel::PointForce { point, axis } => system
                .lines
                .iter()
                .zip(&ws.lines)
                .map(|(l, lw)| {
                    let mut f = 0.0;
                    if l.end_a == point {
                        f += lw.force[0][axis];
                    }
                    if l.end_b == point {
                        f += lw.force[lw.force.len() - 1][axis];
                    }
                    f
                })
                .sum(),
            Channel::BodyMotion { body, dof } => {
                let k = &ws.bodies[body];
                if dof < 3 {
                    k.position[dof]
                } else {
                    let (roll, pitch, yaw) = k.orientation.euler_angles();
                    [roll, pitch, yaw][dof - 3].to_degrees()
                }
            }
            Channel::BodyVelocity { body, dof } => {
                let k = &ws.bodies[body];
                if dof < 3 {
                    k.velocity[dof]
                } else {
                    k.angular_velocity[dof - 3]
                }
            }
            Channel::BodyLineLoad { body, dof } => {
                let origin = ws.bodies[body].position;
                let mut load = [0.0; 6];
                for (li, l) in system.lines.iter().enumerate() {
                    for (end_b, p) in [(false, l.end_a), (true, l.end_b)] {
                        if matches!(system.points[p].kind, PointKind::Body { body: b, .. } if b == body)
                        {
                            let f = system.end_force(ws, li, end_b);
                            let m = (ws.points[p].position - origin).cross(&f);
                            for k in 0..3 {
                                load[k] += f[k];
                                load[k + 3] += m[k];
                            }
                        }
                    }
                }
                load[dof]
            }
            Channel::ObstacleForce { .. } | Channel::ObstacleContactLength { .. } => {
                self.value_at(system, ws, 0.0)
            }
            Channel::LineLength { line } => unstretched_length(system, ws, line),
            Channel::LineStretchedLength { line } => stretched_length(system, ws, line),
            Channel::LineStretch { line } => {
                stretched_length(system, ws, line) / unstretched_length(system, ws, line) - 1.0
            }
            Channel::WinchTension { line } => {
                let end_b = system.lines[line]
                    .winch
                    .as_ref()
                    .is_some_and(|w| w.at_end_b());
                system.end_force(ws, line, end_b).norm()
            }
        }
    }

    /// Checks indices against the system.
    pub fn is_valid(&self, system: &System) -> bool {
        let nodes = |l: usize| system.lines.get(l).map(|x| x.nodes()).unwrap_or(0);
        match *self {
            Channel::EndTension { line, .. }
            | Channel::EndForce { line, .. }
            | Channel::EndNodeForce { line, .. } => line < system.lines.len(),
            Channel::NodeTension { line, node }
            | Channel::NodePosition { line, node, .. }
            | Channel::NodeVelocity { line, node, .. } => node < nodes(line),
            Channel::ElementStrain { line, element }
            | Channel::ElementCurvature { line, element }
            | Channel::ElementBendingMoment { line, element }
            | Channel::ElementShearForce { line, element } => element + 1 < nodes(line),
            Channel::PointPosition { point, .. }
            | Channel::PointVelocity { point, .. }
            | Channel::PointForce { point, .. } => point < system.points.len(),
            Channel::BodyMotion { body, dof }
            | Channel::BodyVelocity { body, dof }
            | Channel::BodyLineLoad { body, dof } => body < system.bodies.len() && dof < 6,
            Channel::ObstacleForce { obstacle, .. }
            | Channel::ObstacleContactLength { obstacle } => {
                obstacle < system.environment.obstacles.len()
            }
            Channel::LineLength { line }
            | Channel::LineStretchedLength { line }
            | Channel::LineStretch { line } => line < system.lines.len(),
            Channel::WinchTension { line } => {
                system.lines.get(line).is_some_and(|l| l.winch.is_some())
            }
            Channel::RelativePosition {
                object,
                reference,
                axis,
            } => {
                let exists = |o: Object| match o {
                    Object::Point(p) => p < system.points.len(),
                    Object::Body(b) => b < system.bodies.len(),
                };
                exists(object) && exists(reference) && axis < 3
            }
        }
    }
}

/// An output column: a channel and, when the scenario named it
/// (`"FairTen1 = L1.end_b.node_force"`, or a MoorDyn deck's OUTPUTS), its column name.
#[derive(Clone, Debug, PartialEq)]
pub struct OutputChannel {
    /// What is measured.
    pub channel: Channel,
    /// Column name given by the scenario, if any.
    pub label: Option<String>,
}

impl OutputChannel {
    /// An unnamed channel (named after what it measures).
    pub fn new(channel: Channel) -> Self {
        Self {
            channel,
            label: None,
        }
    }

    /// Column name without the unit.
    pub fn name(&self, system: &System) -> String {
        match &self.label {
            Some(l) => l.clone(),
            None => self.channel.name(system),
        }
    }
}

/// The channels every run records: both end tensions of every line, the length and winch
/// tension of a line on a winch, the position of every free point, the six motions of every
/// body and the contact force on every obstacle. A scenario's own channels come after these.
pub fn default_channels(model: &Model) -> Vec<OutputChannel> {
    let mut out = Vec::new();
    for (li, _) in model.lines.iter().enumerate() {
        for end_b in [false, true] {
            out.push(OutputChannel::new(Channel::EndTension { line: li, end_b }));
        }
    }
    for (li, l) in model.lines.iter().enumerate() {
        if l.winch.is_some() {
            out.push(OutputChannel::new(Channel::LineLength { line: li }));
            out.push(OutputChannel::new(Channel::WinchTension { line: li }));
        }
    }
    for (pi, p) in model.points.iter().enumerate() {
        if matches!(p.kind, PointKind::Free { .. }) {
            for axis in 0..3 {
                out.push(OutputChannel::new(Channel::PointPosition {
                    point: pi,
                    axis,
                }));
            }
        }
    }
    for body in 0..model.bodies.len() {
        for dof in 0..6 {
            out.push(OutputChannel::new(Channel::BodyMotion { body, dof }));
        }
    }
    for obstacle in 0..model.environment.obstacles.len() {
        for axis in 0..3 {
            out.push(OutputChannel::new(Channel::ObstacleForce {
                obstacle,
                axis,
            }));
        }
    }
    out
}

impl Channel {
    /// Parses a channel name (`L1.end_b.tension`, `buoy.z`, `ROV.relative_to.vessel.x`, ...)
    /// against the model; the error says what is wrong with it.
    pub fn parse(name: &str, model: &Model) -> Result<Channel, String> {
        let axis = |s: &str| match s {
            "x" => Some(0),
            "y" => Some(1),
            "z" => Some(2),
            _ => None,
        };
        let parts: Vec<&str> = name.split('.').collect();
        if let Some(li) = model.line_index(parts[0]) {
            let n = model.lines[li].elements();
            match parts.as_slice() {
                [_, "length"] => return Ok(Channel::LineLength { line: li }),
                [_, "stretched_length"] => return Ok(Channel::LineStretchedLength { line: li }),
                [_, "stretch"] => return Ok(Channel::LineStretch { line: li }),
                [_, "winch_tension"] => {
                    if model.lines[li].winch.is_none() {
                        return Err(format!(
                            "line `{}` has no winch, so no winch tension",
                            parts[0]
                        ));
                    }
                    return Ok(Channel::WinchTension { line: li });
                }
                [_, end @ ("end_a" | "end_b"), q] => {
                    let end_b = *end == "end_b";
                    match *q {
                        "tension" => return Ok(Channel::EndTension { line: li, end_b }),
                        "node_force" => return Ok(Channel::EndNodeForce { line: li, end_b }),
                        f if f.len() == 2 && f.starts_with('f') => {
                            if let Some(a) = axis(&f[1..]) {
                                return Ok(Channel::EndForce {
                                    line: li,
                                    end_b,
                                    axis: a,
                                });
                            }
                        }
                        _ => {}
                    }
                }
                [_, node, q] if node.starts_with("node") => {
                    let Ok(k) = node[4..].parse::<usize>() else {
                        return Err(format!("`{node}` is not a node (use node0 … node{n})"));
                    };
                    if k > n {
                        return Err(format!(
                            "line `{}` has nodes 0 … {n}; node {k} does not exist",
                            parts[0]
                        ));
                    }
                    match *q {
                        "tension" => return Ok(Channel::NodeTension { line: li, node: k }),
                        v if v.len() == 2 && v.starts_with('v') => {
                            if let Some(a) = axis(&v[1..]) {
                                return Ok(Channel::NodeVelocity {
                                    line: li,
                                    node: k,
                                    axis: a,
                                });
                            }
                        }
                        p => {
                            if let Some(a) = axis(p) {
                                return Ok(Channel::NodePosition {
                                    line: li,
                                    node: k,
                                    axis: a,
                                });
                            }
                        }
                    }
                }
                [
                    _,
                    el,
                    quantity @ ("strain" | "curvature" | "bending_moment" | "shear_force"),
                ] if el.starts_with("element") => {
                    let Ok(k) = el[7..].parse::<usize>() else {
                        return Err(format!("`{el}` is not an element"));
                    };
                    if k >= n {
                        return Err(format!(
                            "line `{}` has elements 0 … {}; element {k} does not exist",
                            parts[0],
                            n.saturating_sub(1)
                        ));
                    }
                    let (line, element) = (li, k);
                    return Ok(match *quantity {
                        "strain" => Channel::ElementStrain { line, element },
                        "curvature" => Channel::ElementCurvature { line, element },
                        "bending_moment" => Channel::ElementBendingMoment { line, element },
                        _ => Channel::ElementShearForce { line, element },
                    });
                }
                _ => {}
            }
            return Err(format!("unknown channel `{name}`"));
        }
        let find_object = |n: &str| {
            model.point_index(n).map(Object::Point).or_else(|| {
                model
                    .bodies
                    .iter()
                    .position(|b| b.name == n)
                    .map(Object::Body)
            })
        };
        if let [o, "relative_to", r, q] = parts.as_slice()
            && let Some(object) = find_object(o)
        {
            let Some(reference) = find_object(r) else {
                return Err(format!(
                    "`{r}` in `{name}` is no point or body: the reference of a relative position \
                 is a point (global axes) or a body (its axes)"
                ));
            };
            if reference == object {
                return Err(format!(
                    "`{name}` is a position relative to itself, always zero"
                ));
            }
            let Some(axis) = axis(q) else {
                return Err(format!("`{q}` in `{name}` is not an axis: use x, y or z"));
            };
            return Ok(Channel::RelativePosition {
                object,
                reference,
                axis,
            });
        }
        if let Some(pi) = model.point_index(parts[0]) {
            if let [_, q] = parts.as_slice() {
                if let Some(a) = axis(q) {
                    return Ok(Channel::PointPosition { point: pi, axis: a });
                }
                if q.len() == 2
                    && q.starts_with('v')
                    && let Some(a) = axis(&q[1..])
                {
                    return Ok(Channel::PointVelocity { point: pi, axis: a });
                }
                if q.len() == 2
                    && q.starts_with('f')
                    && let Some(a) = axis(&q[1..])
                {
                    return Ok(Channel::PointForce { point: pi, axis: a });
                }
            }
            return Err(format!("unknown channel `{name}`"));
        }
        if let Some(bi) = model.bodies.iter().position(|b| b.name == parts[0]) {
            if let [_, q] = parts.as_slice() {
                let find = |names: &[&str; 6]| names.iter().position(|n| n == q);
                if let Some(dof) = find(&BODY_MOTION) {
                    return Ok(Channel::BodyMotion { body: bi, dof });
                }
                if let Some(dof) = find(&BODY_VELOCITY) {
                    return Ok(Channel::BodyVelocity { body: bi, dof });
                }
                if let Some(dof) = find(&BODY_LINE_LOAD) {
                    return Ok(Channel::BodyLineLoad { body: bi, dof });
                }
            }
            return Err(format!("unknown channel `{name}`"));
        }
        if let Some(oi) = model
            .environment
            .obstacles
            .iter()
            .position(|o| o.name == parts[0])
        {
            if let [_, q] = parts.as_slice() {
                match *q {
                    "force_x" | "force_y" | "force_z" => {
                        let axis = axis(&q[6..]).expect("x, y or z");
                        return Ok(Channel::ObstacleForce { obstacle: oi, axis });
                    }
                    "contact_length" => return Ok(Channel::ObstacleContactLength { obstacle: oi }),
                    _ => {}
                }
            }
            return Err(format!("unknown channel `{name}`"));
        }
        Err(format!(
            "channel `{name}` names no line, point, body or obstacle"
        ))
    }
}
