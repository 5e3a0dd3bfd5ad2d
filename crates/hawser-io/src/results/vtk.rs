//! ParaView snapshots: at every snapshot time one VTK XML PolyData file (`.vtp`, ASCII) per
//! line (a polyline with its node data), per body (its shape in pose) and one for all points,
//! listed in one collection `vtk/run.pvd` that ParaView plays as an animation (each object a
//! block named after it). Written here rather than by a crate: the format is small, and vtkio
//! is unmaintained. A test reads the files back with the `vtk` package (scripts/vtk_check.sh).
//!
//! Every `.vtp` is written whole into a temporary file and renamed; the collection is kept
//! valid after every snapshot (its new entries and closing tags in one write call), so a run
//! killed at any moment leaves a collection that ParaView opens.

use super::csv::{cannot, push_number};
use super::{safe_file_name, write_atomically};
use hawser::math::{Real, Vec3};
use hawser::model::{Displacement, PointKind};
use hawser::session::View;
use hawser::system::System;
use std::fmt::Write as _;
use std::fs::File;
use std::io::{Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

/// The folder of the ParaView files inside a run's output folder.
pub const VTK_DIR: &str = "vtk";
/// The collection's file name inside [`VTK_DIR`].
pub const PVD_FILE: &str = "run.pvd";

const PVD_HEAD: &str = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" \
                        byte_order=\"LittleEndian\">\n<Collection>\n";
const PVD_TAIL: &str = "</Collection>\n</VTKFile>\n";

/// Segments around a cylinder or a sphere's equator.
const AROUND: usize = 24;
/// Segments from pole to pole of a sphere.
const POLE_TO_POLE: usize = 12;

/// A polygonal surface (or set of lines) fixed in a body's axes.
#[derive(Clone, Debug, Default)]
struct Shape {
    /// Vertices in body axes [m].
    vertices: Vec<Vec3>,
    /// Polygons (outward normals by the right-hand rule), as vertex indices.
    polys: Vec<Vec<usize>>,
    /// Line segments, as vertex indices (the axes glyph of a body without a shape).
    lines: Vec<Vec<usize>>,
}

impl Shape {
    /// A body's shape from its displaced volume: a box or a cylinder (axis along body z) as
    /// given, centred at the centre of buoyancy; a sphere of the displaced volume for a body
    /// that only gives a volume; for a body without any, its axes (x, y, z) as three lines of
    /// length `glyph` [m] from its origin.
    fn of_body(displacement: &Displacement, centre: Vec3, glyph: Real) -> Self {
        match *displacement {
            Displacement::Box {
                length,
                breadth,
                height,
            } => {
                let h = Vec3::new(0.5 * length, 0.5 * breadth, 0.5 * height);
                let vertices = (0..8)
                    .map(|i| {
                        let s = |bit: usize| if i >> bit & 1 == 1 { 1.0 } else { -1.0 };
                        centre + Vec3::new(s(0) * h.x, s(1) * h.y, s(2) * h.z)
                    })
                    .collect();
                // Vertex i has x from bit 0, y from bit 1, z from bit 2.
                let polys = [
                    [0, 2, 3, 1], // z−
                    [4, 5, 7, 6], // z+
                    [0, 1, 5, 4], // y−
                    [2, 6, 7, 3], // y+
                    [0, 4, 6, 2], // x−
                    [1, 3, 7, 5], // x+
                ]
                .iter()
                .map(|f| f.to_vec())
                .collect();
                Self {
                    vertices,
                    polys,
                    lines: Vec::new(),
                }
            }
            Displacement::Cylinder { radius, height } => {
                let mut vertices = Vec::with_capacity(2 * AROUND);
                for z in [-0.5 * height, 0.5 * height] {
                    for k in 0..AROUND {
                        let a = 2.0 * std::f64::consts::PI * k as Real / AROUND as Real;
                        vertices.push(centre + Vec3::new(radius * a.cos(), radius * a.sin(), z));
                    }
                }
                let mut polys: Vec<Vec<usize>> = (0..AROUND)
                    .map(|k| {
                        let n = (k + 1) % AROUND;
                        vec![k, n, AROUND + n, AROUND + k]
                    })
                    .collect();
                polys.push((0..AROUND).rev().collect());
                polys.push((AROUND..2 * AROUND).collect());
                Self {
                    vertices,
                    polys,
                    lines: Vec::new(),
                }
            }
            Displacement::Submerged { volume } if volume > 0.0 => {
                let r = (3.0 * volume / (4.0 * std::f64::consts::PI)).cbrt();
                let mut vertices = vec![centre - Vec3::new(0.0, 0.0, r)];
                for i in 1..POLE_TO_POLE {
                    let polar = std::f64::consts::PI * i as Real / POLE_TO_POLE as Real;
                    for k in 0..AROUND {
                        let a = 2.0 * std::f64::consts::PI * k as Real / AROUND as Real;
                        let (s, c) = (polar.sin(), -polar.cos());
                        vertices.push(centre + r * Vec3::new(s * a.cos(), s * a.sin(), c));
                    }
                }
                let top = vertices.len();
                vertices.push(centre + Vec3::new(0.0, 0.0, r));
                let ring = |i: usize, k: usize| 1 + (i - 1) * AROUND + k % AROUND;
                let mut polys = Vec::new();
                for k in 0..AROUND {
                    polys.push(vec![0, ring(1, k + 1), ring(1, k)]);
                    for i in 1..POLE_TO_POLE - 1 {
                        polys.push(vec![
                            ring(i, k),
                            ring(i, k + 1),
                            ring(i + 1, k + 1),
                            ring(i + 1, k),
                        ]);
                    }
                    polys.push(vec![
                        ring(POLE_TO_POLE - 1, k),
                        ring(POLE_TO_POLE - 1, k + 1),
                        top,
                    ]);
                }
                Self {
                    vertices,
                    polys,
                    lines: Vec::new(),
                }
            }
            Displacement::None | Displacement::Submerged { .. } => Self {
                vertices: vec![
                    Vec3::zeros(),
                    Vec3::new(glyph, 0.0, 0.0),
                    Vec3::new(0.0, glyph, 0.0),
                    Vec3::new(0.0, 0.0, glyph),
                ],
                polys: Vec::new(),
                lines: vec![vec![0, 1], vec![0, 2], vec![0, 3]],
            },
        }
    }
}

/// One `.vtp` file being assembled: points, cells and data arrays.
#[derive(Default)]
struct Piece {
    text: String,
}

/// A data array of a piece: its name and per-point (or per-cell) values, 1 or 3 components.
enum Values<'a> {
    Scalars(&'a [Real]),
    Vectors(&'a [Vec3]),
    Integers(&'a [i64]),
}

impl Piece {
    /// Writes the whole file: `time` [s] as field data, the points, the point data, and the
    /// cells (vertices, lines, polygons), each a list of point indices.
    #[allow(clippy::too_many_arguments)]
    fn write(
        &mut self,
        time: Real,
        points: &[Vec3],
        point_data: &[(&str, Values<'_>)],
        verts: &[Vec<usize>],
        lines: &[Vec<usize>],
        polys: &[Vec<usize>],
        cell_data: &[(&str, Values<'_>)],
    ) -> &str {
        let t = &mut self.text;
        t.clear();
        t.push_str(
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" \
             byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<PolyData>\n\
             <FieldData>\n<DataArray type=\"Float64\" Name=\"TimeValue\" \
             NumberOfTuples=\"1\" format=\"ascii\">\n",
        );
        push_number(t, time);
        t.push_str("\n</DataArray>\n</FieldData>\n");
        let _ = writeln!(
            t,
            "<Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" NumberOfLines=\"{}\" \
             NumberOfStrips=\"0\" NumberOfPolys=\"{}\">",
            points.len(),
            verts.len(),
            lines.len(),
            polys.len()
        );
        Self::data(t, "PointData", point_data);
        Self::data(t, "CellData", cell_data);
        t.push_str("<Points>\n");
        Self::array(t, "Points", &Values::Vectors(points));
        t.push_str("</Points>\n");
        for (tag, cells) in [("Verts", verts), ("Lines", lines), ("Polys", polys)] {
            let _ = writeln!(t, "<{tag}>");
            let connectivity: Vec<i64> = cells.iter().flatten().map(|&i| i as i64).collect();
            let offsets: Vec<i64> = cells
                .iter()
                .scan(0i64, |end, c| {
                    *end += c.len() as i64;
                    Some(*end)
                })
                .collect();
            Self::array(t, "connectivity", &Values::Integers(&connectivity));
            Self::array(t, "offsets", &Values::Integers(&offsets));
            let _ = writeln!(t, "</{tag}>");
        }
        t.push_str("</Piece>\n</PolyData>\n</VTKFile>\n");
        &self.text
    }

    fn data(t: &mut String, tag: &str, arrays: &[(&str, Values<'_>)]) {
        let scalars = arrays.iter().find(|(_, v)| matches!(v, Values::Scalars(_)));
        let vectors = arrays.iter().find(|(_, v)| matches!(v, Values::Vectors(_)));
        let _ = write!(t, "<{tag}");
        if let Some((n, _)) = scalars {
            let _ = write!(t, " Scalars=\"{n}\"");
        }
        if let Some((n, _)) = vectors {
            let _ = write!(t, " Vectors=\"{n}\"");
        }
        t.push_str(">\n");
        for (name, values) in arrays {
            Self::array(t, name, values);
        }
        let _ = writeln!(t, "</{tag}>");
    }

    fn array(t: &mut String, name: &str, values: &Values<'_>) {
        let (kind, components) = match values {
            Values::Scalars(_) => ("Float64", 1),
            Values::Vectors(_) => ("Float64", 3),
            Values::Integers(_) => ("Int64", 1),
        };
        let _ = write!(
            t,
            "<DataArray type=\"{kind}\" Name=\"{name}\" NumberOfComponents=\"{components}\" \
             format=\"ascii\">"
        );
        let mut column = 0;
        let mut space = |t: &mut String| {
            // Six values a line keeps the files readable.
            column += 1;
            t.push(if column % 6 == 1 { '\n' } else { ' ' });
        };
        match values {
            Values::Scalars(v) => v.iter().for_each(|x| {
                space(t);
                push_number(t, *x)
            }),
            Values::Vectors(v) => v.iter().flat_map(|p| [p.x, p.y, p.z]).for_each(|x| {
                space(t);
                push_number(t, x)
            }),
            Values::Integers(v) => v.iter().for_each(|i| {
                space(t);
                let _ = write!(t, "{i}");
            }),
        }
        t.push_str("\n</DataArray>\n");
    }
}

/// Writes the ParaView files of a run ([module docs](self)).
pub struct VtkWriter {
    dir: PathBuf,
    pvd: File,
    /// Length of the collection before its closing tags [bytes].
    pvd_len: u64,
    /// Snapshots written so far.
    snapshots: u64,
    /// Each body's shape in its axes.
    shapes: Vec<Shape>,
    /// Whether each line has curvature and bending moment (`hermite`, `dg` with bending).
    bending: Vec<bool>,
    piece: Piece,
    entries: String,
}

impl VtkWriter {
    /// Creates `dir/vtk` and an empty collection in it.
    pub fn create(dir: &Path, system: &System) -> std::io::Result<Self> {
        let vdir = dir.join(VTK_DIR);
        std::fs::create_dir_all(&vdir).map_err(|e| cannot("create", &vdir, e))?;
        let path = vdir.join(PVD_FILE);
        let mut pvd = File::create(&path).map_err(|e| cannot("create", &path, e))?;
        pvd.write_all(format!("{PVD_HEAD}{PVD_TAIL}").as_bytes())
            .map_err(|e| cannot("write", &path, e))?;
        Ok(Self::new(vdir, pvd, PVD_HEAD.len() as u64, 0, system))
    }

    fn new(dir: PathBuf, pvd: File, pvd_len: u64, snapshots: u64, system: &System) -> Self {
        let shapes = system
            .bodies
            .iter()
            .enumerate()
            .map(|(b, sb)| {
                // The axes glyph reaches half way to the farthest point on the body (1 m
                // without any).
                let reach = system
                    .points
                    .iter()
                    .filter_map(|p| match p.kind {
                        PointKind::Body { body, offset } if body == b => Some(offset.norm()),
                        _ => None,
                    })
                    .fold(0.0, Real::max);
                let glyph = if reach > 0.0 { 0.5 * reach } else { 1.0 };
                Shape::of_body(
                    &sb.body.displacement,
                    sb.body.centre_of_buoyancy,
                    glyph.max(1.0),
                )
            })
            .collect();
        let bending = system
            .lines
            .iter()
            .map(|l| l.has_bending_outputs())
            .collect();
        Self {
            dir,
            pvd,
            pvd_len,
            snapshots,
            shapes,
            bending,
            piece: Piece::default(),
            entries: String::new(),
        }
    }

    /// The collection's length and the snapshot count, for a checkpoint.
    pub fn progress(&self) -> (u64, u64) {
        (self.pvd_len, self.snapshots)
    }

    /// Reopens the files of `dir/vtk` at a checkpoint's `progress` ([`VtkWriter::progress`]):
    /// the collection cut back to its entries then.
    pub fn resume(dir: &Path, system: &System, progress: (u64, u64)) -> std::io::Result<Self> {
        let vdir = dir.join(VTK_DIR);
        let path = vdir.join(PVD_FILE);
        let (len, snapshots) = progress;
        let mut pvd = std::fs::OpenOptions::new()
            .write(true)
            .open(&path)
            .map_err(|e| cannot("open", &path, e))?;
        let now = pvd.metadata().map_err(|e| cannot("read", &path, e))?.len();
        if now < len + PVD_TAIL.len() as u64 {
            return Err(std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                format!("{} is shorter than at the checkpoint", path.display()),
            ));
        }
        pvd.set_len(len).map_err(|e| cannot("cut back", &path, e))?;
        pvd.seek(SeekFrom::Start(len))
            .and_then(|_| pvd.write_all(PVD_TAIL.as_bytes()))
            .map_err(|e| cannot("write", &path, e))?;
        Ok(Self::new(vdir, pvd, len, snapshots, system))
    }

    /// Writes the snapshot of `view` at `time` [s]: a file per line and body and one for the
    /// points, then their entries in the collection.
    pub fn snapshot(&mut self, view: &View<'_>, time: Real) -> std::io::Result<()> {
        let system = view.system;
        let k = self.snapshots;
        self.entries.clear();
        let mut part = 0;
        for li in 0..system.lines.len() {
            let samples: Vec<_> = view.line_samples(li).collect();
            let positions: Vec<Vec3> = samples.iter().map(|s| s.position).collect();
            let velocity: Vec<Vec3> = samples.iter().map(|s| s.velocity).collect();
            let get = |f: fn(&hawser::session::LineSample) -> Real| -> Vec<Real> {
                samples.iter().map(f).collect()
            };
            let (tension, strain, arc) =
                (get(|s| s.tension), get(|s| s.strain), get(|s| s.arc_length));
            let (curvature, moment) = (get(|s| s.curvature), get(|s| s.bending_moment));
            let mut data = vec![
                ("tension", Values::Scalars(&tension)),
                ("strain", Values::Scalars(&strain)),
            ];
            if self.bending[li] {
                data.push(("curvature", Values::Scalars(&curvature)));
                data.push(("bending_moment", Values::Scalars(&moment)));
            }
            data.push(("arc_length", Values::Scalars(&arc)));
            data.push(("velocity", Values::Vectors(&velocity)));
            let polyline = vec![(0..positions.len()).collect::<Vec<_>>()];
            let text = self
                .piece
                .write(time, &positions, &data, &[], &polyline, &[], &[]);
            let line = &system.lines[li].name;
            let file = format!("line_{}_{k:06}.vtp", safe_file_name(line));
            write_part(&self.dir, &mut self.entries, &file, line, text, time, part)?;
            part += 1;
        }
        for (b, shape) in self.shapes.iter().enumerate() {
            let pose = view.body(b);
            let positions: Vec<Vec3> = shape
                .vertices
                .iter()
                .map(|v| pose.position + pose.orientation * v)
                .collect();
            let velocity: Vec<Vec3> = positions
                .iter()
                .map(|p| pose.velocity + pose.angular_velocity.cross(&(p - pose.position)))
                .collect();
            let axis: Vec<i64> = (0..shape.lines.len() as i64).collect();
            let mut cell_data = Vec::new();
            if !shape.lines.is_empty() {
                cell_data.push(("axis", Values::Integers(&axis)));
            }
            let text = self.piece.write(
                time,
                &positions,
                &[("velocity", Values::Vectors(&velocity))],
                &[],
                &shape.lines,
                &shape.polys,
                &cell_data,
            );
            let body = &system.bodies[b].body.name;
            let file = format!("body_{}_{k:06}.vtp", safe_file_name(body));
            write_part(&self.dir, &mut self.entries, &file, body, text, time, part)?;
            part += 1;
        }
        if !system.points.is_empty() {
            let n = system.points.len();
            let positions: Vec<Vec3> = (0..n).map(|i| view.point(i).position).collect();
            let velocity: Vec<Vec3> = (0..n).map(|i| view.point(i).velocity).collect();
            let force: Vec<Vec3> = (0..n).map(|i| view.point_line_force(i)).collect();
            let index: Vec<i64> = (0..n as i64).collect();
            let verts: Vec<Vec<usize>> = (0..n).map(|i| vec![i]).collect();
            let text = self.piece.write(
                time,
                &positions,
                &[
                    ("index", Values::Integers(&index)),
                    ("velocity", Values::Vectors(&velocity)),
                    ("line_force", Values::Vectors(&force)),
                ],
                &verts,
                &[],
                &[],
                &[],
            );
            let file = format!("points_{k:06}.vtp");
            write_part(
                &self.dir,
                &mut self.entries,
                &file,
                "points",
                text,
                time,
                part,
            )?;
        }
        // The new entries and the closing tags in one write call: the collection stays whole.
        let path = self.dir.join(PVD_FILE);
        let mut tail = std::mem::take(&mut self.entries);
        let added = tail.len() as u64;
        tail.push_str(PVD_TAIL);
        let written = self
            .pvd
            .seek(SeekFrom::Start(self.pvd_len))
            .and_then(|_| self.pvd.write_all(tail.as_bytes()));
        if let Err(e) = written {
            // Back to the entries before this snapshot, closed again (best effort).
            let _ = self.pvd.set_len(self.pvd_len);
            let _ = self.pvd.write_all(PVD_TAIL.as_bytes());
            return Err(cannot("write", &path, e));
        }
        self.pvd_len += added;
        self.snapshots += 1;
        tail.clear();
        self.entries = tail;
        Ok(())
    }
}

/// Writes `text` into `dir/file` (atomically) and adds its entry to the collection's `entries`:
/// block `block` at `time` [s], part `part`.
fn write_part(
    dir: &Path,
    entries: &mut String,
    file: &str,
    block: &str,
    text: &str,
    time: Real,
    part: usize,
) -> std::io::Result<()> {
    write_atomically(&dir.join(file), text.as_bytes())?;
    entries.push_str("<DataSet timestep=\"");
    push_number(entries, time);
    let _ = writeln!(
        entries,
        "\" part=\"{part}\" name=\"{}\" file=\"{}\"/>",
        xml_escaped(block),
        xml_escaped(file)
    );
    Ok(())
}

/// `s` with the characters XML gives a meaning in attribute values escaped.
fn xml_escaped(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Volume enclosed by a shape's polygons (fan-triangulated), by the divergence theorem:
    /// positive when every polygon's normal points outward.
    fn signed_volume(s: &Shape) -> Real {
        s.polys
            .iter()
            .flat_map(|p| (1..p.len() - 1).map(move |k| [p[0], p[k], p[k + 1]]))
            .map(|[a, b, c]| {
                let (a, b, c) = (s.vertices[a], s.vertices[b], s.vertices[c]);
                a.dot(&b.cross(&c)) / 6.0
            })
            .sum()
    }

    #[test]
    fn body_shapes_are_closed_with_outward_normals_and_their_volume() {
        let centre = Vec3::new(0.3, -0.2, 0.5);
        let boxed = Shape::of_body(
            &Displacement::Box {
                length: 4.0,
                breadth: 2.0,
                height: 1.5,
            },
            centre,
            1.0,
        );
        // Exact for a box; the centroid of its vertices is its centre.
        assert!((signed_volume(&boxed) - 12.0).abs() < 1e-12);
        let mean = boxed.vertices.iter().sum::<Vec3>() / 8.0;
        assert!((mean - centre).norm() < 1e-15);
        // A cylinder is drawn as a 24-sided prism: its volume is the prism's,
        // 24/2 sin(2π/24) r² h, 1.1 % below π r² h.
        let cylinder = Shape::of_body(
            &Displacement::Cylinder {
                radius: 0.5,
                height: 2.0,
            },
            centre,
            1.0,
        );
        let prism = 12.0 * (2.0 * std::f64::consts::PI / 24.0).sin() * 0.25 * 2.0;
        assert!((signed_volume(&cylinder) - prism).abs() < 1e-12);
        // A body with only a volume is a sphere of that volume: the inscribed polyhedron
        // (12 × 24 faces) encloses a little less, within 3 %.
        let v = 2.0;
        let sphere = Shape::of_body(&Displacement::Submerged { volume: v }, centre, 1.0);
        let enclosed = signed_volume(&sphere);
        assert!(enclosed < v && enclosed > 0.97 * v, "{enclosed}");
        let r = (3.0 * v / (4.0 * std::f64::consts::PI)).cbrt();
        for p in &sphere.vertices {
            assert!(((p - centre).norm() - r).abs() < 1e-12);
        }
        // Without a shape: the axes, `glyph` long, from the origin (not the centre).
        let axes = Shape::of_body(&Displacement::None, centre, 2.5);
        assert!(axes.polys.is_empty() && axes.lines.len() == 3);
        assert_eq!(axes.vertices[0], Vec3::zeros());
        assert_eq!(axes.vertices[3], Vec3::new(0.0, 0.0, 2.5));
    }

    #[test]
    fn names_are_escaped_in_the_collection() {
        assert_eq!(xml_escaped("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&apos;");
    }
}
