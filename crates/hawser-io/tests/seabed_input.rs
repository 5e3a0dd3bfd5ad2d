//! The seabed's shape in scenario files and MoorDyn decks: `gradient`, `normal` and `grid` in
//! `[environment.seabed]`, MoorDyn's `SeafloorFile`, and the errors of each.

mod common;
use common::*;
use hawser::physics::seabed::Bathymetry;
use hawser_io::moordyn::{self, ConvertOptions};
use hawser_io::scenario;
use std::path::{Path, PathBuf};

/// A chain from an anchor on the bed to a fixed fairlead over 100 m of water.
const BASE: &str = r#"[simulation]
duration = 1.0

[environment]
depth = 100.0

[environment.seabed]
stiffness = 3.0e6

[[line_types]]
name = "chain"
diameter = 0.09
mass_per_length = 77.7
axial_stiffness = 3.84e8
normal_drag = 1.6
tangential_drag = 0.05

[[points]]
name = "anchor"
type = "fixed"
position = [-400.0, 0.0, -100.0]

[[points]]
name = "fairlead"
type = "fixed"
position = [0.0, 0.0, -10.0]

[[lines]]
name = "L1"
end_a = "anchor"
end_b = "fairlead"
type = "chain"
length = 450.0
elements = 20
"#;

/// A folder of its own for this test binary's files.
fn folder() -> PathBuf {
    let d = std::env::temp_dir().join(format!("hawser_seabed_input_{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn bathymetry(text: &str, dir: &Path) -> (Bathymetry, f64) {
    let loaded =
        scenario::parse(&dir.join("scenario.toml"), text).unwrap_or_else(|e| panic!("{e}"));
    let env = loaded.model.environment;
    (env.bathymetry, env.depth)
}

#[test]
fn gradient_normal_and_grid_build_the_bed() {
    let dir = folder();
    let plane = |key: &str| {
        replaced(
            &replaced(
                BASE,
                "stiffness = 3.0e6",
                &format!("stiffness = 3.0e6\n{key}"),
            ),
            "[-400.0, 0.0, -100.0]",
            "[-400.0, 0.0, -120.0]",
        )
    };
    let (b, _) = bathymetry(&plane("gradient = [0.05, 0.0]"), &dir);
    assert_eq!(
        b,
        Bathymetry::Plane {
            gradient: [0.05, 0.0]
        }
    );
    let (b, _) = bathymetry(&plane("normal = [-0.5, 0.0, 10.0]"), &dir);
    assert_eq!(
        b,
        Bathymetry::Plane {
            gradient: [0.05, 0.0]
        }
    );
    // A CSV grid of depths; without environment.depth the waves' depth is its mean.
    std::fs::write(
        dir.join("bed.csv"),
        "x [m],y [m],depth [m]\n-500,-50,110\n100,-50,90\n-500,50,110\n100,50,90\n",
    )
    .unwrap();
    let text = replaced(
        &replaced(
            BASE,
            "stiffness = 3.0e6",
            "stiffness = 3.0e6\ngrid = \"bed.csv\"",
        ),
        "depth = 100.0\n",
        "",
    );
    let text = replaced(&text, "[-400.0, 0.0, -100.0]", "[-400.0, 0.0, -106.0]");
    let (b, depth) = bathymetry(&text, &dir);
    let Bathymetry::Grid(g) = &b else {
        panic!("{b:?}")
    };
    assert_eq!(g.x(), &[-500.0, 100.0]);
    assert_eq!(g.heights(), &[-110.0, -90.0, -110.0, -90.0]);
    assert_eq!(depth, 100.0);
    // Bilinear: the anchor's x is 1/6 of the way from −500 to 100.
    let bed = b.at(depth, -400.0, 0.0);
    assert!((bed.z + 110.0 - 20.0 / 6.0).abs() < 1e-12, "{bed:?}");
}

#[test]
fn bad_shapes_are_refused_at_their_key() {
    let dir = folder();
    let with = |extra: &str| {
        replaced(
            BASE,
            "stiffness = 3.0e6",
            &format!("stiffness = 3.0e6\n{extra}"),
        )
    };
    let text = with("gradient = [0.0, 0.1]\nnormal = [0.0, 0.0, 1.0]");
    let msg = bad(&text, "normal = [", "environment.seabed.normal");
    assert!(msg.contains("given twice"), "{msg}");
    let text = with("normal = [0.0, 1.0, -1.0]");
    let msg = bad(&text, "normal = [", "environment.seabed.normal");
    assert!(msg.contains("must point up"), "{msg}");
    let text = with("gradient = [1e9, 0.0]");
    bad(&text, "gradient = [", "environment.seabed.gradient");
    // A missing grid file names the file.
    let text = with("grid = \"no_such_grid.txt\"");
    let msg = bad(&text, "grid = ", "environment.seabed.grid");
    assert!(msg.contains("no_such_grid.txt"), "{msg}");
    // An anchor under a rising bed is below it there.
    let text = with("gradient = [-0.1, 0.0]");
    let msg = bad(&text, "[-400.0, 0.0, -100.0]", "points[0].position");
    assert!(msg.contains("seabed's height at x = -400"), "{msg}");
    let _ = dir;
}

/// MoorDyn-C's `SeafloorFile` (rows `x y z`) becomes the grid, found beside the deck; WtrDpth
/// gives way to the grid's mean depth, as in MoorDyn.
#[test]
fn moordyn_seafloor_file_is_read() {
    let dir = folder();
    std::fs::write(
        dir.join("seafloor.txt"),
        "2 2\n-500 100\n-50 50\n-500 -50 -110\n100 -50 -90\n-500 50 -110\n100 50 -90\n",
    )
    .unwrap();
    let deck = "--------------------- MoorDyn Input File -------------------------
A chain over a sloping bed
----------------------- LINE TYPES ------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI    Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)
chain      0.09    77.7       3.84e8     -0.8        0     1.6    1.0    0.05    0.0
---------------------- POINTS --------------------------------
ID  Attachment  X       Y     Z      M     V    CdA   CA
(#)   (-)       (m)     (m)   (m)    (kg)  (m^3)  (m^2)  (-)
1     Fixed     -400.0  0.0   -106.0  0     0    0     0
2     Fixed     0.0     0.0   -10.0   0     0    0     0
---------------------- LINES --------------------------------------
ID  LineType  AttachA  AttachB  UnstrLen  NumSegs   Outputs
(#)   (name)    (#)      (#)       (m)       (-)       (-)
1     chain     1        2         450.0     20        -
---------------------- OPTIONS -----------------------------------------
0.002    dtM
100.0    WtrDpth
seafloor.txt   SeafloorFile
3.0e6    kBot
3.0e5    cBot
------------------------- need this line -------------------------------------
";
    let d = moordyn::parse(&dir.join("deck.txt"), deck, &ConvertOptions::default())
        .unwrap_or_else(|e| panic!("{e}"));
    let env = &d.loaded.model.environment;
    let Bathymetry::Grid(g) = &env.bathymetry else {
        panic!("{:?}", env.bathymetry)
    };
    assert_eq!(g.heights(), &[-110.0, -90.0, -110.0, -90.0]);
    assert_eq!(env.depth, 100.0);
    assert!(
        d.notes.iter().any(|n| n.message.contains("SeafloorFile")),
        "{:?}",
        d.notes
    );
    // The converted scenario names the file by its absolute path and reads back the same.
    let toml = moordyn::to_toml(&d, &dir.join("deck.txt"));
    assert!(toml.contains("grid = "), "{toml}");
    let back = scenario::parse(&std::env::temp_dir().join("elsewhere.toml"), &toml)
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(back.model.environment.bathymetry, env.bathymetry);
}

/// The example `seabed_step.toml` (docs/examples.md): a chain from 60 m of water up a 10 m
/// seabed step (a grid of depths) to a fairlead at 10 m depth. In statics the bed is
/// frictionless and pushes along its normal, so the tension grows along the chain by exactly
/// its wet weight times the rise: T_B − T_A = w Δz = w · 50 m. The 4 m elements over the
/// step's curvature (radius 32 m at its shoulder) put the nodes' contact forces slightly off
/// the chain's normal: measured −0.7 % (−0.65 % on 2 m, +0.17 % on 1 m elements); asserted
/// within 1 %.
#[test]
fn seabed_step_statics_tension_rises_by_the_weight_times_the_rise() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/seabed_step.toml");
    let model = scenario::load(&path).unwrap().model;
    assert!(matches!(model.environment.bathymetry, Bathymetry::Grid(_)));
    let system = hawser::System::new(&model).unwrap();
    let y = hawser::statics::solve(&system, None, &Default::default())
        .unwrap()
        .state;
    let mut ws = system.workspace();
    let mut dydt = vec![0.0; y.len()];
    system.rhs(0.0, &y, &mut dydt, &mut ws).unwrap();
    let (ta, tb) = (
        system.end_force(&ws, 0, false).norm(),
        system.end_force(&ws, 0, true).norm(),
    );
    let t = &model.line_types[0];
    let env = &model.environment;
    let area = std::f64::consts::PI * t.diameter * t.diameter / 4.0;
    let w = (t.mass_per_length - env.water_density * area) * env.gravity;
    let expected = w * 50.0;
    eprintln!(
        "T_A {ta:.1} N, T_B {tb:.1} N, T_B − T_A {:.1} N vs w Δz {expected:.1} N",
        tb - ta
    );
    assert!(
        ((tb - ta) / expected - 1.0).abs() < 0.01,
        "T_B − T_A = {} N, w Δz = {expected} N",
        tb - ta
    );
}
