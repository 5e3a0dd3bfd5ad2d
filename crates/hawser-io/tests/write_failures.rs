//! A result file that cannot be written (here: opened on /dev/full, where every write fails
//! with "No space left on device", as on a full disk) is found when the writer creates it,
//! before the run starts, and the error names it. (A file that fills up during the run is
//! tested with a file-size limit in hawser-cli's tests/write_failures.rs.)

use hawser_io::results::RunWriter;
use hawser_io::scenario::OutputFormats;
use std::path::{Path, PathBuf};

fn session() -> (hawser::Session, PathBuf) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/catenary_mooring.toml");
    let (loaded, _) = hawser_io::input::load_input(&path, &Default::default()).unwrap();
    (hawser::Session::new(loaded.model).unwrap(), path)
}

#[test]
fn a_file_on_a_full_disk_is_refused_at_creation_with_its_name() {
    if !Path::new("/dev/full").exists() {
        panic!("this test needs /dev/full (Linux)");
    }
    let (session, scenario) = session();
    let formats = OutputFormats {
        parquet: false,
        vtk: true,
    };
    for file in ["timeseries.csv", "snapshots/chain.csv", "vtk/run.pvd"] {
        let dir = std::env::temp_dir().join(format!(
            "hawser_full_{}_{}",
            file.replace('/', "_"),
            std::process::id()
        ));
        let _ = std::fs::remove_dir_all(&dir);
        let target = dir.join(file);
        std::fs::create_dir_all(target.parent().unwrap()).unwrap();
        std::os::unix::fs::symlink("/dev/full", &target).unwrap();
        let e = match RunWriter::create(&dir, &session, &scenario, &formats, &Default::default()) {
            Ok(_) => panic!("{file} on /dev/full was accepted"),
            Err(e) => e.to_string(),
        };
        assert!(
            e.contains(&format!("cannot write {}", target.display()))
                && e.contains("No space left on device"),
            "{file}: {e}"
        );
        let _ = std::fs::remove_dir_all(&dir);
    }
}
